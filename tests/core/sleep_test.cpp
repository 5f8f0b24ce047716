// Resting particles sleep in the default mode (src/core/collision/sleepers.h). The promises here:
// a sleeper does not move; nothing sleeps that moves, however slowly, or that a spring holds;
// ties make islands that sleep together; and a run in which nothing sleeps is the same, bit for
// bit, with sleeping on or off, and for any thread count. What wakes a sleeper:
// sleep_wake_test.cpp.
#include "../../src/core/collision/sleepers.h"
#include "sleep_scenes.h"

#include "fosssim/core/forces.h"

namespace fosssim::testing {
namespace {

TEST(Sleep, RestingDiskSleepsAfterItsStillStepsAndThenDoesNotMoveAtAll) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = floorScene(type, {{0.0, 0.0}});
    auto sim = defaultModeSimulator(s, true);
    // Gravity closes the contact in every step and the response stops it: still from the first
    // step, so it falls asleep at the end of step kStepsToSleep, not before.
    for (int k = 1; k < kStepsToSleep; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_EQ(sim->stats().asleep, 0) << "step " << k;
    }
    ASSERT_TRUE(stepClean(*sim, s));
    ASSERT_EQ(sim->stats().asleep, 1);
    const VecX rest = s.state.x;
    for (int k = 0; k < 100; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_EQ(s.state.x, rest) << "a sleeper moved";
      ASSERT_EQ(s.state.v, VecX::Zero(2)) << "a sleeper has a velocity";
    }
  }
}

// Without forces nothing may take up a velocity, so only a particle exactly at rest sleeps: one
// drifting at 0.01 m/s with dt 10^-4 moves 10^-6 m a step and 6 10^-5 m in kStepsToSleep steps,
// both within the sleep distance (3 10^-3 r = 3 10^-4 m), and slept at step 60 with its
// velocity dropped before a sleeper's speed had to be within kWakeKickFactor kicks (here 0).
TEST(Sleep, ADiskDriftingWithoutForcesNeverSleepsAtASmallStep) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 1.0, 1e-4);
    addBody(s, 1.0, Vec2::Zero(), Vec2(0.01, 0.0), kR);
    auto sim = defaultModeSimulator(s, true);
    for (int k = 1; k <= 3 * kStepsToSleep; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_EQ(sim->stats().asleep, 0) << "step " << k;
    }
    EXPECT_EQ(at(s.state.v, 0), Vec2(0.01, 0.0));
  }
}

TEST(Sleep, ADiskSlidingSlowerThanTheSleepSpeedStillNeverSleeps) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    const double h = 0.01, speed = 0.5 * kSleepFraction * kR / h;  // half the per-step threshold
    TestScene s = floorScene(type, {{0.0, speed}});
    auto sim = defaultModeSimulator(s, true);
    for (int k = 0; k < 3 * kStepsToSleep; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_EQ(sim->stats().asleep, 0) << "step " << k + 1;
    }
    EXPECT_NEAR(at(s.state.x, 0).x(), speed * 3 * kStepsToSleep * h, 1e-12);
  }
}

// A ball of radius 1 thrown up at 0.5 m/s with dt 5e-4: around the top of its flight it moves
// at most 30 g h^2 = 7e-5 m per step and g (30 h)^2 / 2 = 1.1e-3 m in all over the kStepsToSleep
// = 30 steps after it, both within the sleep distance (3e-3 m), so stillness alone would put it
// to sleep in mid-air. Its velocity changes by every kick of gravity, though (it is not
// supported), so it flies on: the symplectic Euler parabola y_k = k h v0 - g h^2 k (k + 1) / 2,
// exactly.
TEST(Sleep, ABallAtTheTopOfItsFlightDoesNotSleep) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    const double h = 5e-4, v0 = 0.5, r = 1.0;
    TestScene s = contactScene(type, 0.0, h);
    s.scene.halfplanes.push_back(HalfPlane{Vec2(0, -100), Vec2(0, 1)});
    s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -kG)));
    addBody(s, 1.0, Vec2(0, 0), Vec2(0, v0), r);
    auto sim = defaultModeSimulator(s, true);
    const int steps = 400;  // the top at step 102
    for (int k = 1; k <= steps; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_EQ(sim->stats().asleep, 0) << "step " << k;
    }
    const double k = steps;
    EXPECT_NEAR(at(s.state.x, 0).y(), k * h * v0 - kG * h * h * k * (k + 1) / 2, 1e-12);
  }
}

