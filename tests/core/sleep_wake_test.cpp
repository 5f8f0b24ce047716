// What wakes a sleeper in the default mode (src/core/collision/sleepers.h), in the step it
// happens: a contact that hits it (it then takes its speed; an island wakes whole), its support
// knocked away, a velocity given between steps (also to an island's member); and what does not:
// a mover that leaves it behind, whatever the broad phase's candidates. Last, two cases an audit
// of the default mode found wanting: a support creeping away from under a sleeper, and a slow hit
// across gravity, each run with sleeping on and off (the sleeper must do what the awake run does).
#include "../../src/core/collision/sleepers.h"
#include "sleep_scenes.h"

#include <cmath>

namespace fosssim::testing {
namespace {

TEST(Sleep, ADiskHittingASleeperWakesItInTheSameStepAndGivesItsSpeed) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    // Disk 1 slides along the frictionless floor at 1 m/s into disk 0, which has long been asleep
    // when it arrives (2.805 s later, in mid-step). Equal masses, COR 0, central impact: both go on at 0.5 m/s
    // (momentum kept, relative normal velocity zero).
    TestScene s = floorScene(type, {{0.0, 0.0}, {-3.005, 1.0}});
    auto sim = defaultModeSimulator(s, true);
    bool hit = false;
    for (int k = 0; k < 400 && !hit; ++k) {
      const bool asleepBefore = sim->stats().asleep == 1;
      ASSERT_TRUE(stepClean(*sim, s));
      if (at(s.state.v, 0).x() > 0.25) {
        hit = true;
        EXPECT_TRUE(asleepBefore) << "disk 0 should have been asleep when it was hit";
        EXPECT_GE(sim->stats().woken, 1);
      }
    }
    ASSERT_TRUE(hit) << "disk 0 never moved";
    EXPECT_NEAR(at(s.state.v, 0).x(), 0.5, 1e-9);
    EXPECT_NEAR(at(s.state.v, 1).x(), 0.5, 1e-9);
    // And it goes on: 50 steps later disk 0 is 0.25 m further (frictionless floor).
    const double x0 = at(s.state.x, 0).x();
    for (int k = 0; k < 50; ++k) ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_NEAR(at(s.state.x, 0).x() - x0, 0.25, 1e-9);
  }
}

/// A Newton's cradle without gravity (scene s: COR 1): equal disks of radius r at rest at (x, 0)
/// for each x of `rest` (descending), and one more starting `shortBy` m short of touching the last
/// of them, moving at `speed` toward them (by default 0.401 m at 0.5 m/s: with dt 0.01 it arrives
/// 0.2 into step 81, long after the others fell asleep at step kStepsToSleep). Runs `steps`
/// steps; returns the most disks asleep at once.
int runCradleIntoSleepers(TestScene& s, const std::vector<double>& rest, double r, double speed = 0.5,
                          double shortBy = 0.401, int steps = 90) {
  for (double x : rest) addBody(s, 1.0, Vec2(x, 0.0), Vec2::Zero(), r);
  addBody(s, 1.0, Vec2(rest.back() - 2 * r - shortBy, 0.0), Vec2(speed, 0.0), r);
  auto sim = defaultModeSimulator(s, true);
  int asleepMost = 0;
  for (int k = 0; k < steps; ++k) {
    if (const auto clean = stepClean(*sim, s); !clean) {
      ADD_FAILURE() << "step " << k << ": " << clean.message();
      return -1;
    }
    asleepMost = std::max(asleepMost, sim->stats().asleep);
  }
  return asleepMost;
}

/// After a cradle's hit (COR 1, equal disks): the far disk (0) leaves at `speed`, the rest stop.
void expectOnlyTheFarDiskMoves(const TestScene& s, double speed) {
  EXPECT_NEAR(at(s.state.v, 0).x(), speed, 1e-12);
  for (int k = 1; k < s.scene.numParticles(); ++k) EXPECT_NEAR(at(s.state.v, k).norm(), 0.0, 1e-12) << "disk " << k;
}

TEST(Sleep, ASleeperHitByADiskThatWasStillWakesAtTheImpact) {
  // A Newton's cradle without gravity (COR 1, equal masses, on the x axis): disks 0 and 1 rest
  // 1 mm apart and fall asleep at step kStepsToSleep; disk 2 arrives at 0.5 m/s and hits disk 1
  // 0.2 into step 81, which crosses the gap and hits disk 0 0.4 into it. Disk 1 was still in
  // step 80, so only the impact itself can wake disk 0 (a moving neighbour wakes sleepers at a
  // step's start). It closes at 0.5 m/s, 1,000 times disk 0's sleep speed (3 10^-3 r in 60
  // steps: 5 10^-4 m/s), and there are no forces: disk 0 must wake and take all the speed, disks
  // 1 and 2 stop.
  // (The wake rule once compared that speed in metres per step, 0.005, with the sleep speed in
  // m/s: disk 0 stayed asleep and disk 1 bounced off it as off a wall.)
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 1.0);
    EXPECT_EQ(runCradleIntoSleepers(s, {0.0, -2 * kR - 1e-3}, kR), 2)
        << "disks 0 and 1 should have slept before the hit";
    expectOnlyTheFarDiskMoves(s, 0.5);
  }
}

