// fosssim-box2d-pile: FOSSSim's `rain` pile stepped by Box2D 2.4 (Debian's libbox2d-dev), so the
// README can compare milliseconds per step on a pile that flows in both engines.
//
//   fosssim-box2d-pile [N ...]      default N = 1000 2500 10000 (-h: the options)
//
// The scene is not rebuilt by hand: the positions, masses, radii, half-planes, gravity, dt and
// step count all come from bench::makeScene("rain", N, "hybrid", 1, ...), exactly what
// fosssim-bench steps (same generator, same seed, hence the same jittered grid). Each disk becomes
// a dynamic Box2D circle with friction 0 (FOSSSim's contacts are frictionless) and restitution 0
// (the scene's COR); each half-plane becomes a static edge (see addWall). Box2D keeps its own
// defaults otherwise: 8 velocity / 3 position iterations, sleeping on, continuous collision on.
//
// Timing follows fosssim-bench: world construction is not timed; a short warm-up run (5 steps,
// discarded), then 3 full runs from the initial positions, each in a fresh world; the fastest run's
// figures are printed (the machine may be shared). Per 100-step block as well as in total, because
// the cost of a pile changes as it falls, piles up and (in Box2D) goes to sleep.
#include "bench_scenes.h"

#include "cli_values.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using fosssim::bench::BenchScene;

constexpr long kBlock = 100;  ///< steps per reported block
constexpr int kVelocityIterations = 8, kPositionIterations = 3;  ///< Box2D's documented defaults

struct RunResult {
  double totalMs = 0;              ///< wall time of all steps
  std::vector<double> blockMs;     ///< wall time of each block of kBlock steps
  int awake = 0;                   ///< bodies awake after the last step
  double comY = 0;                 ///< mean height of the disks after the last step (all masses 1)
  int contacts = 0, touching = 0;  ///< Box2D's contacts (pairs of overlapping fattened boxes) at the end
};

/// One half-plane as a static two-sided edge on its boundary line. Only the upward half of the
/// line from the plane's point is used: rain's planes pass through the origin and form a V, and
/// the lower halves would lie under the other arm, where no disk goes, while doubling each edge's
/// bounding box (Box2D's broad phase would then pair every disk with both edges).
void addWall(b2World& world, const fosssim::HalfPlane& plane, double length) {
  fosssim::Vec2 along(-plane.normal.y(), plane.normal.x());
  along.normalize();
  if (along.y() < 0) along = -along;
  const fosssim::Vec2 end = plane.point + length * along;
  b2BodyDef def;  // static by default
  b2Body* body = world.CreateBody(&def);
  b2EdgeShape edge;
  edge.SetTwoSided(b2Vec2(static_cast<float>(plane.point.x()), static_cast<float>(plane.point.y())),
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
  // (the pile only sinks), and the length is along the arm, so divide by its slope's sine.
  double top = 1;
  for (int i = 0; i < n; ++i) top = std::max(top, s.state.x[2 * i + 1] + s.scene.radius[i]);
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
    fixture.restitution = 0;
    bodies[i]->CreateFixture(&fixture);
  }
  return world;
}

RunResult run(const BenchScene& s, long steps) {
  std::vector<b2Body*> bodies;
  std::unique_ptr<b2World> world = buildWorld(s, bodies);
  RunResult out;
  const float dt = static_cast<float>(s.scene.dt);
  auto blockStart = std::chrono::steady_clock::now();
  const auto start = blockStart;
  for (long k = 0; k < steps; ++k) {
    world->Step(dt, kVelocityIterations, kPositionIterations);
    if ((k + 1) % kBlock == 0 || k + 1 == steps) {
      const auto now = std::chrono::steady_clock::now();
      out.blockMs.push_back(std::chrono::duration<double, std::milli>(now - blockStart).count());
      blockStart = now;
    }
  }
  out.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
  CLI::App app("FOSSSim's rain pile stepped by Box2D 2.4 (same positions), ms per step: the README's comparison.",
               "fosssim-box2d-pile");
  app.add_option("N", sizes, "particle counts, each 1 to 10^6 (default 1000 2500 10000)")
      ->option_text("N ...")
      ->check(fosssim::cli::integerIn(1, 1000000));
  if (const int status = fosssim::cli::parseCommandLine(app, argc, argv); status >= 0) return status;

  // The library's b2_version says 2.4.0 in the 2.4.1 release: print the package's version too.
  std::printf("Box2D %s (b2_version %d.%d.%d): FOSSSim's rain pile (same positions), %d velocity / %d position iterations, "
              "friction 0, restitution 0, sleeping on, one thread; best of 3 runs\n",
              FOSSSIM_BOX2D_VERSION, b2_version.major, b2_version.minor, b2_version.revision, kVelocityIterations, kPositionIterations);
  for (int n : sizes) {
    BenchScene s;
    if (!fosssim::bench::makeScene("rain", n, "hybrid", 1, s)) return 1;  // seed 1, as fosssim-bench
    const long steps = s.scene.numSteps();
    double startY = 0;
    for (int i = 0; i < s.scene.numParticles(); ++i) startY += s.state.x[2 * i + 1];
    startY /= s.scene.numParticles();

    run(s, std::min<long>(5, steps));  // warm-up, as fosssim-bench's
    RunResult best;
    for (int r = 0; r < 3; ++r) {
      RunResult trial = run(s, steps);
      if (r == 0 || trial.totalMs < best.totalMs) best = trial;
    }
    std::printf("rain N=%-6d %ld steps of %g s: %8.3f ms/step; per %ld-step block:", s.scene.numParticles(), steps,
                s.scene.dt, best.totalMs / steps, kBlock);
    for (size_t b = 0; b < best.blockMs.size(); ++b) {
      const long inBlock = std::min(kBlock, steps - static_cast<long>(b) * kBlock);
      std::printf(" %.3f", best.blockMs[b] / inBlock);
    }
    std::printf("; awake at the end %d of %d; centre of mass height %.3f m (start %.3f m); contacts %d (%d touching)\n",
                best.awake, s.scene.numParticles(), best.comY, startY, best.contacts, best.touching);
    std::fflush(stdout);
  }
  return 0;
}