// Particles tied by a spring or an edge are one island: they sleep only together (the count of
// sleepers goes from 0 to 2 in one step, never through 1), and not while one of them moves, even
// when the tie pulls with no force at all (k = 0): disk 0 is perfectly still but its mate slides.
TEST(Sleep, ParticlesHeldBySpringsOrEdgesSleepOnlyTogether) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene spring = springPair(type);
    TestScene edge = floorScene(type, {{0.0, 0.0}, {0.5, 0.0}});
    edge.scene.edges.push_back(Edge{0, 1, 0.02});
    for (TestScene* s : {&spring, &edge}) {
      auto sim = defaultModeSimulator(*s, true);
      int fellAt = -1;
      for (int k = 1; k <= 3 * kStepsToSleep; ++k) {
        ASSERT_TRUE(stepClean(*sim, *s));
        ASSERT_NE(sim->stats().asleep, 1) << "step " << k << ": half an island asleep";
        if (sim->stats().asleep == 2 && fellAt < 0) fellAt = k;
      }
      EXPECT_EQ(fellAt, kStepsToSleep) << "the island should sleep when both have been still for its steps";
    }
    TestScene sliding = springPair(type, {}, /*k=*/0.0, /*vx1=*/1.0);
    auto sim = defaultModeSimulator(sliding, true);
    for (int k = 1; k <= 3 * kStepsToSleep; ++k) {
      ASSERT_TRUE(stepClean(*sim, sliding));
      ASSERT_EQ(sim->stats().asleep, 0) << "step " << k << ": disk 0 slept while its mate slides";
    }
    EXPECT_EQ(at(sliding.state.x, 0), Vec2(0.0, kR));
  }
}
TEST(Sleep, ARunInWhichNothingSleepsIsTheSameBitForBitWithSleepingOff) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    // Elastic disks bouncing on the floor and off each other never stay still.
    TestScene a = floorScene(type, {{0.0, 0.3}, {0.5, -0.2}, {1.0, 0.0}}, 1.0);
    for (int i = 0; i < 3; ++i) at(a.state.x, i).y() += 0.3 * (i + 1);
    TestScene b = floorScene(type, {{0.0, 0.3}, {0.5, -0.2}, {1.0, 0.0}}, 1.0);
    b.state = a.state;
    auto on = defaultModeSimulator(a, true), off = defaultModeSimulator(b, false);
    for (int k = 0; k < 500; ++k) {
      ASSERT_TRUE(stepClean(*on, a));
      ASSERT_TRUE(stepClean(*off, b));
      ASSERT_EQ(on->stats().asleep, 0);
      ASSERT_EQ(a.state.x, b.state.x) << "step " << k + 1;
      ASSERT_EQ(a.state.v, b.state.v) << "step " << k + 1;
    }
  }
}

// Sleeping's per-particle passes run on the handler's threads: a row of 4,200 disks (enough to
// be split) resting on the floor, half of them sliding slowly (never asleep), gives the same
// bits and the same sleepers on 1 and 2 threads, and the resting half does fall asleep.
TEST(Sleep, ThreadCountDoesNotChangeWhoSleeps) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    std::vector<std::pair<double, double>> disks;
    for (int k = 0; k < 4200; ++k) disks.emplace_back(3 * kR * k, k % 2 ? 0.01 : 0.0);
    std::vector<TestScene> scenes;
    std::vector<std::unique_ptr<Simulator>> sims;
    for (int threads = 1; threads <= 2; ++threads) {
      scenes.push_back(floorScene(type, disks));
      SimulatorOptions options;
      options.handler.compat = false;
      options.handler.threads = threads;
      std::unique_ptr<Simulator> sim;
      ASSERT_TRUE(Simulator::create(scenes.back().scene, options, sim).isOk());
      sims.push_back(std::move(sim));
    }
    for (int k = 0; k < kStepsToSleep + 5; ++k) {
      for (size_t m = 0; m < sims.size(); ++m) ASSERT_TRUE(sims[m]->step(scenes[m].scene, scenes[m].state).isOk());
      for (size_t m = 1; m < sims.size(); ++m) {
        ASSERT_EQ(scenes[m].state.x, scenes[0].state.x) << "step " << k + 1;
        ASSERT_EQ(scenes[m].state.v, scenes[0].state.v) << "step " << k + 1;
        ASSERT_EQ(sims[m]->stats().asleep, sims[0]->stats().asleep) << "step " << k + 1;
      }
    }
    EXPECT_EQ(sims[0]->stats().asleep, 2100);
  }
}

}  // namespace
}  // namespace fosssim::testing
