// What wakes a sleeper (src/core/collision/sleepers.h), found wanting by an audit of the default
// mode: a support creeping away from under a sleeper, and a slow hit across gravity. Each scene is
// run with sleeping on and off: the sleeper must do what the awake run does.
#include "../../src/core/collision/sleepers.h"
#include "contact_physics.h"

#include "fosssim/core/forces.h"

#include <cmath>

namespace fosssim::testing {
namespace {

// Disk B asleep on disk A, both r = 0.1 on a frictionless floor (COR 0, dt 0.01); a light disk
// (0.1 kg, r 0.05, 0.25 m/s) nudges A after both have slept, and A creeps out from under B at
// about 2.6 cm/s: 2.6e-4 m a step, under the sleep distance (3e-3 r = 3e-4 m), so every step of
// A's was still. Awake, B slides off A's flank and lands on the floor. Before, B stayed asleep
// at y = 0.3 for good (A's still runs broke only at their ends, and did not count as moving).
TEST(SleepWake, ASleeperWhoseSupportCreepsAwayFalls) {
  for (const char* type : kEventTypes)
    for (const bool sleep : {true, false}) {
      SCOPED_TRACE(std::string(type) + (sleep ? ", sleeping on" : ", sleeping off"));
      TestScene s = contactScene(type, 0.0);
      addFloorAndGravity(s);
      addBody(s, 1.0, Vec2(0, 0.1), Vec2::Zero(), 0.1);
      const int top = addBody(s, 1.0, Vec2(0, 0.3), Vec2::Zero(), 0.1);
      addBody(s, 0.1, Vec2(-0.25125, 0.05), Vec2(0.25, 0), 0.05);
      auto sim = defaultModeSimulator(s, sleep);
      int slept = 0;
      for (int k = 0; k < 1000; ++k) {
        ASSERT_TRUE(stepClean(*sim, s)) << "step " << k + 1;
        slept = std::max(slept, sim->stats().asleep);
      }
      if (sleep) {
        EXPECT_GE(slept, 2) << "A and B never slept: the scene tests nothing";
      }
      EXPECT_NEAR(s.state.x[2 * top + 1], 0.1, 1e-6) << "B is not on the floor";
    }
}

// A heavy disk slides along a frictionless floor into a light one asleep on it (r = 1, dt 0.01,
// gravity down, COR 0.5), slower than two kicks (2 g h = 0.196 m/s). Newton's law for the pair:
// u1' = (m1 u1 + m2 u2 - m2 e (u1 - u2)) / (m1 + m2), u2' = u1' + e (u1 - u2). The wake rule
// compared the closing speed with the whole kick, which is across this contact: the sleeper
// stayed, a wall, and the heavy disk bounced back at -e u1 (momentum 150 -> -75). Also through
// the zones (hybrid, maxiters 0), whose rule is the same.
TEST(SleepWake, ASlowHitAcrossTheKicksWakesTheSleeper) {
  struct Case {
    const char* type;
    int maxIterations;
    double heavy, u, r;
  };
  for (const Case c : {Case{"continuous-time", 10, 1000.0, 0.15, 1.0}, Case{"hybrid", 10, 1000.0, 0.15, 1.0},
                       Case{"hybrid", 0, 1000.0, 0.15, 1.0}, Case{"continuous-time", 10, 1.0, 0.01, 0.1}})
    for (const bool sleep : {true, false}) {
      SCOPED_TRACE(std::string(c.type) + " maxiters " + std::to_string(c.maxIterations) + ", mass " +
                   std::to_string(c.heavy) + (sleep ? ", sleeping on" : ", sleeping off"));
      const double e = 0.5, m2 = 1.0;
      TestScene s = contactScene(c.type, e, 0.01, Failsafe::Projection, c.maxIterations);
      addFloorAndGravity(s);
      const int rest = addBody(s, m2, Vec2(0, c.r), Vec2::Zero(), c.r);
      // Far enough that the light disk sleeps (kStepsToSleep) before the hit.
      const double gap = (kStepsToSleep + 10) * 0.01 * c.u;
      const int hitter = addBody(s, c.heavy, Vec2(-2 * c.r - gap, c.r), Vec2(c.u, 0), c.r);
      auto sim = defaultModeSimulator(s, sleep);
      bool sleptBeforeTheHit = false;
      for (int k = 0; k < 100; ++k) {
        ASSERT_TRUE(stepClean(*sim, s)) << "step " << k + 1;
        if (s.state.v[2 * rest] == 0.0 && sim->stats().asleep > 0) sleptBeforeTheHit = true;
      }
      if (sleep) {
        EXPECT_TRUE(sleptBeforeTheHit) << "the light disk never slept: the scene tests nothing";
      }
      const double u1 = (c.heavy * c.u - m2 * e * c.u) / (c.heavy + m2), u2 = u1 + e * c.u;
      EXPECT_NEAR(s.state.v[2 * hitter], u1, 1e-9 * c.u);
      EXPECT_NEAR(s.state.v[2 * rest], u2, 1e-9 * c.u);
    }
}

}  // namespace
}  // namespace fosssim::testing
