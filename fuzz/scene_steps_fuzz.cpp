// libFuzzer target: a fuzzed scene, run for a few steps under every collision handler in both
// modes. fuzz_scene_loader steps each scene once with the handler its file names; this target
// exists because a class of crashes only shows when geometry meets a handler it was not written
// for (finite coordinates near 1e308 overflowed the broad phase's cell arithmetic of every
// handler: the scene named "none", so the loader target never ran one).
//
// Every step must either succeed with a finite state or fail with a message; nothing may crash,
// hang or trip a sanitizer. Scenes are capped in size so that one input runs in milliseconds.
#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/simulator.h"
#include "fosssim/io/scene_file.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

namespace {

constexpr const char* kName = "fuzz.xml";
// Size caps: enough for multi-contact configurations (racks, slots, piles of a few disks), small
// enough that every handler x mode x step combination of one input takes milliseconds.
constexpr int kMaxParticles = 48;
constexpr size_t kMaxEdges = 64;
constexpr size_t kMaxHalfplanes = 16;
constexpr size_t kMaxForces = 64;
constexpr long kMaxSteps = 4;

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "fuzz_scene_steps: invariant violated: %s\n", what.c_str());
  std::abort();
}

bool hasPenaltyForce(const fosssim::Scene& scene) {
  return std::any_of(scene.forces.begin(), scene.forces.end(), [](const auto& f) {
    return dynamic_cast<const fosssim::PenaltyForce*>(f.get()) != nullptr;
  });
}

/// Runs up to kMaxSteps steps of `text`'s scene with collision handling `entry` in one mode.
void runWith(const std::string& text, const fosssim::CollisionEntry& entry, bool compat) {
  fosssim::SceneFile file;
  if (!fosssim::parseScene(text, kName, file)) broken("a scene accepted once is accepted again");
  fosssim::Scene& scene = file.scene;
  scene.collision.type = entry.type;
  // What the loader does for a file that names this handler: penalty and hybrid come with a
  // penalty force (the file's <collision> may have named another type and so added none; then
  // the type's defaults, as for a file that gives no k or thickness).
  if (!hasPenaltyForce(scene)) {
    scene.collision.penaltyK = entry.defaultK;
    scene.collision.penaltyThickness = entry.defaultThickness;
  }
  fosssim::finalizeScene(scene);

  fosssim::SimulatorOptions options;
  options.handler.compat = compat;
  options.logPolynomials = true;  // the -o / -i path: every pair queried and logged
  std::unique_ptr<fosssim::Simulator> simulator;
  if (!fosssim::Simulator::create(scene, options, simulator))
    broken(std::string("an accepted scene builds a simulator for ") + entry.keyword);

  fosssim::State state = file.initial;
  const long steps = std::min(scene.numSteps(), kMaxSteps);
  for (long k = 0; k < steps; ++k) {
    const fosssim::Status status = simulator->step(scene, state);
    if (!status) {
      if (status.message().empty()) broken("a failed step says why");
      return;  // a located failure (overflow, blow-up, unrepresentable contact) is a valid outcome
    }
    if (!state.x.allFinite() || !state.v.allFinite())
      broken(std::string("a successful step leaves a finite state (") + entry.keyword + (compat ? ", --compat)" : ")"));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fosssim::SceneFile file;
  if (!fosssim::parseScene(text, kName, file)) return 0;  // rejection is fuzz_scene_loader's subject
  const fosssim::Scene& s = file.scene;
  if (s.numParticles() > kMaxParticles || s.edges.size() > kMaxEdges || s.halfplanes.size() > kMaxHalfplanes ||
      s.forces.size() > kMaxForces)
    return 0;
  for (const fosssim::CollisionEntry& entry : fosssim::collisionTable())
    for (bool compat : {false, true}) runWith(text, entry, compat);
  return 0;
}