TEST(Sleep, AHitRunsThroughARowOfTouchingSleepersInTheSameStep) {
  // The same cradle with four touching sleepers (radius 1/8, centres 1/4 apart: exact in binary,
  // so they touch without overlapping). Only the first is within the moving disk's reach at the
  // step's start; each of the others is woken by its neighbour's impact within the step, as the
  // impulse runs along the row (COR 1, one contact after another): the far disk leaves at 0.5 m/s
  // and the rest stop, whatever the step.
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 1.0);
    EXPECT_EQ(runCradleIntoSleepers(s, {0.0, -0.25, -0.5, -0.75}, 0.125), 4)
        << "the row should have slept before the hit";
    expectOnlyTheFarDiskMoves(s, 0.5);
  }
}

TEST(Sleep, ASleeperWhoseSupportIsKnockedAwayFalls) {
  // Disk 2 sits on disk 0; both are asleep by the time disk 1 slides in at 2 m/s and knocks
  // disk 0 away (COR 0: both go on at 1 m/s).
  TestScene s = floorScene("hybrid", {{0.0, 0.0}, {-3.0, 2.0}});
  addBody(s, 1.0, Vec2(0.0, 3 * kR), Vec2::Zero(), kR);
  auto sim = defaultModeSimulator(s, true);
  int asleepMost = 0;
  for (int k = 0; k < 500; ++k) {
    ASSERT_TRUE(stepClean(*sim, s));
    asleepMost = std::max(asleepMost, sim->stats().asleep);
  }
  EXPECT_EQ(asleepMost, 2) << "the stack should have slept before the hit";
  // 3.6 s after the hit nothing is under disk 2's old place: it must have fallen to the floor.
  EXPECT_NEAR(at(s.state.x, 2).y(), kR, 1e-6) << "the top disk floats where its support was";
}

TEST(Sleep, ASleeperGivenAVelocityBetweenStepsWakesAndMoves) {
  // A script (Python's assignable velocities) or the grader may change the state between steps.
  TestScene s = floorScene("hybrid", {{0.0, 0.0}});
  auto sim = defaultModeSimulator(s, true);
  for (int k = 0; k < 2 * kStepsToSleep; ++k) ASSERT_TRUE(stepClean(*sim, s));
  ASSERT_EQ(sim->stats().asleep, 1);
  at(s.state.v, 0) = Vec2(1.0, 0.0);
  ASSERT_TRUE(stepClean(*sim, s));
  EXPECT_EQ(sim->stats().asleep, 0);
  EXPECT_NEAR(at(s.state.x, 0).x(), 0.01, 1e-12);  // one step of 0.01 s at 1 m/s on the floor
  EXPECT_NEAR(at(s.state.v, 0).x(), 1.0, 1e-12);
}

// A disk set moving between steps hits the sleeper in its way. Five disks rest apart, without
// forces or walls (so nothing else is hit first), at x = 0, 0.5, ..., 2, and fall asleep (exactly
// at rest), while a sixth flies away from them at 60 m/s (the scene's energy, against which the
// energy watch measures the kick given below); then disk 2 is given -60 m/s. It did not move in
// the last step, so it wakes no neighbour at the step's start: only the step's first detection
// can find its pair with disk 1, which it reaches 0.3 / 0.6 = 0.5 into the step. With most
// particles asleep (four of six) that detection reads rows from the particles that move
// (EventHandler::detectAll), and disk 1 has the lower index: the pair must come from disk 2's
// side. COR 0, equal masses: both go on at -30 m/s, and nothing overlaps (stepClean).
TEST(Sleep, ADiskSetMovingBetweenStepsHitsALowerNumberedSleeperInItsWay) {
  TestScene s = contactScene("hybrid", 0.0);
  for (int k = 0; k < 5; ++k) addBody(s, 1.0, Vec2(0.5 * k, 0.0), Vec2::Zero(), kR);
  addBody(s, 1.0, Vec2(0.0, 5.0), Vec2(0.0, 60.0), kR);
  auto sim = defaultModeSimulator(s, true);
  for (int k = 0; k < 2 * kStepsToSleep; ++k) ASSERT_TRUE(stepClean(*sim, s));
  ASSERT_EQ(sim->stats().asleep, 5);
  at(s.state.v, 2) = Vec2(-60.0, 0.0);
  ASSERT_TRUE(stepClean(*sim, s));
  EXPECT_NEAR(at(s.state.v, 1).x(), -30.0, 1e-9);
  EXPECT_NEAR(at(s.state.v, 2).x(), -30.0, 1e-9);
  for (int k : {0, 3, 4}) EXPECT_EQ(at(s.state.x, k), Vec2(0.5 * k, 0.0)) << "disk " << k << " is out of reach";
}

