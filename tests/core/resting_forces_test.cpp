// Forces of particles at rest (ForceContext::resting): a sleeper goes back where it rests whatever
// the integrator predicts for it, so an explicit step may leave out what acts on sleepers alone.
// The promise: every other particle's force is the same to the last bit, and a run is the same
// whether the sleepers' forces were computed or not.
#include "../../src/core/collision/sleepers.h"
#include "contact_physics.h"

#include "fosssim/core/forces.h"

#include <random>

namespace fosssim::testing {
namespace {

/// n disks of radius 0.05 scattered in a square of side `side` (dense: most touch within the
/// penalty's reach), a chain of edges through the first 200, and two half-planes through the
/// square's lower left corner.
TestScene scatteredDisks(int n, double side, unsigned seed) {
  TestScene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, side);
  // Draws in braces or separate statements, left to right: a call's arguments are evaluated in an
  // order the compiler picks (gcc right to left, clang left to right).
  for (int i = 0; i < n; ++i) addBody(s, 1.0, Vec2{u(rng), u(rng)}, Vec2::Zero(), 0.05);
  for (int i = 0; i + 1 < std::min(n, 200); ++i) s.scene.edges.push_back(Edge{i, i + 1, 0.02});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0.1, 0.1), Vec2(0, 1)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0.1, 0.1), Vec2(1, 0)});
  return s;
}

VecX penaltyGradient(const TestScene& s, const PenaltyForce& force, const std::vector<char>* resting, int threads) {
  ForceContext context(false, threads);
  context.setResting(resting);
  VecX g = VecX::Zero(s.state.x.size());
  force.addGradientWith(s.scene, s.state.x, s.state.v, g, context);
  return g;
}

// A third of the particles resting (every row read, resting pairs dropped), nine tenths (the
// rows of resting particles that meet no moving one are skipped) and all (nothing to compute),
// on one thread and on two.
TEST(RestingForces, EveryMovingParticlesPenaltyForceIsTheSameBitForBit) {
  const PenaltyForce force(100.0, 0.05);
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const TestScene s = scatteredDisks(5000, 6.0, seed);
    const VecX full = penaltyGradient(s, force, nullptr, 1);
    ASSERT_GT(full.squaredNorm(), 0.0);
    for (double share : {0.33, 0.9, 1.0}) {
      std::mt19937 rng(seed + 100);
      std::bernoulli_distribution rests(share);
      std::vector<char> resting(5000);
      for (char& r : resting) r = rests(rng);
      for (int threads = 1; threads <= 2; ++threads) {
        SCOPED_TRACE("seed " + std::to_string(seed) + ", share " + std::to_string(share) + ", threads " +
                     std::to_string(threads));
        const VecX g = penaltyGradient(s, force, &resting, threads);
        int differs = 0;
        for (int i = 0; i < 5000; ++i) {
          if (resting[i]) {
            differs += at(g, i) != at(full, i);
            continue;
          }
          ASSERT_EQ(at(g, i), at(full, i)) << "moving particle " << i;
        }
        EXPECT_GT(differs, 0) << "no pair of resting particles was left out";
      }
    }
  }
}

/// Steps `a` with the sleepers' forces left out and `b` (the same scene) with the polynomial log
/// on, which records sleepers' predicted motion too: under an explicit integrator that turns the
/// leaving out off. The states must be the same bit for bit after every step. Raises `mostAsleep` to the most
/// particles asleep after a step and adds the sleepers woken to `woken`.
void runBothWays(TestScene& a, TestScene& b, int steps, int& mostAsleep, int& woken) {
  std::unique_ptr<Simulator> leaving, computing;
  SimulatorOptions options;
  options.handler.compat = false;
  ASSERT_TRUE(Simulator::create(a.scene, options, leaving).isOk());
  options.logPolynomials = true;
  ASSERT_TRUE(Simulator::create(b.scene, options, computing).isOk());
  for (int k = 0; k < steps; ++k) {
    ASSERT_TRUE(leaving->step(a.scene, a.state).isOk());
    ASSERT_TRUE(computing->step(b.scene, b.state).isOk());
    ASSERT_EQ(a.state.x, b.state.x) << "step " << k + 1;
    ASSERT_EQ(a.state.v, b.state.v) << "step " << k + 1;
    mostAsleep = std::max(mostAsleep, leaving->stats().asleep);
    woken += leaving->stats().woken;
  }
}

/// Three rows of twelve disks between two walls on the floor, under gravity and a penalty layer,
/// and one disk high above them that lands on the pile at about step 200.
TestScene pileAndDrop(const char* type) {
  TestScene s = contactScene(type, 0.0);
  addFloorAndGravity(s);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(-0.1, 0), Vec2(1, 0)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(2.4, 0), Vec2(-1, 0)});
  s.scene.forces.push_back(std::make_unique<PenaltyForce>(10.0, 0.01));
  for (int row = 0; row < 3; ++row)
    for (int k = 0; k < 12; ++k) addBody(s, 1.0, Vec2(0.2 * k + 0.1 * (row % 2), 0.1 + 0.18 * row), Vec2::Zero(), 0.1);
  addBody(s, 1.0, Vec2(1.1, 20.0), Vec2::Zero(), 0.1);
  return s;
}

