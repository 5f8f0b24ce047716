// The energy watch (src/core/energy_watch.h): blow-ups stop with a message that names step,
// particle, force and what to change; honest scenes, far from the origin or in other units, run.
#include "support/collision_type.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include "core/energy_watch.h"

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

/// How a run ended.
struct RunEnd {
  Status status = Status::ok();
  long steps = 0;         ///< steps completed without failure
  double topSpeed = 0;    ///< the largest particle speed over the completed steps
  double growth = 0;      ///< the watch's largest gain / scale
};

RunEnd runFor(TestScene& s, long steps, bool watch = true) {
  SimulatorOptions options;
  options.watchEnergy = watch;
  std::unique_ptr<Simulator> sim;
  RunEnd end;
  end.status = Simulator::create(s.scene, options, sim);
  for (long k = 0; end.status && k < steps; ++k) {
    end.status = sim->step(s.scene, s.state);
    if (!end.status) break;
    ++end.steps;
    for (int i = 0; i < s.state.numParticles(); ++i) end.topSpeed = std::max(end.topSpeed, at(s.state.v, i).norm());
  }
  if (sim) end.growth = sim->energyGrowth();
  return end;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// A ball of radius 0.1 dropped from height 1 onto the floor y = 0 under gravity, in units
/// scaled by length L, mass M and time T (powers of two keep the arithmetic exact).
TestScene droppedBall(const std::string& collision, double k, double thickness, double L = 1, double M = 1,
                      double T = 1) {
  TestScene s;
  addBody(s, 1.0 * M, Vec2(0, 1) * L, Vec2::Zero(), 0.1 * L);
  s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), Vec2::UnitY()});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81) * L / (T * T)));
  s.scene.collision.type = test::collisionType(collision);
  s.scene.collision.cor = 1.0;
  if (collision == "penalty" || collision == "hybrid")
    s.scene.forces.push_back(std::make_unique<PenaltyForce>(k * M / (T * T), thickness * L));
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = 0.01 * T;
  return s;
}

/// Two disks of radius 0.1 tied by a spring (rest length 0.1, so it pulls them together) whose
/// centres are 0.25 apart, inside a penalty layer of thickness 0.1 and stiffness k that pushes
/// them apart: the tracker's "two disks tied by a spring inside a stiff penalty layer".
TestScene springInPenaltyLayer(const std::string& integrator, double k, double L = 1, double M = 1, double T = 1) {
  TestScene s;
  addBody(s, 1.0 * M, Vec2(0, 0), Vec2::Zero(), 0.1 * L);
  addBody(s, 1.0 * M, Vec2(0.25, 0) * L, Vec2::Zero(), 0.1 * L);
  s.scene.edges.push_back(Edge{0, 1, 0.02 * L});
  s.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 100.0 * M / (T * T), 0.1 * L, 0.0));
  s.scene.forces.push_back(std::make_unique<PenaltyForce>(k * M / (T * T), 0.1 * L));
  s.scene.collision.type = CollisionType::Penalty;
  s.scene.integrator = integrator;
  s.scene.dt = 0.01 * T;
  return s;
}

/// The step number a failure message starts with ("step 43 (t = ...): ..."), or -1.
long failedStep(const Status& status) {
  const std::string& m = status.message();
  return m.rfind("step ", 0) == 0 ? std::stol(m.substr(5)) : -1;
}

// The tracker's first case: a ball falls into a penalty layer of stiffness 1e200. It leaves at
// about 1e195 m/s; the watch stops the run in that step and says who, what and what to change.
TEST(EnergyWatch, AbsurdlyStiffPenaltyContactStopsTheRun) {
  TestScene s = droppedBall("penalty", 1e200, 0.01);
  const RunEnd end = runFor(s, 200);
  ASSERT_FALSE(end.status.isOk());
  const std::string& m = end.status.message();
  EXPECT_EQ(failedStep(end.status), end.steps + 1) << m;  // the failing step, and nothing after it
  EXPECT_LT(end.steps, 60) << m;                          // it reaches the floor at t ~ 0.43
  EXPECT_LT(end.topSpeed, 10.0) << "no completed step carries the blow-up on";
  for (const char* part : {"energy blow-up", "particle 0 is fastest", "'collision penalty'", "k = 1e+200",
                           "smaller time step (dt = 0.01)", "smaller stiffness k", "sqrt(m/k) = 1e-100"})
    EXPECT_TRUE(contains(m, part)) << "missing \"" << part << "\" in: " << m;
}

