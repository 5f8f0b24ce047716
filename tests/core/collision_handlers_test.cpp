// The collision handlers on hand-made scenes whose outcome follows from the physics alone:
// momentum exchange in 1D collisions, restitution, fixed (infinitely heavy) particles,
// tunnelling through thin edges, chains that need several impulse passes, piles that need the
// rigid-zone failsafe, and mirror symmetry.
#include "support/collision_type.h"
#include "fosssim/core/simulator.h"
#include "fosssim/core/verify.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

TestScene collisionSetup(const std::string& type, double cor, double dt = 0.01) {
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = dt;
  s.scene.collision.type = test::collisionType(type);
  s.scene.collision.cor = cor;
  s.scene.collision.maxIterations = 100;
  return s;
}

std::unique_ptr<Simulator> makeSimulator(const TestScene& s, bool compat = false) {
  std::unique_ptr<Simulator> sim;
  SimulatorOptions options;
  options.handler.compat = compat;
  EXPECT_TRUE(Simulator::create(s.scene, options, sim).isOk());
  return sim;
}

void run(TestScene& s, Simulator& sim, int steps) {
  for (int k = 0; k < steps; ++k) ASSERT_TRUE(sim.step(s.scene, s.state).isOk());
}

Vec2 momentum(const TestScene& s) {
  Vec2 p = Vec2::Zero();
  for (int i = 0; i < s.state.numParticles(); ++i)
    if (!s.scene.isFixed(i)) p += s.scene.massOf(i) * at(s.state.v, i);
  return p;
}

const char* const kImpulseHandlers[] = {"simple", "continuous-time", "hybrid"};

// Two equal masses, head on: an elastic collision exchanges their velocities, a perfectly
// inelastic one leaves both with the mean velocity. Holds for every impulse handler.
TEST(CollisionHandlers, HeadOnEqualMassesExchangeOrShareVelocity) {
  for (const char* type : kImpulseHandlers) {
    for (double cor : {1.0, 0.0}) {
      TestScene s = collisionSetup(type, cor);
      addBody(s, 1.0, Vec2(-0.5, 0), Vec2(2, 0), 0.2);
      addBody(s, 1.0, Vec2(0.5, 0), Vec2(0, 0), 0.2);
      auto sim = makeSimulator(s);
      run(s, *sim, 60);  // contact after about 0.3 s
      SCOPED_TRACE(std::string(type) + " COR " + std::to_string(cor));
      const Vec2 expectA = cor == 1.0 ? Vec2(0, 0) : Vec2(1, 0), expectB = cor == 1.0 ? Vec2(2, 0) : Vec2(1, 0);
      EXPECT_LT((at(s.state.v, 0) - expectA).norm(), 1e-12);
      EXPECT_LT((at(s.state.v, 1) - expectB).norm(), 1e-12);
      EXPECT_LT((momentum(s) - Vec2(2, 0)).norm(), 1e-12);
    }
  }
}

// A fixed particle is infinitely heavy: an elastic ball bounces straight back, the fixed one
// does not move.
TEST(CollisionHandlers, FixedParticleReflectsAndStays) {
  for (const char* type : kImpulseHandlers) {
    TestScene s = collisionSetup(type, 1.0);
    addBody(s, 1.0, Vec2(-0.5, 0), Vec2(3, 0), 0.1);
    addBody(s, 1.0, Vec2(0.5, 0), Vec2(0, 0), 0.1, /*fixed=*/true);
    auto sim = makeSimulator(s);
    run(s, *sim, 40);
    EXPECT_LT((at(s.state.v, 0) - Vec2(-3, 0)).norm(), 1e-12) << type;
    EXPECT_EQ(at(s.state.x, 1), Vec2(0.5, 0)) << type;
  }
}

