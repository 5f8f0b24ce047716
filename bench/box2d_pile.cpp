// fosssim-box2d-pile: FOSSSim's benchmark piles (`rain` and the dense-pile family) stepped by
// Box2D 2.4 (Debian's libbox2d-dev), so the README can compare milliseconds per step on piles
// that flow in both engines.
//
//   fosssim-box2d-pile [--scenes rain,...] [--seed S] [--steps K] [--repeats R] [--blocks-csv FILE] [N ...]
//                                   default rain, seed 1, N = 1000 2500 10000 (-h: the options)
//
// The scene is not rebuilt by hand: the positions, masses, radii, half-planes, gravity, COR, dt
// and step count all come from bench::makeScene(kind, N, "hybrid", seed, ...), exactly what
// fosssim-bench --seed S steps (same generator, same seed, hence the same jittered starts). Each
// disk becomes a dynamic Box2D circle with friction 0 (FOSSSim's contacts are frictionless) and
// the scene's COR as restitution (Box2D treats approaches slower than b2_velocityThreshold, 1 m/s,
// as inelastic); each half-plane becomes a static edge (see addWall). Box2D keeps its own
// defaults otherwise: 8 velocity / 3 position iterations, sleeping on, continuous collision on.
//
// Timing follows fosssim-bench: world construction is not timed; a short warm-up run (5 steps,
// discarded), then 3 full runs from the initial positions, each in a fresh world; the fastest run's
// figures are printed (the machine may be shared). Per 100-step block as well as in total, because
// the cost of a pile changes as it falls, piles up and (in Box2D) goes to sleep: in fosssim-bench's
// block format (block_table.h), with the share at rest taken between blocks, untimed.
#include "bench_scenes.h"
#include "block_table.h"

#include "cli_values.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using fosssim::bench::BenchScene;

using fosssim::bench::Block;
using fosssim::bench::kBlockSteps;
constexpr int kVelocityIterations = 8, kPositionIterations = 3;  ///< Box2D's documented defaults

struct RunResult {
  double totalMs = 0;              ///< wall time of all steps
  long steps = 0;                  ///< steps taken (fewer than asked when stopped at the time limit)
  std::vector<Block> blocks;       ///< each block of kBlockSteps steps
  int awake = 0;                   ///< bodies awake after the last step
  double comY = 0;                 ///< mean height of the disks after the last step (all masses 1)
  int contacts = 0, touching = 0;  ///< Box2D's contacts (pairs of overlapping fattened boxes) at the end
};

/// One half-plane as a static two-sided edge on its boundary line. Only the upward half of the
/// line from the plane's point is used: the V's planes pass through the origin, and the lower
/// halves would lie under the other arm, where no disk goes, while doubling each edge's bounding
/// box (Box2D's broad phase would then pair every disk with both edges); the box's walls have
/// their points on the floor. A horizontal plane (a floor) gets the whole line, centred on its point.
void addWall(b2World& world, const fosssim::HalfPlane& plane, double length) {
  fosssim::Vec2 along(-plane.normal.y(), plane.normal.x());
  along.normalize();
  if (along.y() < 0) along = -along;
  const bool floor = std::abs(along.y()) < 1e-12;
  const fosssim::Vec2 start = floor ? fosssim::Vec2(plane.point - length * along) : plane.point;
  const fosssim::Vec2 end = plane.point + length * along;
  b2BodyDef def;  // static by default
  b2Body* body = world.CreateBody(&def);
  b2EdgeShape edge;
  edge.SetTwoSided(b2Vec2(static_cast<float>(start.x()), static_cast<float>(start.y())),
                   b2Vec2(static_cast<float>(end.x()), static_cast<float>(end.y())));
  b2FixtureDef fixture;
  fixture.shape = &edge;
  fixture.friction = 0;
  fixture.restitution = 0;
  body->CreateFixture(&fixture);
}