// The largest stiffness a double holds: the penalty layer throws the ball off at about 6e304
// m/s, whose kinetic energy overflows. The watch's own limit (1e3 times the energy scale)
// overflowed too, and inf <= inf let the run go on with an infinite energy and exit 0.
TEST(EnergyWatch, AStiffnessWhoseBlowUpOverflowsEverythingStillStopsTheRun) {
  TestScene s = droppedBall("penalty", 1e308, 0.01);
  s.state.x[1] = 0.05;  // resting 0.05 deep in the floor's layer from the start
  const RunEnd end = runFor(s, 10);
  ASSERT_FALSE(end.status.isOk());
  EXPECT_EQ(end.steps, 0) << end.status.message();
  EXPECT_TRUE(contains(end.status.message(), "energy blow-up")) << end.status.message();
}

// A scene whose energy cannot be represented at its start: a speed of 1e158 m/s (m |v|^2 / 2
// overflows). Without a finite baseline nothing could tell a blow-up from the start; the ball
// stopped dead on the floor instead of bouncing, exit 0. The first step fails, naming it.
TEST(EnergyWatch, AStartWhoseEnergyOverflowsIsRefusedNamingTheParticle) {
  for (const char* collision : {"continuous-time", "hybrid", "none"}) {
    SCOPED_TRACE(collision);
    TestScene s = droppedBall(collision, 100.0, 0.01);
    s.state.v[1] = -1e158;
    const RunEnd end = runFor(s, 10);
    ASSERT_FALSE(end.status.isOk());
    EXPECT_EQ(end.steps, 0);
    for (const char* part : {"energy at the start is not finite", "particle 0", "speed 1e+158"})
      EXPECT_TRUE(contains(end.status.message(), part)) << "missing \"" << part << "\" in: " << end.status.message();
  }
}

// The start's other two ways to overflow: a force's potential alone (a spring of k = 1e300
// stretched by 1e6 m: k d^2 / 2 ~ 5e311), and a sum of finite terms (three kinetic energies of
// 8.45e307 each: m v^2 / 2 with m = 1, v = 1.3e154, v^2 finite). Each is named for what overflowed.
TEST(EnergyWatch, AStartWhosePotentialOrEnergySumOverflowsIsRefusedSayingWhich) {
  TestScene stretched = testing::spring("symplectic-euler", 0.01, 1e300, 1e6);
  RunEnd end = runFor(stretched, 10);
  ASSERT_FALSE(end.status.isOk());
  EXPECT_EQ(end.steps, 0);
  for (const char* part : {"energy at the start is not finite", "the potential of 'springforce' #1 is inf",
                           "choose smaller units"})
    EXPECT_TRUE(contains(end.status.message(), part)) << "missing \"" << part << "\" in: " << end.status.message();

  TestScene fast = testing::spring("symplectic-euler", 0.01, 1.0);
  fast.state.v[0] = 1.3e154;
  fast.state.v[2] = -1.3e154;
  addBody(fast, 1.0, Vec2(5, 0), Vec2(0, 1.3e154));
  ASSERT_TRUE(std::isfinite(1.3e154 * 1.3e154));  // each term, v^2 included, is finite
  ASSERT_FALSE(std::isfinite(3 * (0.5 * 1.3e154 * 1.3e154)));
  end = runFor(fast, 10);
  ASSERT_FALSE(end.status.isOk());
  EXPECT_EQ(end.steps, 0);
  EXPECT_TRUE(contains(end.status.message(), "the sum of the kinetic and potential energies overflows (inf)"))
      << end.status.message();
  EXPECT_FALSE(contains(end.status.message(), "particle 0")) << end.status.message();
}

