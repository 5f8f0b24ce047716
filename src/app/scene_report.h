// What the command line says about a loaded scene: its errors and warnings in line order, or with
// -q (and a scene that loads) one line counting the warnings; --strict makes warnings errors; --check stops after the
// load with "scene.xml: ok (...)". Header-only: main.cpp is its one user.
#pragma once

#include "options.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/io/scene_file.h"

#include <cstdio>
#include <string>

namespace fosssim::app {

inline std::string plural(long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

/// "2 particles, 1 edge, 1 half-plane, 3 forces, 100 steps of dt 0.01, symplectic-euler, hybrid collisions"
inline std::string sceneSummary(const SceneFile& file) {
  const Scene& s = file.scene;
  char dt[32];
  std::snprintf(dt, sizeof dt, "%g", s.dt);
  return plural(s.numParticles(), "particle", "particles") + ", " +
         plural(static_cast<long>(s.edges.size()), "edge", "edges") + ", " +
         plural(static_cast<long>(s.halfplanes.size()), "half-plane", "half-planes") + ", " +
         plural(static_cast<long>(s.forces.size()), "force", "forces") + ", " + plural(s.numSteps(), "step", "steps") +
         " of dt " + dt + ", " + s.integrator + ", collisions: " + collisionKeyword(s.collision.type);
}

/// Prints the loader's messages. Returns the exit status when the program must stop here (a
/// failed load, --strict with warnings, --check), or -1 to go on.
inline int reportScene(const Options& options, const Status& loaded, const SceneFile& file) {
  const bool strict = options.strict && file.warningCount > 0;
  const bool failed = !loaded || strict;
  // Without messages (the file could not be read at all) the Status says what happened.
  if (!loaded && file.messages.empty()) {
    std::fprintf(stderr, "FOSSSim: error: %s\n", loaded.message().c_str());
    return 1;
  }
  // -q hides warnings behind a count, except when the load fails: then they may explain the
  // errors (a misspelt 'raduis' before the missing 'radius' it causes).
  const bool showWarnings = failed || !options.quiet;
  for (const SceneMessage& m : file.messages)
    if (m.isError() || showWarnings)
      std::fprintf(stderr, "FOSSSim: %s: %s\n", m.isError() || strict ? "error" : "warning", m.text.c_str());
  if (!showWarnings && file.warningCount > 0)
    std::fprintf(stderr, "FOSSSim: warning: %s: %s about the scene (run without -q to see them)\n", file.path.c_str(),
                 plural(file.warningCount, "warning", "warnings").c_str());
  if (strict)
    std::fprintf(stderr, "FOSSSim: error: %s: %s, and --strict makes warnings errors\n", file.path.c_str(),
                 plural(file.warningCount, "warning", "warnings").c_str());
  if (failed) return 1;
  if (options.check) {
    std::printf("%s: ok (%s%s)\n", file.path.c_str(), sceneSummary(file).c_str(),
                file.warningCount > 0 ? (", " + plural(file.warningCount, "warning", "warnings")).c_str() : "");
    return 0;
  }
  return -1;
}

}  // namespace fosssim::app
