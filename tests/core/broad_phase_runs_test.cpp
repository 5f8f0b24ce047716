// Whole runs with the broad phase are bit for bit the runs that check every pair (the reference's
// way), for every collision handler, both quintic forms and with the failsafe at work: the same
// positions and velocities after every step, the same impulses, the same counts of collisions,
// impulse passes and zones. Runs that log polynomials (which check every pair) end the same too.
#include "support/collision_type.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

/// A little of everything: disks of several sizes raining into a V of two half-planes, a fixed
/// chain of thin edges across the V, a free chain of springs falling on it, a few fast bullets.
TestScene mixedScene(const std::string& type, int maxIterations, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = 0.01;
  s.scene.collision.type = test::collisionType(type);
  s.scene.collision.cor = 0.5;
  s.scene.collision.maxIterations = maxIterations;
  // One draw a statement, left to right: a call's arguments are evaluated in an order the compiler
  // picks (gcc right to left, clang left to right), and both must build the same scenes.
  for (int row = 0; row < 8; ++row)
    for (int col = 0; col < 10; ++col) {
      const double m = 0.5 + unit(rng);
      const double x = -1.0 + 0.2 * col + 0.03 * unit(rng);
      const double vx = unit(rng) - 0.5;
      addBody(s, m, Vec2(x, 0.8 + 0.2 * row), Vec2(vx, -1), 0.04 + 0.05 * unit(rng));
    }
  const int chain = s.state.numParticles();
  for (int k = 0; k < 9; ++k) addBody(s, 1.0, Vec2(-0.8 + 0.2 * k, 0.45), Vec2::Zero(), 0.01, /*fixed=*/true);
  for (int k = 0; k + 1 < 9; ++k) s.scene.edges.push_back(Edge{chain + k, chain + k + 1, 0.01});
  const int rope = s.state.numParticles();
  for (int k = 0; k < 8; ++k) addBody(s, 0.3, Vec2(-0.7 + 0.18 * k, 2.6), Vec2(0, -2), 0.03);
  for (int k = 0; k + 1 < 8; ++k) {
    s.scene.edges.push_back(Edge{rope + k, rope + k + 1, 0.02});
    s.scene.forces.push_back(std::make_unique<SpringForce>(rope + k, rope + k + 1, 200.0, 0.18, 0.5));
  }
  for (int k = 0; k < 4; ++k) addBody(s, 0.1, Vec2(-0.9 + 0.5 * k, 1.2), Vec2(8.0 * (unit(rng) - 0.5), -60), 0.015);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(1, 1)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(-2, 2)});  // unnormalised on purpose
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  if (type == "hybrid") s.scene.forces.push_back(std::make_unique<PenaltyForce>(10.0, 0.02));
  if (type == "penalty") s.scene.forces.push_back(std::make_unique<PenaltyForce>(1000.0, 0.01));
  return s;
}

bool sameBits(const VecX& a, const VecX& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

struct SimRun {
  TestScene s;
  std::unique_ptr<Simulator> sim;
};

SimRun start(const std::string& type, int maxIterations, unsigned seed, bool compat, bool allPairs, bool log,
          int threads = 1) {
  SimRun r{mixedScene(type, maxIterations, seed), nullptr};
  SimulatorOptions options;
  options.handler.compat = compat;
  options.handler.allPairs = allPairs;
  options.handler.threads = threads;
  options.logPolynomials = log;
  // These runs compare bits, not physics. With ten impulse passes the hybrid handler meets its
  // known divergence on this scene (a pass sums the impulses of redundant contacts: a disk leaves
  // at 1.7e5 m/s in step 1), which the energy watch rightly stops.
  options.watchEnergy = false;
  EXPECT_TRUE(Simulator::create(r.s.scene, options, r.sim).isOk());
  return r;
}

void expectIdenticalRuns(const std::string& type, int maxIterations, unsigned seed, bool compat, int steps) {
  SimRun fast = start(type, maxIterations, seed, compat, false, false);
  SimRun reference = start(type, maxIterations, seed, compat, true, false);
  SimRun logged = start(type, maxIterations, seed, compat, false, true);
  long collisions = 0, failsafeSteps = 0;
  for (int k = 0; k < steps; ++k) {
    SCOPED_TRACE(type + " maxiters " + std::to_string(maxIterations) + " seed " + std::to_string(seed) +
                 (compat ? " compat" : "") + " step " + std::to_string(k + 1));
    ASSERT_TRUE(fast.sim->step(fast.s.scene, fast.s.state).isOk());
    ASSERT_TRUE(reference.sim->step(reference.s.scene, reference.s.state).isOk());
    ASSERT_TRUE(logged.sim->step(logged.s.scene, logged.s.state).isOk());
    ASSERT_TRUE(sameBits(fast.s.state.x, reference.s.state.x));
    ASSERT_TRUE(sameBits(fast.s.state.v, reference.s.state.v));
    ASSERT_TRUE(sameBits(fast.s.state.x, logged.s.state.x));
    ASSERT_TRUE(sameBits(fast.s.state.v, logged.s.state.v));
    const auto& a = fast.sim->log().impulses;
    const auto& b = reference.sim->log().impulses;
    ASSERT_EQ(a.size(), b.size());
    for (size_t m = 0; m < a.size(); ++m) {
      EXPECT_EQ(a[m].kind, b[m].kind);
      EXPECT_EQ(a[m].i, b[m].i);
      EXPECT_EQ(a[m].j, b[m].j);
      EXPECT_EQ(a[m].n, b[m].n);
      EXPECT_EQ(a[m].tau, b[m].tau);
    }
    const StepStats& sf = fast.sim->stats();
    const StepStats& sr = reference.sim->stats();
    EXPECT_EQ(sf.collisions, sr.collisions);
    EXPECT_EQ(sf.impulsePasses, sr.impulsePasses);
    EXPECT_EQ(sf.failsafeUsed, sr.failsafeUsed);
    EXPECT_EQ(sf.zones, sr.zones);
    EXPECT_EQ(sf.largestZone, sr.largestZone);
    for (int p = 0; p < fast.s.state.numParticles(); ++p)
      ASSERT_EQ(fast.sim->zoneOf(p) >= 0, reference.sim->zoneOf(p) >= 0);
    // The broad phase queries fewer pairs (or as many, when everything is close).
    if (type != "penalty") {
      EXPECT_LE(sf.candidatePairs, sr.candidatePairs);
    }
    collisions += sf.collisions + static_cast<long>(a.size()) + sf.zones;
    failsafeSteps += sf.failsafeUsed;
  }
  if (type != "penalty") {
    EXPECT_GT(collisions, 0) << "the scene must collide";
  }
  if (type == "hybrid" && maxIterations <= 2) {
    EXPECT_GT(failsafeSteps, 0) << "the failsafe must act";
  }
}

TEST(BroadPhaseRuns, SimpleHandlerIsIdentical) {
  for (unsigned seed : {1u, 2u}) expectIdenticalRuns("simple", 10, seed, false, 120);
}

TEST(BroadPhaseRuns, ContinuousTimeHandlerIsIdentical) {
  for (bool compat : {false, true})
    for (unsigned seed : {1u, 2u}) expectIdenticalRuns("continuous-time", 10, seed, compat, 120);
}

TEST(BroadPhaseRuns, HybridHandlerIsIdentical) {
  for (bool compat : {false, true})
    for (int maxIterations : {0, 1, 2, 10}) expectIdenticalRuns("hybrid", maxIterations, 3, compat, 100);
}

TEST(BroadPhaseRuns, PenaltyForceIsIdentical) {
  for (unsigned seed : {1u, 2u}) expectIdenticalRuns("penalty", 10, seed, false, 120);
}

}  // namespace
}  // namespace fosssim