// The tracker's second case: two disks tied by a spring inside a stiff penalty layer. Left alone
// they reach thousands of m/s (the tracker saw 1,650); watched, they stop well before.
TEST(EnergyWatch, SpringPairInsideAStiffPenaltyLayerIsCaught) {
  for (const auto& [integrator, k] : {std::pair{"symplectic-euler", 1e6}, std::pair{"explicit-euler", 1e4}}) {
    SCOPED_TRACE(integrator);
    TestScene unwatched = springInPenaltyLayer(integrator, k);
    const RunEnd free = runFor(unwatched, 2000, /*watch=*/false);
    ASSERT_TRUE(free.status.isOk()) << free.status.message();
    EXPECT_GT(free.topSpeed, 1650.0);

    TestScene watched = springInPenaltyLayer(integrator, k);
    const RunEnd end = runFor(watched, 2000);
    ASSERT_FALSE(end.status.isOk());
    const std::string& m = end.status.message();
    EXPECT_EQ(failedStep(end.status), end.steps + 1) << m;
    EXPECT_LT(end.topSpeed, 1650.0) << m;
    EXPECT_GT(end.growth, EnergyWatch::kBlowUpGrowth) << m;
    EXPECT_TRUE(contains(m, "energy blow-up")) << m;
    EXPECT_TRUE(contains(m, " is fastest, at speed ")) << m;
    // The advice: with symplectic Euler the stiff penalty layer is at fault (even when the soft
    // spring takes up the energy in the failing step); explicit Euler is unstable on any spring.
    if (k == 1e6) {
      EXPECT_TRUE(contains(m, "the stiffest force is 'collision penalty' #1 (k = 1e+06)")) << m;
      EXPECT_TRUE(contains(m, "smaller stiffness k: steps resolve k = 1e+06")) << m;
    } else {
      EXPECT_TRUE(contains(m, "'springforce' #1 (k = 100)")) << m;
      EXPECT_TRUE(contains(m, "explicit Euler gains energy on every oscillation")) << m;
    }
  }
}

/// The "'springforce' #N" a message names, or "" when it names none.
std::string namedSpring(const std::string& message) {
  const size_t at = message.find("'springforce' #");
  if (at == std::string::npos) return "";
  size_t end = at + 15;
  while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
  return message.substr(at, end - at);
}

// The energy watch and the step's non-finite check name forces alike. Two springs, each on its
// own pair of particles: the first at rest, the second stiff and stretched, which explicit Euler
// blows up. Watched, the run stops on the energy; unwatched, it runs on until the state is
// non-finite. Both messages blame the second <springforce> of the scene, counted from 1.
TEST(EnergyWatch, NamesTheForceAsTheNonFiniteCheckDoes) {
  auto twoSprings = [] {
    TestScene s;
    addBody(s, 1, Vec2(0, 0), Vec2::Zero());
    addBody(s, 1, Vec2(1, 0), Vec2::Zero());
    addBody(s, 1, Vec2(0, 5), Vec2::Zero());
    addBody(s, 1, Vec2(1.5, 5), Vec2::Zero());
    s.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 1.0, 1.0, 0.0));
    s.scene.forces.push_back(std::make_unique<SpringForce>(2, 3, 1e6, 1.0, 0.0));
    s.scene.integrator = "explicit-euler";
    s.scene.dt = 0.01;
    return s;
  };
  TestScene watched = twoSprings();
  const RunEnd energy = runFor(watched, 2000);
  ASSERT_FALSE(energy.status.isOk());
  EXPECT_TRUE(contains(energy.status.message(), "energy blow-up")) << energy.status.message();

  TestScene unwatched = twoSprings();
  const RunEnd nonFinite = runFor(unwatched, 2000, /*watch=*/false);
  ASSERT_FALSE(nonFinite.status.isOk());
  EXPECT_TRUE(contains(nonFinite.status.message(), "non-finite")) << nonFinite.status.message();
  EXPECT_GT(nonFinite.steps, energy.steps);

  EXPECT_EQ(namedSpring(energy.status.message()), "'springforce' #2") << energy.status.message();
  EXPECT_EQ(namedSpring(nonFinite.status.message()), "'springforce' #2") << nonFinite.status.message();
}

// Honest scenes: energy kept up to the integrator's error. Their growth stays far below the mark
// (about the scene's energy scale at most), not merely below it.
// An elastic ball under gravity with continuous-time or hybrid handling gains about m g^2 dt / 2
// per unit of time for ever (the response reflects a velocity that took a full step of gravity):
// its energy grows linearly in time, without bound. That drift is allowed for (linear in the
// steps, where a blow-up is exponential); it must not read as a blow-up.
TEST(EnergyWatch, ElasticBouncingBallRunsForLong) {
  for (const char* collision : {"hybrid", "continuous-time"})
    for (double height : {1.0, 0.01}) {
      SCOPED_TRACE(std::string(collision) + " from " + std::to_string(height));
      TestScene s = droppedBall(collision, 10, 0.1);  // the hybrid's default penalty layer
      s.state.x[1] = 0.1 + height;
      const RunEnd end = runFor(s, 30000);
      EXPECT_TRUE(end.status.isOk()) << end.status.message();
      EXPECT_LT(end.growth, 1.5);
    }
}

TEST(EnergyWatch, SymplecticSpringRunsForLong) {
  TestScene s = testing::spring("symplectic-euler", 0.01, 100.0);
  const RunEnd end = runFor(s, 20000);
  EXPECT_TRUE(end.status.isOk()) << end.status.message();
  EXPECT_LT(end.growth, 0.1);
}