/// A Box2D world holding the scene in its initial state; `bodies` gets the disks, in scene order.
std::unique_ptr<b2World> buildWorld(const BenchScene& s, std::vector<b2Body*>& bodies) {
  auto world = std::make_unique<b2World>(b2Vec2(0.0f, static_cast<float>(s.gravity)));
  const int n = s.scene.numParticles();
  // The arms must reach above anything that can touch them: twice the highest start is ample
  // (the pile only sinks), and the length is along the arm, so divide by its slope's sine; a
  // floor must reach past the farthest disk.
  double top = 1;
  for (int i = 0; i < n; ++i)
    top = std::max({top, s.state.x[2 * i + 1] + s.scene.radius[i], std::abs(s.state.x[2 * i]) + s.scene.radius[i]});
  for (const auto& plane : s.scene.halfplanes) addWall(*world, plane, 2 * top * std::sqrt(2.0));
  bodies.assign(n, nullptr);
  for (int i = 0; i < n; ++i) {
    b2BodyDef def;
    def.type = s.scene.isFixed(i) ? b2_staticBody : b2_dynamicBody;
    def.position.Set(static_cast<float>(s.state.x[2 * i]), static_cast<float>(s.state.x[2 * i + 1]));
    def.linearVelocity.Set(static_cast<float>(s.state.v[2 * i]), static_cast<float>(s.state.v[2 * i + 1]));
    bodies[i] = world->CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = static_cast<float>(s.scene.radius[i]);
    b2FixtureDef fixture;
    fixture.shape = &circle;
    // Box2D takes a density: the scene's mass spread over the disk's area.
    const double r = s.scene.radius[i];
    fixture.density = static_cast<float>(s.scene.massOf(i) / (b2_pi * r * r));
    fixture.friction = 0;
    fixture.restitution = static_cast<float>(s.scene.collision.cor);
    bodies[i]->CreateFixture(&fixture);
  }
  return world;
}