// The pile falls asleep, then the disk from above lands on it and wakes part of it: with the
// sleepers' forces left out or computed, the states are the same bit for bit, so nothing in the
// step read a sleeper's incomplete force. Under an implicit integrator the sleepers are held
// where they rest and leave the linear system (implicit_system.h) with the log on too: their
// prediction is rest, which the log may record, so writing a trajectory does not change the run.
TEST(RestingForces, APileRunsTheSameWhetherSleepersForcesAreComputedOrNot) {
  for (const char* integrator : {"symplectic-euler", "implicit-euler", "linearized-implicit-euler"}) {
    for (const char* type : kEventTypes) {
      SCOPED_TRACE(std::string(integrator) + ", " + type);
      TestScene a = pileAndDrop(type), b = pileAndDrop(type);
      a.scene.integrator = b.scene.integrator = integrator;
      int mostAsleep = 0, woken = 0;
      runBothWays(a, b, 300, mostAsleep, woken);
      if (HasFatalFailure()) return;
      EXPECT_GE(mostAsleep, 30) << "the pile should have fallen asleep";
      EXPECT_GT(woken, 0) << "the dropped disk should have woken sleepers";
      EXPECT_LT(at(a.state.x, 36).y(), 1.0) << "the dropped disk should have landed";
    }
  }
}

/// A random heap: `disks` disks of random radius dropped from random heights into a box (floor
/// and walls), a fixed disk on the floor, capsule links of three particles, gravity and a penalty
/// layer; and one disk high above that lands on the heap after it has settled.
TestScene randomHeap(const char* type, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TestScene s = contactScene(type, 0.2 * u(rng));
  addFloorAndGravity(s);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(-1, 0), Vec2(1, 0)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(1, 0), Vec2(-1, 0)});
  // Draws in separate statements or braces, left to right: a call's arguments are evaluated in an
  // order the compiler picks (gcc right to left, clang left to right).
  const double stiffness = 5.0 + 20.0 * u(rng);
  const double thickness = 0.005 + 0.01 * u(rng);
  s.scene.forces.push_back(std::make_unique<PenaltyForce>(stiffness, thickness));
  addBody(s, 1.0, Vec2(0.3, 0.05), Vec2::Zero(), 0.05, true);
  for (int k = 0; k < 30; ++k) {
    const double m = 0.5 + u(rng);
    const Vec2 x{-0.9 + 1.8 * u(rng), 0.1 + 1.5 * u(rng)};
    addBody(s, m, x, Vec2::Zero(), 0.04 + 0.03 * u(rng));
  }
  for (int link = 0; link < 2; ++link) {
    const Vec2 at0(-0.6 + 1.0 * u(rng), 1.8 + 0.3 * link);
    const int first = s.scene.numParticles();
    for (int k = 0; k < 3; ++k) addBody(s, 0.5, at0 + Vec2(0.1 * k, 0), Vec2::Zero(), 0.03);
    for (int k = 0; k < 2; ++k) s.scene.edges.push_back(Edge{first + k, first + k + 1, 0.03});
  }
  addBody(s, 1.0, Vec2(-0.5 + u(rng), 25.0), Vec2::Zero(), 0.05);
  return s;
}

// The same promise on random heaps, with fixed particles and edges among the sleepers; under the
// implicit integrators, whose sleepers leave the linear system (the heaps' edges tie their ends
// into islands, and the fixed disk is left out of it from the start).
TEST(RestingForces, RandomHeapsRunTheSameWhetherSleepersForcesAreComputedOrNot) {
  for (const char* integrator : {"symplectic-euler", "implicit-euler", "linearized-implicit-euler"}) {
    int slept = 0, woken = 0;
    for (const char* type : kEventTypes) {
      for (unsigned seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(std::string(integrator) + ", " + type + ", seed " + std::to_string(seed));
        TestScene a = randomHeap(type, seed), b = randomHeap(type, seed);
        a.scene.integrator = b.scene.integrator = integrator;
        runBothWays(a, b, 300, slept, woken);
        if (HasFatalFailure()) return;
      }
    }
    EXPECT_GE(slept, 20) << integrator << ": the heaps should have fallen asleep";
    EXPECT_GT(woken, 0) << integrator << ": the dropped disks should have woken sleepers";
  }
}

// What a sleeper's incomplete prediction could still reach: its kick, the velocity change its
// forces gave it, which the zones' holds and the sleep test read if a hit wakes it. A disk on the
// floor whose contact takes back a kick of 0.1 m/s every step falls asleep; then, told that its
// prediction is incomplete, it keeps the kick of 0.1 whatever is predicted.
TEST(RestingForces, ASleeperKeepsTheKickOfTheStepItFellAsleepIn) {
  TestScene s = contactScene("hybrid", 0.0);
  addBody(s, 1.0, Vec2(0, 0.1), Vec2::Zero(), 0.1);
  Sleepers sleepers;
  const State rest = s.state;
  auto step = [&](const Vec2& predicted) {
    State state = rest;
    at(state.v, 0) = predicted;
    sleepers.begin(s.scene, rest, state, s.scene.dt);
    return state;
  };
  EXPECT_EQ(sleepers.restingAtStart(s.scene, rest), nullptr);
  for (int k = 0; k < kStepsToSleep && !sleepers.any(); ++k) {
    step(Vec2(0, -0.1));
    State end = rest;  // the contact took the kick back
    sleepers.end(s.scene, rest, end);
  }
  ASSERT_TRUE(sleepers.any());
  const std::vector<char>* resting = sleepers.restingAtStart(s.scene, rest);
  ASSERT_NE(resting, nullptr);
  EXPECT_EQ((*resting)[0], 1);
  const State state = step(Vec2(0, -0.03));  // what incomplete forces predict
  EXPECT_EQ(sleepers.kick(0), 0.1);
  EXPECT_EQ(at(state.v, 0), Vec2::Zero()) << "back at rest";
  // Moved by a caller between steps, it is not resting: it takes its prediction and its kick.
  State moved = rest;
  at(moved.x, 0).x() += 0.5;
  EXPECT_EQ((*sleepers.restingAtStart(s.scene, moved))[0], 0);
}

}  // namespace
}  // namespace fosssim::testing