// Explicit Euler gains m g^2 dt^2 / 2 in the first step of a fall from rest, before any
// potential is released; over 100 s (49 km) the gain stays a sliver of what gravity released.
TEST(EnergyWatch, LongFreeFallFromAGreatHeightRuns) {
  for (const char* integrator : {"explicit-euler", "symplectic-euler"}) {
    SCOPED_TRACE(integrator);
    TestScene s = testing::projectile(integrator, 0.01, Vec2::Zero(), Vec2(0, -9.81));
    s.state.x = Vec2(0, 5e4);
    const RunEnd end = runFor(s, 10000);
    EXPECT_TRUE(end.status.isOk()) << end.status.message();
    EXPECT_LE(end.growth, 1.0);
  }
}

// Gravity's potential -m g.x depends on where the origin is; the verdict must not.
TEST(EnergyWatch, SceneFarFromTheOriginRuns) {
  const Vec2 far(3e6, -7e6);
  for (const char* collision : {"hybrid", "penalty"}) {
    SCOPED_TRACE(collision);
    TestScene near = droppedBall(collision, 1e4, 0.01), away = droppedBall(collision, 1e4, 0.01);
    away.state.x += far;
    away.scene.halfplanes[0].point += far;
    const RunEnd a = runFor(near, 1000), b = runFor(away, 1000);
    EXPECT_TRUE(a.status.isOk()) << a.status.message();
    EXPECT_TRUE(b.status.isOk()) << b.status.message();
    EXPECT_LT(b.growth, 1.0);
    EXPECT_NEAR(b.growth, a.growth, 0.05);
  }
}

// Scaling length, mass and time (by powers of two, so that the arithmetic stays exact) changes
// every energy by the same factor: the same verdict at the same step, the same growth.
TEST(EnergyWatch, UnitsDoNotChangeTheVerdict) {
  const double L = 32, M = 0.125, T = 0.25;
  TestScene pair = springInPenaltyLayer("symplectic-euler", 1e6),
            scaledPair = springInPenaltyLayer("symplectic-euler", 1e6, L, M, T);
  const RunEnd a = runFor(pair, 2000), b = runFor(scaledPair, 2000);
  EXPECT_FALSE(a.status.isOk());
  EXPECT_FALSE(b.status.isOk());
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_NEAR(b.growth / a.growth, 1.0, 1e-9);

  TestScene ball = droppedBall("penalty", 1e4, 0.01), scaledBall = droppedBall("penalty", 1e4, 0.01, L, M, T);
  const RunEnd c = runFor(ball, 1000), d = runFor(scaledBall, 1000);
  EXPECT_TRUE(c.status.isOk()) << c.status.message();
  EXPECT_TRUE(d.status.isOk()) << d.status.message();
  EXPECT_NEAR(d.growth, c.growth, 1e-9 * std::max(1.0, c.growth));
}

// Where energy may grow honestly the watch stays off; and a caller can turn it off.
TEST(EnergyWatch, OffWhereOutsideWorkIsPossibleOrWhenAsked) {
  auto activeFor = [](TestScene& s) {
    EnergyWatch watch;
    State end = s.state;
    end.step = 1;
    EXPECT_TRUE(watch.check(s.scene, s.state, end).isOk());
    return watch.active();
  };
  TestScene vortex = testing::spring("symplectic-euler", 0.01, 1.0);
  vortex.scene.forces.push_back(std::make_unique<VortexForce>(0, 1, 1.0, 1.0));
  EXPECT_FALSE(activeFor(vortex)) << "the vortex force does work without a potential";

  TestScene driven = testing::spring("symplectic-euler", 0.01, 1.0);
  driven.scene.fixed[0] = 1;
  at(driven.state.v, 0) = Vec2(1, 0);
  EXPECT_FALSE(activeFor(driven)) << "a fixed particle with a velocity drives the spring";

  TestScene damped = testing::spring("symplectic-euler", 0.01, 1.0);
  damped.scene.forces.push_back(std::make_unique<DragDampingForce>(0.5));
  damped.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 1.0, 1.0, 0.3));
  EXPECT_TRUE(activeFor(damped)) << "drag and spring damping only remove energy";

  TestScene pair = springInPenaltyLayer("symplectic-euler", 1e6);
  const RunEnd end = runFor(pair, 2000, /*watch=*/false);
  EXPECT_TRUE(end.status.isOk()) << end.status.message();
  EXPECT_EQ(end.steps, 2000);
}

}  // namespace
}  // namespace fosssim