// A fixed particle given a velocity: the course's integrators move it at that velocity (x += h v,
// its force zeroed), and --compat does, for every handler. The default mode's time-ordered
// handlers keep pairs apart only against fixed particles at rest: their first step fails with a
// message naming the particle (a 4 m/s fixed disk pushing two disks into a wall used to leave
// pairs overlapping in 14 of 50 steps); the same scene at rest runs.
TEST(CollisionHandlers, AMovingFixedParticleMovesInCompatAndIsRefusedByTheDefaultMode) {
  const auto scene = [](const char* type, double speed) {
    TestScene s = collisionSetup(type, 0.5);
    addBody(s, 1.0, Vec2(-1, 0), Vec2(speed, 0), 0.1, /*fixed=*/true);
    addBody(s, 1.0, Vec2(0, 0), Vec2(0, 0), 0.1);
    addBody(s, 1.0, Vec2(0.2, 0), Vec2(0, 0), 0.1);
    s.scene.halfplanes.push_back(HalfPlane{Vec2(0.5, 0), Vec2(-1, 0)});
    return s;
  };
  for (const char* type : kImpulseHandlers) {
    TestScene s = scene(type, 4.0);
    auto compat = makeSimulator(s, /*compat=*/true);
    run(s, *compat, 5);
    EXPECT_NEAR(at(s.state.x, 0).x(), -1 + 5 * 0.01 * 4.0, 1e-12) << type;
  }
  for (const char* type : {"continuous-time", "hybrid"}) {
    TestScene s = scene(type, 4.0);
    auto sim = makeSimulator(s);
    const Status status = sim->step(s.scene, s.state);
    ASSERT_FALSE(status.isOk()) << type;
    EXPECT_NE(status.message().find("particle 0 is fixed but moves (velocity (4, 0))"), std::string::npos)
        << status.message();
    EXPECT_NE(status.message().find("--compat"), std::string::npos) << status.message();
    TestScene still = scene(type, 0.0);
    auto stillSim = makeSimulator(still);
    run(still, *stillSim, 5);
  }
}

// Restitution against a half-plane: the normal velocity leaves as -COR times what it came with.
TEST(CollisionHandlers, HalfPlaneBounceScalesNormalVelocityByCor) {
  for (const char* type : {"continuous-time", "hybrid"}) {
    for (double cor : {0.0, 0.5, 1.0}) {
      TestScene s = collisionSetup(type, cor);
      addBody(s, 1.0, Vec2(0, 0.5), Vec2(1, -2), 0.1);
      s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(0, 3)});  // unnormalised on purpose
      auto sim = makeSimulator(s);
      run(s, *sim, 40);
      SCOPED_TRACE(std::string(type) + " COR " + std::to_string(cor));
      EXPECT_NEAR(s.state.v[0], 1.0, 1e-12);  // tangential velocity untouched
      EXPECT_NEAR(s.state.v[1], 2.0 * cor, 1e-12);
      EXPECT_GE(s.state.x[1], 0.1 - 1e-12);  // never below the surface
    }
  }
}

// A particle moving one unit per step against a thin fixed edge: discrete detection never sees
// the overlap and lets it through; continuous-time detection finds the crossing.
TEST(CollisionHandlers, FastParticleTunnelsOnlyThroughDiscreteDetection) {
  for (const char* type : kImpulseHandlers) {
    TestScene s = collisionSetup(type, 1.0);
    addBody(s, 1.0, Vec2(0, 1.55), Vec2(0, -100), 0.01);
    addBody(s, 1.0, Vec2(-1, 0), Vec2(0, 0), 0.01, true);
    addBody(s, 1.0, Vec2(1, 0), Vec2(0, 0), 0.01, true);
    s.scene.edges.push_back(Edge{1, 2, 0.005});
    auto sim = makeSimulator(s);
    run(s, *sim, 3);
    const bool tunnelled = s.state.x[1] < 0;
    EXPECT_EQ(tunnelled, std::string(type) == "simple") << type << " ends at y = " << s.state.x[1];
    if (!tunnelled) {
      EXPECT_NEAR(s.state.v[1], 100.0, 1e-9) << type;
    }
  }
}

