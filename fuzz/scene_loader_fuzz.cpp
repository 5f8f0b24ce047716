// libFuzzer target: the XML scene loader on arbitrary bytes.
// Every input must either be rejected with a located message or give a scene that satisfies the
// invariants the rest of the simulator relies on; accepted small scenes are also stepped once, so
// that anything the loader lets through but the simulator cannot handle shows up as a crash.
#include "fosssim/core/simulator.h"
#include "fosssim/io/scene_file.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

constexpr const char* kName = "fuzz.xml";

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz_scene_loader: invariant violated: %s\n", what);
  std::abort();
}

void check(bool ok, const char* what) {
  if (!ok) broken(what);
}

bool isColor(const fosssim::Rgb& c) {
  return c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1;
}

void checkAccepted(const fosssim::SceneFile& file) {
  const fosssim::Scene& s = file.scene;
  const int n = s.numParticles();
  check(s.mass.size() == 2 * n && static_cast<int>(s.fixed.size()) == n, "per-particle arrays have N entries");
  check(file.initial.x.size() == 2 * n && file.initial.v.size() == 2 * n, "the initial state has 2N entries");
  check(file.initial.x.allFinite() && file.initial.v.allFinite(), "the initial state is finite");
  for (int i = 0; i < n; ++i) {
    check(s.massOf(i) > 0 && std::isfinite(s.massOf(i)), "masses are positive and finite");
    check(s.radius[i] > 0 && std::isfinite(s.radius[i]), "radii are positive and finite");
  }
  for (const fosssim::Edge& e : s.edges)
    check(e.i >= 0 && e.i < n && e.j >= 0 && e.j < n && e.i != e.j && e.radius > 0, "edges join two particles");
  for (const fosssim::HalfPlane& h : s.halfplanes)
    check(h.point.allFinite() && h.normal.allFinite() && h.normal.squaredNorm() > 0, "half-planes are proper");
  check(s.dt > 0 && std::isfinite(s.dt) && s.duration >= 0 && std::isfinite(s.duration), "dt and duration");
  check(s.numSteps() >= 0, "the step count is not negative");
  check(s.collision.cor >= 0 && s.collision.cor <= 1, "COR lies in [0, 1]");
  const fosssim::Appearance& look = file.look;
  check(static_cast<int>(look.particleColors.size()) == n, "one colour per particle");
  check(look.edgeColors.size() == s.edges.size(), "one colour per edge");
  check(look.halfplaneColors.size() == s.halfplanes.size(), "one colour per half-plane");
  check(isColor(look.background), "the background colour lies in [0, 1]");
  for (const auto& c : look.particleColors) check(isColor(c), "particle colours lie in [0, 1]");
  for (const auto& c : look.edgeColors) check(isColor(c), "edge colours lie in [0, 1]");
  for (const auto& c : look.halfplaneColors) check(isColor(c), "half-plane colours lie in [0, 1]");
  for (const auto& p : look.paths)
    check(p.particle >= 0 && p.particle < n && isColor(p.color) && p.duration >= 0, "paths name a particle");
  if (look.viewport) check(look.viewport->size > 0, "the viewport has a positive size");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  fosssim::SceneFile file;
  const fosssim::Status status = fosssim::parseScene(text, kName, file);
  if (!status) {
    check(status.message().rfind(kName, 0) == 0, "an error message starts with the file name");
    return 0;
  }
  for (const std::string& w : file.warnings) check(w.rfind(kName, 0) == 0, "a warning starts with the file name");
  checkAccepted(file);

  // One step of small scenes: the loader must not accept what the simulator cannot take.
  if (file.scene.numParticles() > 64 || file.scene.forces.size() > 64) return 0;
  std::unique_ptr<fosssim::Simulator> simulator;
  fosssim::SimulatorOptions options;
  options.logPolynomials = true;
  if (!fosssim::Simulator::create(file.scene, options, simulator)) broken("an accepted scene builds a simulator");
  fosssim::State state = file.initial;
  (void)simulator->step(file.scene, state);  // may fail (e.g. overflow to infinity), must not crash
  return 0;
}