// The same for an island: whichever member a script moves, all of it wakes in that step (disk 0
// is the island's first member, disk 1 its last: both are tried), and the spring then pulls the
// other member along.
TEST(Sleep, AnIslandMemberGivenAVelocityBetweenStepsWakesTheIsland) {
  for (int moved : {0, 1}) {
    SCOPED_TRACE(moved);
    TestScene s = springPair("hybrid");
    auto sim = defaultModeSimulator(s, true);
    for (int k = 0; k < 2 * kStepsToSleep; ++k) ASSERT_TRUE(stepClean(*sim, s));
    ASSERT_EQ(sim->stats().asleep, 2);
    at(s.state.v, moved) = Vec2(1.0, 0.0);
    ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_EQ(sim->stats().asleep, 0);
    const Vec2 other = at(s.state.x, 1 - moved);
    for (int k = 0; k < 10; ++k) ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_NE(at(s.state.x, 1 - moved), other) << "the spring should pull the other disk along";
  }
}

// The same at a small step (dt 2 10^-4): two touching sleepers (radius 1/8, centres 1/4 apart)
// and a disk arriving at 1 m/s. The first sleeper is within the mover's reach and wakes at the
// step's start; the far one only by the impact, at 1 m/s. The sleep speed was the sleep distance
// per step over h, 3 10^-3 r / h = 1.9 m/s here: the far disk stayed asleep and its neighbour
// bounced back off it as off a wall. Measured over the still run (3 10^-3 r in kStepsToSleep
// steps: 0.031 m/s) the hit wakes it: it leaves at 1 m/s, the others stop (COR 1).
TEST(Sleep, AHitWakesASleeperAtASmallStepToo) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 1.0, 2e-4);
    // The mover arrives 0.5 into step 251.
    EXPECT_EQ(runCradleIntoSleepers(s, {0.0, -0.25}, 0.125, 1.0, 0.0501, 300), 2)
        << "both should have slept before the hit";
    expectOnlyTheFarDiskMoves(s, 1.0);
  }
}


// A disk sliding into a sleeping island wakes all of it in the same step: disk 2 (free) meets
// disk 0, whose spring mate, disk 1, is out of its reach; both wake at once (the count of sleepers
// drops from 2 to 0), and the pair then moves off together with what disk 2 gave it.
TEST(Sleep, ADiskHittingAnIslandWakesAllOfIt) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    // Disk 2 leaves after the island has slept: 0.6 m away at 0.5 m/s, it arrives near step 100.
    TestScene s = springPair(type, {{-2 * kR - 0.6, 0.5}});
    auto sim = defaultModeSimulator(s, true);
    int slept = 0, wokeAt = -1;
    for (int k = 1; k <= 200 && wokeAt < 0; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_NE(sim->stats().asleep, 1) << "step " << k << ": half an island asleep";
      if (sim->stats().asleep == 2) slept = k;
      else if (slept > 0) wokeAt = k;
    }
    ASSERT_GT(slept, 0) << "the island never slept";
    ASSERT_GT(wokeAt, 0) << "the island never woke";
    EXPECT_EQ(sim->stats().woken, 2);
    for (int k = 0; k < 20; ++k) ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_GT(at(s.state.x, 0).x(), 0.0) << "disk 0 should have been pushed";
    EXPECT_GT(at(s.state.x, 1).x(), 0.5) << "disk 1 should follow through the spring";
  }
}

// A mover near a sleeper wakes it only if their boxes over the step meet, as the broad phase
// finds them: a disk set down beside a sleeper, 0.05 apart, and leaving it at 10 m/s (0.1 a
// step: within a disk's reach of the sleeper at the step's start, but never nearer) leaves it
// asleep, with the broad phase and with every pair as candidates alike (the reach alone woke it
// with every pair and not with the broad phase, so the two runs parted). Disk 1 falls freely,
// far away, until it is set down: it moved in the last step.
TEST(Sleep, AMoverLeavingASleeperBehindDoesNotWakeItWhateverTheCandidates) {
  for (const char* type : kEventTypes) {
    for (bool allPairs : {false, true}) {
      SCOPED_TRACE(std::string(type) + (allPairs ? ", every pair" : ", broad phase"));
      TestScene s = floorScene(type, {{0.0, 0.0}});
      addBody(s, 1.0, Vec2(50.0, 1000.0), Vec2::Zero(), kR);
      SimulatorOptions options;
      options.handler.compat = false;
      options.handler.allPairs = allPairs;
      std::unique_ptr<Simulator> sim;
      ASSERT_TRUE(Simulator::create(s.scene, options, sim).isOk());
      for (int k = 0; k < 2 * kStepsToSleep; ++k) ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_EQ(sim->stats().asleep, 1);
      at(s.state.x, 1) = Vec2(2 * kR + 0.05, kR + 0.01);  // off the floor for the step
      at(s.state.v, 1) = Vec2(10.0, 0.0);
      ASSERT_TRUE(stepClean(*sim, s));
      EXPECT_EQ(sim->stats().woken, 0);
      EXPECT_EQ(sim->stats().asleep, 1);
      EXPECT_EQ(at(s.state.x, 0), Vec2(0.0, kR));
    }
  }
}

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
