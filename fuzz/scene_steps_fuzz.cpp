// libFuzzer target: a fuzzed scene, run for a few steps under every collision handler in both
// modes. fuzz_scene_loader steps each scene once with the handler its file names; this target
// exists because a class of crashes only shows when geometry meets a handler it was not written
// for (finite coordinates near 1e308 overflowed the broad phase's cell arithmetic of every
// handler: the scene named "none", so the loader target never ran one).
//
// Every step must either succeed with a finite state or fail with a message; nothing may crash,
// hang or trip a sanitizer. Scenes are capped in size so that one input runs in milliseconds.
//
// Small scenes then run long enough for particles to fall asleep (kRestSteps, past
// kStepsToSleep) under the handlers that let them (the default mode's event handler), with the
// polynomial log off, as a user's run would: that is the only way the sleepers' paths (not
// integrated, not searched, the penalty layer's rows of resting particles left out) are reached.
// The same run with sleeping off must then be identical, bit for bit, for as long as nothing
// sleeps (the promise of HandlerOptions::sleep).
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
// The long runs: scenes of up to this many particles, this many steps whatever their duration
// (sleeping starts after 30 still steps, src/core/collision/sleepers.h).
constexpr int kMaxRestParticles = 24;
constexpr long kRestSteps = 40;

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "fuzz_scene_steps: invariant violated: %s\n", what.c_str());
  std::abort();
}

bool hasPenaltyForce(const fosssim::Scene& scene) {
  return std::any_of(scene.forces.begin(), scene.forces.end(), [](const auto& f) {
    return dynamic_cast<const fosssim::PenaltyForce*>(f.get()) != nullptr;
  });
}

/// `text`'s scene with collision handling `entry`, as the loader makes it for a file naming
/// that handler: penalty and hybrid come with a penalty force (the file's <collision> may have
/// named another type and so added none; then the type's defaults, as for a file that gives no
/// k or thickness).
fosssim::SceneFile sceneWith(const std::string& text, const fosssim::CollisionEntry& entry) {
  fosssim::SceneFile file;
  if (!fosssim::parseScene(text, kName, file)) broken("a scene accepted once is accepted again");
  fosssim::Scene& scene = file.scene;
  scene.collision.type = entry.type;
  if (!hasPenaltyForce(scene)) {
    scene.collision.penaltyK = entry.defaultK;
    scene.collision.penaltyThickness = entry.defaultThickness;
  }
  fosssim::finalizeScene(scene);
  return file;
}

std::unique_ptr<fosssim::Simulator> simulatorFor(const fosssim::Scene& scene, const fosssim::SimulatorOptions& options,
                                                 const fosssim::CollisionEntry& entry) {
  std::unique_ptr<fosssim::Simulator> simulator;
  if (!fosssim::Simulator::create(scene, options, simulator))
    broken(std::string("an accepted scene builds a simulator for ") + entry.keyword);
  return simulator;
}

/// Whether a step ended well: a failure says why (and ends the run: a located failure, such as
/// an overflow, a blow-up or an unrepresentable contact, is a valid outcome), a success leaves a
/// finite state.
bool stepped(const fosssim::Status& status, const fosssim::State& state, const fosssim::CollisionEntry& entry,
             const char* how) {
  if (!status) {
    if (status.message().empty()) broken("a failed step says why");
    return false;
  }
  if (!state.x.allFinite() || !state.v.allFinite())
    broken(std::string("a successful step leaves a finite state (") + entry.keyword + ", " + how + ")");
  return true;
}

/// Runs up to kMaxSteps steps of `text`'s scene with collision handling `entry` in one mode.
void runWith(const std::string& text, const fosssim::CollisionEntry& entry, bool compat) {
  const fosssim::SceneFile file = sceneWith(text, entry);
  fosssim::SimulatorOptions options;
  options.handler.compat = compat;
  options.logPolynomials = true;  // the -o / -i path: every pair queried and logged
  const auto simulator = simulatorFor(file.scene, options, entry);
  fosssim::State state = file.initial;
  const long steps = std::min(file.scene.numSteps(), kMaxSteps);
  for (long k = 0; k < steps; ++k)
    if (!stepped(simulator->step(file.scene, state), state, entry, compat ? "--compat" : "default mode")) return;
}

/// kRestSteps steps of `text`'s scene with handling `entry` in the default mode, with sleeping
/// on and off, side by side: identical until something sleeps, then the sleeping run goes on
/// alone.
void restWith(const std::string& text, const fosssim::CollisionEntry& entry) {
  const fosssim::SceneFile file = sceneWith(text, entry);
  fosssim::SimulatorOptions options;
  const auto sleeping = simulatorFor(file.scene, options, entry);
  if (!sleeping->keepsPairsApart()) return;  // not the event handler: nothing sleeps
  options.handler.sleep = false;
  const auto awake = simulatorFor(file.scene, options, entry);
  fosssim::State a = file.initial, b = file.initial;
  bool compared = true;  // nothing has slept yet
  for (long k = 0; k < kRestSteps; ++k) {
    const fosssim::Status s = sleeping->step(file.scene, a);
    compared = compared && sleeping->stats().asleep == 0;
    if (compared) {
      const fosssim::Status t = awake->step(file.scene, b);
      // A failed step's state is not compared (it may hold what made it fail: NaN != NaN).
      const bool same =
          s.isOk() && t.isOk() ? a.x == b.x && a.v == b.v : s.isOk() == t.isOk() && s.message() == t.message();
      if (!same)
        broken(std::string("a run in which nothing sleeps is the same with sleeping off (") + entry.keyword + ")");
    }
    if (!stepped(s, a, entry, "default mode, long run")) return;
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
  if (s.numParticles() <= kMaxRestParticles)
    for (const fosssim::CollisionEntry& entry : fosssim::collisionTable()) restWith(text, entry);
  return 0;
}
