// Sleepers that the failsafe's zones run into (src/core/collision/zone_stops.cpp,
// ContactZones::wakeHitSleepers). A sleeper is an obstacle to a zone, as a fixed particle is; a
// zone that pushes one harder than resting contact does wakes it, and the zone is solved again
// with it as a member: a hit that travels through a sleeping row ends as it does with sleeping off
// (momentum kept, the row woken). That a resting load does not wake what it rests on is measured
// on piles: the benchmark's pile-rest, whose share at rest tests/bench/pile_scenes_test.cpp checks.
#include "../../src/core/collision/sleepers.h"
#include "contact_physics.h"

namespace fosssim::testing {
namespace {

constexpr double kG = 9.81;
constexpr double kR = 0.05;

/// `count` disks of 1 kg touching in a row on a frictionless floor (x = 1, 1 + 2r, ...), and a
/// striker of mass `strikerMass` sliding at `speed` towards the row's first disk from far enough
/// away that it arrives after the row has slept (about step 2 kStepsToSleep at dt 0.01).
TestScene sleepingRow(const char* type, int count, double strikerMass, double speed) {
  TestScene s = contactScene(type, 0.0);
  addFloorAndGravity(s, kG);
  for (int k = 0; k < count; ++k) addBody(s, 1.0, Vec2(1.0 + 2 * kR * k, kR), Vec2::Zero(), kR);
  const double gap = speed * 2 * kStepsToSleep * s.scene.dt;
  addBody(s, strikerMass, Vec2(1.0 - 2 * kR - gap, kR), Vec2(speed, 0), kR);
  return s;
}

// A row of touching sleepers hit end-on at COR 0. The reference answer is independent of any
// sleeping: a perfectly inelastic collision in one dimension leaves every body of a touching row
// with the common velocity P / M, and the same scene run with sleeping off must get it. Until
// zones woke what they hit, the zone that the hit's events handed over to (kEventsPerInstant)
// stopped against the first sleeper the events had not reached: the striker and the woken disks
// ended at rest, momentum 10 -> 0 for five disks hit at 10 m/s, and the rest of the row slept on.
TEST(SleepZones, ARowOfSleepersHitEndOnMovesOffTogetherAsWithSleepingOff) {
  struct Case {
    int count;
    double strikerMass, speed;
  };
  const Case cases[] = {{4, 1.0, 2.0}, {5, 1.0, 10.0}, {8, 1.0, 100.0}, {12, 1.0, 2.0}, {10, 1000.0, 30.0}};
  for (const char* type : kEventTypes) {
    for (const Case& c : cases) {
      SCOPED_TRACE(std::string(type) + ", " + std::to_string(c.count) + " disks at " + std::to_string(c.speed) +
                   " m/s, striker " + std::to_string(c.strikerMass) + " kg");
      TestScene on = sleepingRow(type, c.count, c.strikerMass, c.speed);
      TestScene off = sleepingRow(type, c.count, c.strikerMass, c.speed);
      auto sleeping = defaultModeSimulator(on, true), awake = defaultModeSimulator(off, false);
      const double p = c.strikerMass * c.speed, common = p / (c.count + c.strikerMass);
      bool slept = false;
      for (int k = 0; k < 3 * kStepsToSleep; ++k) {
        ASSERT_TRUE(stepClean(*sleeping, on));
        ASSERT_TRUE(stepClean(*awake, off));
        slept = slept || sleeping->stats().asleep == c.count;
      }
      ASSERT_TRUE(slept) << "the row never slept before the hit";
      ASSERT_GT(at(on.state.v, 0).x(), 0.0) << "the striker had not arrived";
      EXPECT_EQ(sleeping->stats().asleep, 0) << "part of the row slept through the hit";
      EXPECT_NEAR(momentum(on).x(), p, 1e-9 * p);
      // The zones' solves settle to a tolerance and may end on their budgets, differently with
      // and without sleepers: velocities agree to that (the run with sleeping off is 3e-4 of the
      // speed from the common velocity with the heavy striker), momentum to rounding.
      for (int d = 0; d <= c.count; ++d) {
        EXPECT_NEAR(at(on.state.v, d).x(), common, 1e-3 * c.speed) << "disk " << d;
        EXPECT_NEAR(at(on.state.v, d).x(), at(off.state.v, d).x(), 1e-3 * c.speed) << "disk " << d;
      }
    }
  }
}

}  // namespace
}  // namespace fosssim::testing
