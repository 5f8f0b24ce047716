// Resting contact does not bounce (EventHandler::respond, kRestingBounceKicks): in the default
// mode an impulse takes COR 0 when its contact closes no faster than twice the step's kicks along
// its normal. Why: symplectic Euler gives a ball on the floor the whole step's gravity, h g, at
// the step's start; at COR e it bounced e h g off the floor in every step and the next kick took
// it back, a cycle that never ended (the ball never slept, its kinetic energy never reached 0).
// What must not change: a contact that hits harder keeps the scene's COR, a kick across the
// normal (gravity, for disks side by side on a floor) does not count, and COR 1 stays elastic
// (sleep_test.cpp: elastic disks on the floor never sleep).
#include "contact_physics.h"

#include "fosssim/core/forces.h"

#include <cmath>

namespace fosssim::testing {
namespace {

constexpr double kG = 9.81;
constexpr double kR = 0.1;
constexpr double kH = 0.01;  // contactScene's step

TestScene floorScene(const std::string& type, double cor) {
  TestScene s = contactScene(type, cor, kH);
  addFloorAndGravity(s, kG);
  return s;
}

// Dropped from 0.5 m, the ball's first rebound leaves at e times its impact speed (3.13 m/s, far
// above the two kicks, 0.196 m/s, below which a contact rests); once its bounces fall below that
// it rests on the floor, exactly, and falls asleep. At COR 0.9 that takes some 27 bounces.
TEST(RestingContact, ABallDroppedOnTheFloorBouncesThenRestsAndSleepsAtAnyCorBelowOne) {
  for (const char* type : kEventTypes) {
    for (double cor : {0.3, 0.5, 0.9}) {
      SCOPED_TRACE(std::string(type) + " COR " + std::to_string(cor));
      TestScene s = floorScene(type, cor);
      const double drop = 0.5;
      addBody(s, 1.0, Vec2(0.0, kR + drop), Vec2::Zero(), kR);
      auto sim = defaultModeSimulator(s);
      const double impact = std::sqrt(2 * kG * drop);
      double rebound = 0.0;
      for (int k = 0; k < 1000; ++k) {
        ASSERT_TRUE(stepClean(*sim, s));
        rebound = std::max(rebound, at(s.state.v, 0).y());
      }
      // The impact speed is sqrt(2 g drop) to within a kick (the step's discrete fall).
      EXPECT_NEAR(rebound, cor * impact, cor * (kG * kH + 0.01 * impact));
      EXPECT_EQ(sim->stats().asleep, 1);
      EXPECT_EQ(at(s.state.v, 0), Vec2::Zero());
      EXPECT_NEAR(at(s.state.x, 0).y(), kR, 1e-12);
    }
  }
}

// The same on a shelf: a fixed edge (capsule radius 0.02 between two fixed particles) instead of
// the floor, with no floor at all. The edge's kick is its fixed ends' (0): the ball's own kick
// along the normal decides, and the ball, dropped 0.2 m onto it at COR 0.5, comes to rest on it.
TEST(RestingContact, ABallOnAFixedEdgeRestsToo) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 0.5, kH);
    s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -kG)));
    addBody(s, 1.0, Vec2(-1.0, 0.0), Vec2::Zero(), 0.02, /*fixed=*/true);
    addBody(s, 1.0, Vec2(1.0, 0.0), Vec2::Zero(), 0.02, /*fixed=*/true);
    s.scene.edges.push_back(Edge{0, 1, 0.02});
    addBody(s, 1.0, Vec2(0.1, kR + 0.02 + 0.2), Vec2::Zero(), kR);
    auto sim = defaultModeSimulator(s);
    for (int k = 0; k < 300; ++k) ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_EQ(sim->stats().asleep, 1);
    EXPECT_EQ(at(s.state.v, 2), Vec2::Zero());
    EXPECT_NEAR(at(s.state.x, 2).y(), kR + 0.02, 1e-12);
  }
}

// Two disks on the floor, one sliding at half a kick (0.05 m/s) into the other: gravity is
// across their normal, so their contact is not resting and keeps COR 0.5. Equal masses, 1D:
// they leave at (1 - e) v / 2 and (1 + e) v / 2.
TEST(RestingContact, AKickAcrossTheNormalDoesNotStopASlowBounce) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    const double cor = 0.5, v = 0.05;
    TestScene s = floorScene(type, cor);
    addBody(s, 1.0, Vec2(0.0, kR), Vec2(v, 0.0), kR);
    addBody(s, 1.0, Vec2(2 * kR + 0.001, kR), Vec2::Zero(), kR);
    auto sim = defaultModeSimulator(s);
    for (int k = 0; k < 5; ++k) ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_NEAR(at(s.state.v, 0).x(), (1 - cor) * v / 2, 1e-12);
    EXPECT_NEAR(at(s.state.v, 1).x(), (1 + cor) * v / 2, 1e-12);
  }
}

// Two disks falling together under gravity, the upper gaining on the lower at u, far below the
// two kicks (4 g h summed over both, 0.39 m/s): equal kicks do not close their contact, so it is a
// hit at the speed they had before the step, not a rest (ContactZones::resting). Equal masses,
// 1D: the closing speed comes back times e, and the centre of mass keeps falling freely.
TEST(RestingContact, TwoDisksFallingIntoEachOtherBounceAtAnySpeed) {
  for (const char* type : kEventTypes) {
    for (double u : {0.01, 0.1, 0.3}) {
      SCOPED_TRACE(std::string(type) + " u " + std::to_string(u));
      const double cor = 0.5;
      TestScene s = contactScene(type, cor, kH);
      s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -kG)));
      addBody(s, 1.0, Vec2(0.0, 0.0), Vec2::Zero(), kR);
      addBody(s, 1.0, Vec2(0.0, 2 * kR + 0.3 * u), Vec2(0.0, -u), kR);  // meets within 30 steps
      auto sim = defaultModeSimulator(s);
      for (int k = 0; k < 40; ++k) ASSERT_TRUE(stepClean(*sim, s));
      const double fall = -kG * kH * 40;  // symplectic Euler's free fall of the centre of mass
      EXPECT_NEAR(at(s.state.v, 1).y() - at(s.state.v, 0).y(), cor * u, 1e-12);
      EXPECT_NEAR(at(s.state.v, 1).y() + at(s.state.v, 0).y(), 2 * fall - u, 1e-12);
    }
  }
}

// What the start speeds must not undo: a column of three disks on the floor, the lower ones
// stopped by the floor's impulse in each step before the upper one's contact closes at its own
// kick. Each contact gained its closing in the step (none had any at its start): the column
// rests, exactly, and sleeps.
TEST(RestingContact, AColumnOnTheFloorRestsAndSleeps) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = floorScene(type, 0.5);
    for (int k = 0; k < 3; ++k) addBody(s, 1.0, Vec2(0.0, kR + 2 * kR * k + 0.01 * k), Vec2::Zero(), kR);
    auto sim = defaultModeSimulator(s);
    for (int k = 0; k < 300; ++k) ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_EQ(sim->stats().asleep, 3);
    for (int p = 0; p < 3; ++p) {
      EXPECT_EQ(at(s.state.v, p), Vec2::Zero()) << p;
      EXPECT_NEAR(at(s.state.x, p).y(), kR + 2 * kR * p, 1e-9) << p;
    }
  }
}

}  // namespace
}  // namespace fosssim::testing