// A ball hits the first of a row of touching balls: impulses travel down the row one pass at a
// time, so the course's hybrid method (--compat: passes of summed impulses) needs several passes;
// momentum is kept and nothing overlaps after. (The default mode's events: contact_physics_test.)
TEST(CollisionHandlers, ChainNeedsSeveralImpulsePasses) {
  TestScene s = collisionSetup("hybrid", 1.0);
  s.scene.collision.maxIterations = 50;
  addBody(s, 1.0, Vec2(-0.4, 0), Vec2(5, 0), 0.1);
  for (int k = 0; k < 4; ++k) addBody(s, 1.0, Vec2(0.2 * k, 0), Vec2(0, 0), 0.1 - 1e-9);
  auto sim = makeSimulator(s, /*compat=*/true);
  const Vec2 p0 = momentum(s);
  int maxPasses = 0;
  for (int k = 0; k < 30; ++k) {
    ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
    maxPasses = std::max(maxPasses, sim->stats().impulsePasses);
  }
  EXPECT_LT((momentum(s) - p0).norm(), 1e-9);
  EXPECT_GE(maxPasses, 3);
  for (int i = 0; i < 5; ++i)
    for (int j = i + 1; j < 5; ++j)
      EXPECT_GE((at(s.state.x, j) - at(s.state.x, i)).norm(), 0.2 - 1e-6) << i << " " << j;
}

// A dense pile dropped into a V with a single impulse pass (per particle and step in the default
// mode): impulses alone cannot resolve it, so the failsafe must act, and after every step nothing
// collides outside a rigid zone. Both modes.
TEST(CollisionHandlers, PileNeedsTheFailsafeAndEndsCollisionFree) {
  for (const bool compat : {false, true}) {
  SCOPED_TRACE(compat ? "compat" : "default mode");
  TestScene s = collisionSetup("hybrid", 0.0, 0.02);
  s.scene.collision.maxIterations = 1;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 5; ++col)
      addBody(s, 1.0 + 0.1 * col, Vec2(-0.5 + 0.21 * col + 0.05 * row, 0.6 + 0.21 * row), Vec2(0, -3), 0.1);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(1, 1)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(-1, 1)});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  auto sim = makeSimulator(s, compat);
  int failsafeSteps = 0, largestZone = 0;
  for (int k = 0; k < 60; ++k) {
    ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
    failsafeSteps += sim->stats().failsafeUsed;
    largestZone = std::max(largestZone, sim->stats().largestZone);
    const auto left = sim->unresolved(s.scene, s.state);
    ASSERT_TRUE(left.empty()) << "step " << k + 1 << ": pair (" << left[0].i << ", " << left[0].j << ")";
  }
  EXPECT_GT(failsafeSteps, 0);
  EXPECT_GE(largestZone, 2);
  }
}

// Mirror-symmetric scene, simultaneous impulses summed as the course does (--compat): the result
// stays mirror-symmetric. (The default mode applies simultaneous impulses one after another,
// which keeps energy from growing but picks an order: contact_physics_test.)
TEST(CollisionHandlers, MirrorSymmetricSceneStaysSymmetric) {
  TestScene s = collisionSetup("hybrid", 0.5);
  addBody(s, 1.0, Vec2(-1, 0), Vec2(4, 0), 0.2);
  addBody(s, 1.0, Vec2(1, 0), Vec2(-4, 0), 0.2);
  addBody(s, 2.0, Vec2(0, 0.5), Vec2(0, -1), 0.2);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, -0.5), Vec2(0, 1)});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  auto sim = makeSimulator(s, /*compat=*/true);
  run(s, *sim, 100);
  EXPECT_NEAR(s.state.x[0], -s.state.x[2], 1e-9);
  EXPECT_NEAR(s.state.x[1], s.state.x[3], 1e-9);
  EXPECT_NEAR(s.state.x[4], 0.0, 1e-9);
  EXPECT_NEAR(s.state.v[0], -s.state.v[2], 1e-9);
}

}  // namespace
}  // namespace fosssim