namespace fosssim {
namespace {

/// 6000 disks with random velocities falling into a V, on a fixed chain of edges.
TestScene pile(const std::string& type) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = 0.01;
  s.scene.collision.type = test::collisionType(type);
  s.scene.collision.cor = 0.3;
  s.scene.collision.maxIterations = 4;
  for (int row = 0; row < 60; ++row)
    for (int col = 0; col < 100; ++col) {  // one draw a statement, left to right (see mixedScene)
      const double m = 0.5 + unit(rng);
      const double x = -10.0 + 0.2 * col + 0.03 * unit(rng);
      const Vec2 v{2 * unit(rng) - 1, 2 * unit(rng) - 3};
      addBody(s, m, Vec2(x, 11.0 + 0.2 * row), v, 0.04 + 0.05 * unit(rng));
    }
  const int chain = s.state.numParticles();
  for (int k = 0; k < 41; ++k) addBody(s, 1.0, Vec2(-10.0 + 0.5 * k, 10.5), Vec2::Zero(), 0.01, /*fixed=*/true);
  for (int k = 0; k + 1 < 41; ++k) s.scene.edges.push_back(Edge{chain + k, chain + k + 1, 0.02});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(1, 1)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(-1, 1)});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  if (type == "hybrid") s.scene.forces.push_back(std::make_unique<PenaltyForce>(10.0, 0.02));
  if (type == "penalty") s.scene.forces.push_back(std::make_unique<PenaltyForce>(1000.0, 0.01));
  return s;
}

// Threads split the rows of the broad and narrow phase and of the penalty force; the results are
// joined in row order, so any thread count gives the same run. (Scenes of several thousand
// particles: smaller ones are not split.)
TEST(BroadPhaseRuns, ThreadCountDoesNotChangeResults) {
  for (const char* type : {"hybrid", "continuous-time", "penalty"}) {
    std::vector<SimRun> runs;
    for (int threads : {1, 2, 3}) {
      SimRun r{pile(type), nullptr};
      SimulatorOptions options;
      options.handler.threads = threads;
      ASSERT_TRUE(Simulator::create(r.s.scene, options, r.sim).isOk());
      runs.push_back(std::move(r));
    }
    long collisions = 0;
    for (int k = 0; k < 25; ++k) {
      for (SimRun& r : runs) {
        const Status st = r.sim->step(r.s.scene, r.s.state);
        ASSERT_TRUE(st.isOk()) << type << ": " << st.message();
      }
      for (size_t m = 1; m < runs.size(); ++m) {
        ASSERT_TRUE(sameBits(runs[0].s.state.x, runs[m].s.state.x)) << type << " step " << k + 1;
        ASSERT_TRUE(sameBits(runs[0].s.state.v, runs[m].s.state.v)) << type << " step " << k + 1;
        EXPECT_EQ(runs[0].sim->stats().candidatePairs, runs[m].sim->stats().candidatePairs);
      }
      collisions += runs[0].sim->stats().collisions;
    }
    if (std::string(type) != "penalty") {
      EXPECT_GT(collisions, 0) << type;
    }
  }
}

}  // namespace
}  // namespace fosssim