/// Steps the scene; with a time limit (seconds, 0: none) it stops after the block that passes it.
RunResult run(const BenchScene& s, long steps, double timeLimit = 0) {
  std::vector<b2Body*> bodies;
  std::unique_ptr<b2World> world = buildWorld(s, bodies);
  RunResult out;
  const float dt = static_cast<float>(s.scene.dt);
  fosssim::VecX v(2 * bodies.size()), x(2 * bodies.size());
  auto blockStart = std::chrono::steady_clock::now();
  for (long k = 0; k < steps; ++k) {
    world->Step(dt, kVelocityIterations, kPositionIterations);
    if ((k + 1) % kBlockSteps == 0 || k + 1 == steps) {
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - blockStart).count();
      out.totalMs += ms;
      // Untimed: the velocities for the share at rest, and who is awake.
      Block b;
      b.first = k / kBlockSteps * kBlockSteps + 1;
      b.last = k + 1;
      b.msPerStep = ms / static_cast<double>(b.last - b.first + 1);
      int awake = 0;
      for (size_t i = 0; i < bodies.size(); ++i) {
        const b2Vec2 u = bodies[i]->GetLinearVelocity(), p = bodies[i]->GetPosition();
        v[2 * i] = u.x;
        v[2 * i + 1] = u.y;
        x[2 * i] = p.x;
        x[2 * i + 1] = p.y;
        awake += bodies[i]->IsAwake() ? 1 : 0;
      }
      b.atRest = fosssim::bench::atRestShare(s.scene, v);
      b.touching = fosssim::bench::touchingPairs(s.scene, x);
      b.awake = bodies.empty() ? 0 : static_cast<double>(awake) / static_cast<double>(bodies.size());
      out.blocks.push_back(b);
      out.steps = k + 1;
      if (timeLimit > 0 && out.totalMs > 1000 * timeLimit) break;
      blockStart = std::chrono::steady_clock::now();
    }
  }
  double massSum = 0, moment = 0;
  for (size_t i = 0; i < bodies.size(); ++i) {
    out.awake += bodies[i]->IsAwake() ? 1 : 0;
    massSum += bodies[i]->GetMass();
    moment += bodies[i]->GetMass() * bodies[i]->GetPosition().y;
  }
  // Contacts explain the cost: Box2D keeps one per pair of overlapping boxes, fattened by
  // b2_aabbExtension = 0.1 m, two disk radii here, so most are not touching.
  out.contacts = world->GetContactCount();
  for (b2Contact* c = world->GetContactList(); c; c = c->GetNext()) out.touching += c->IsTouching() ? 1 : 0;
  out.comY = massSum > 0 ? moment / massSum : 0;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {1000, 2500, 10000};
  std::vector<std::string> scenes = {"rain"};
  unsigned seed = 1;
  long steps = 0;  // 0: the scene's own length
  int repeats = 3;
  std::string blocksCsv;
  double timeLimit = 0;
  CLI::App app("FOSSSim's benchmark piles stepped by Box2D 2.4 (same starts as fosssim-bench --seed S), ms per step\n"
               "in total and per block of 100 steps: the README's comparison.",
               "fosssim-box2d-pile");
  std::vector<std::string> piles = {"rain"};
  piles.insert(piles.end(), fosssim::bench::pileKinds().begin(), fosssim::bench::pileKinds().end());
  app.add_option("N", sizes, "particle counts, each 1 to 10^6 (default 1000 2500 10000)")
      ->option_text("N ...")
      ->check(fosssim::cli::integerIn(1, 1000000));
  app.add_option("--scenes", scenes, "scenes, comma-separated, of " + fosssim::cli::listed(piles) + " (default rain)")
      ->option_text("NAME,...")
      ->delimiter(',')
      ->check(fosssim::cli::oneOf("scene", piles));
  app.add_option("--seed", seed, "seed of the scenes' jitter, as fosssim-bench's, 0 to 2^31 - 1 (default 1)")
      ->option_text("S")
      ->check(fosssim::cli::integerIn(0, 2147483647));
  app.add_option("--steps", steps, "steps per run, 1 to 10^9 (default: each scene's own length)")
      ->option_text("K")
      ->check(fosssim::cli::integerIn(1, 1000000000));
  app.add_option("--repeats", repeats, "timed runs per scene and size, 1 to 1000 (default 3)")
      ->option_text("R")
      ->check(fosssim::cli::integerIn(1, 1000));
  app.add_option("--blocks-csv", blocksCsv, "append the block tables' rows to this CSV file (fosssim-bench's format)")
      ->option_text("FILE");
  app.add_option("--time-limit", timeLimit,
                 "seconds per timed run: a run stops after the 100-step block that passes it (default: none)")
      ->option_text("S")
      ->check(fosssim::cli::integerIn(1, 1000000));
  if (const int status = fosssim::cli::parseCommandLine(app, argc, argv); status >= 0) return status;

  // The library's b2_version says 2.4.0 in the 2.4.1 release: print the package's version too.
  const std::string engine = std::string("Box2D ") + FOSSSIM_BOX2D_VERSION;
  std::printf(
      "%s (b2_version %d.%d.%d): FOSSSim's scenes (same starts, seed %u), %d velocity / %d position iterations, "
      "friction 0, restitution = the scene's COR, sleeping on, one thread; best of %d run%s\n",
      engine.c_str(), b2_version.major, b2_version.minor, b2_version.revision, seed, kVelocityIterations,
      kPositionIterations, repeats, repeats == 1 ? "" : "s");
  for (const std::string& kind : scenes)
    for (int n : sizes) {
      BenchScene s;
      if (!fosssim::bench::makeScene(kind, n, "hybrid", seed, s)) return 1;  // kinds were checked above
      const long length = steps > 0 ? steps : s.scene.numSteps();
      double startY = 0;
      for (int i = 0; i < s.scene.numParticles(); ++i) startY += s.state.x[2 * i + 1];
      startY /= s.scene.numParticles();

      run(s, std::min<long>(5, length));  // warm-up, as fosssim-bench's
      RunResult best;
      for (int r = 0; r < repeats; ++r) {
        RunResult trial = run(s, length, timeLimit);
        if (r == 0 || trial.totalMs / static_cast<double>(trial.steps) < best.totalMs / static_cast<double>(best.steps))
          best = trial;
      }
      std::printf(
          "%s N=%-6d %ld steps of %g s: %8.3f ms/step; awake at the end %d of %d; centre of mass height %.3f m "
          "(start %.3f m); contacts %d (%d touching)\n",
          kind.c_str(), s.scene.numParticles(), best.steps, s.scene.dt, best.totalMs / static_cast<double>(best.steps),
          best.awake, s.scene.numParticles(), best.comY, startY, best.contacts, best.touching);
      if (best.steps < length) std::printf("  (stopped at --time-limit %g s after %ld steps)\n", timeLimit, best.steps);
      const fosssim::bench::RunLabel label = fosssim::bench::runLabel(engine, s, seed);
      const int count = static_cast<int>(std::min<size_t>(best.blocks.size(), fosssim::bench::kMaxBlocks));
      fosssim::bench::printBlocks(label, best.blocks.data(), count);
      if (!blocksCsv.empty() && !fosssim::bench::appendBlocksCsv(blocksCsv, label, best.blocks.data(), count)) {
        std::fprintf(stderr, "fosssim-box2d-pile: cannot write %s: %s\n", blocksCsv.c_str(), std::strerror(errno));
        return 1;
      }
    }
  return 0;
}
