// The failsafe's budget on resting columns (src/core/collision/contact_zones.h): a solve that
// spends its budget is not a jam, and each step starts from the last step's whole impulses, so a
// column that a cold solve cannot settle within the jam limit jams in its first step only (these
// two with holding off, which would settle the column before any jam). Holding: a budget-ended
// solve stops the particles it has brought to rest, so the column rests without ever jamming,
// while a disk that slides faster than a quarter of its kick keeps its speed. The last resort: a
// zone that moved rigidly goes back to the projection when it meets an obstacle, never stopping
// whole. Expected values come from the Gauss-Seidel rate of the column's system (computed with
// NumPy), from the column being at rest (the same answer in every step), from the hold's stated
// bounds and from rigid motion and momentum (a frictionless floor takes no momentum along it).
#include "contact_physics.h"
#include "step_zones.h"

#include "fosssim/math/contact_projector.h"

namespace fosssim::testing {
namespace {

/// `disks` unit disks of radius 0.05 stacked exactly on the floor y = 0 under gravity, hybrid COR 0.
TestScene restingColumn(int disks) {
  TestScene s = contactScene("hybrid", 0.0);
  for (int k = 0; k < disks; ++k) addBody(s, 1.0, Vec2(0.0, 0.05 + 0.1 * k), Vec2::Zero(), 0.05);
  s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), Vec2(0, 1)});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  return s;
}

// 8c. A solve that runs out of its budget is not a jam. Five unit disks (radius 0.05) stacked
// exactly on a floor under gravity, hybrid COR 0, no sleep: each step the zone's answer is rest
// (v = 0), reached by Gauss-Seidel from a cold start in the first step. Its rows (floor-disk 0,
// then disk k-disk k+1) give the tridiagonal system [1 -1; -1 2 -1; ...; -1 2], whose Gauss-
// Seidel iteration contracts the error by rho = 0.9045 per sweep (the spectral radius of
// -L^-1 U, computed with NumPy), so reaching 1e-10 takes about ln(1e-10)/ln(rho) = 229 sweeps of
// 5 rows, some 1,150 updates. Starved to 30 updates per row, one solve may spend 30 x max(5, 8)
// = 240: the cold solve ends on its budget and its contacts come back, but the solves allowed
// before the jam limit (kMaxZoneProjections + 1 = 9, 2,160 updates) finish it. Counting each
// contact that comes back after a budget-ended solve as a jam reached the limit after one such
// solve and stopped the disks every step. With 10 updates per row (9 x 80 = 720 < 1,150) the
// column does jam: the control that the budget, not something else, decides. (Holding off: with
// it, a zone's first solve has a fifth of the budget and the column is held, 8e.)
TEST(ContactPhysics, BudgetEndedSolveIsNotAJam) {
  for (long perRow : {30L, 10L}) {
    SCOPED_TRACE("updates per row " + std::to_string(perRow));
    TestScene s = restingColumn(5);
    auto sim = defaultModeSimulator(s, /*sleep=*/false, perRow, /*hold=*/false);
    int jammed = 0, failsafeSteps = 0;
    for (int k = 0; k < 20; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      jammed += sim->stats().jammedParticles;
      failsafeSteps += sim->stats().failsafeUsed;
      for (int i = 0; i < 5; ++i) ASSERT_NEAR(s.state.x[2 * i + 1], 0.05 + 0.1 * i, 1e-9) << "disk " << i;
    }
    EXPECT_EQ(failsafeSteps, 20);  // the column rests in a zone in every step
    if (perRow == 30) EXPECT_EQ(jammed, 0);
    else EXPECT_GT(jammed, 0);
  }
}

// 8d. The warm start is each contact's whole impulse. Ten unit disks (radius 0.05) stacked on a
// floor, hybrid COR 0, the default budget, no sleep: from a cold start Gauss-Seidel needs some
// 9,300 updates on this chain (its 10-row system, as in 8c, contracts by rho = 0.9755 per sweep,
// computed with NumPy: 929 sweeps to 1e-10), more than the nine solves allowed before the jam
// limit may spend (9 x 100 x max(10, 8) = 9,000), so the first step jams (the control). At rest
// every step has the same answer, the last step's impulses: started from them the solve has
// nothing left to do and no later step may jam. Fails when a contact that came
// back in a step (its row replaced, multiplier restarted at 0) starts the next step from its last
// multiplier alone: the column then jammed in every one of the 100 steps.
TEST(ContactPhysics, RestingColumnStartsFromItsWholeImpulsesAndJamsOnlyOnce) {
  TestScene s = restingColumn(10);
  auto sim = defaultModeSimulator(s, /*sleep=*/false, 0, /*hold=*/false);
  for (int k = 1; k <= 100; ++k) {
    ASSERT_TRUE(stepClean(*sim, s));
    if (k == 1) EXPECT_GT(sim->stats().jammedParticles, 0) << "the cold first step should jam (the control)";
    else ASSERT_EQ(sim->stats().jammedParticles, 0) << "step " << k;
    for (int i = 0; i < 10; ++i)
      ASSERT_NEAR(s.state.x[2 * i + 1], 0.05 + 0.1 * i, 1e-9) << "disk " << i << ", step " << k;
  }
}

// 8e. Holding replaces the jam. The same ten-disk column with holding on (the default): its cold
// first solve cannot finish within its budget (above), and every disk started the step at rest
// and has been brought back within 0.9 of a kick of rest by then, so the disks are held: they stop for
// the rest of the step, the column rests exactly where it stands, and no contact ever has to
// come back until the jam limit. Without holding, the first step jams (8d's control).
TEST(ContactPhysics, ABudgetEndedSolveHoldsARestingColumnInsteadOfJamming) {
  TestScene s = restingColumn(10);
  auto sim = defaultModeSimulator(s, /*sleep=*/false);
  int held = 0;
  for (int k = 1; k <= 100; ++k) {
    ASSERT_TRUE(stepClean(*sim, s));
    ASSERT_EQ(sim->stats().jammedParticles, 0) << "step " << k;
    held += sim->stats().heldParticles;
    for (int i = 0; i < 10; ++i)
      ASSERT_NEAR(s.state.x[2 * i + 1], 0.05 + 0.1 * i, 1e-9) << "disk " << i << ", step " << k;
  }
  EXPECT_GT(held, 0);
}

// 8f. What holding may not touch. A disk slides along the floor away from the foot of the
// column, touching it, so it joins the column's zone, whose cold solve ends on its budget in
// step 1. The kick is g h = 0.0981 m/s. Sliding at 0.3 kicks (above kHeldStartFraction) it keeps
// its speed exactly: frictionless sliding is tangential to every row. At 0.2 kicks it is held
// (the stated price: it loses at most a kick of speed, here all of its 0.2): the control that
// the disk was in the held zone.
TEST(ContactPhysics, HoldingLeavesADiskSlidingFasterThanAQuarterKick) {
  const double kick = 9.81 * 0.01;
  for (const double kicks : {0.3, 0.2}) {
    SCOPED_TRACE("sliding at " + std::to_string(kicks) + " kicks");
    TestScene s = restingColumn(10);
    addBody(s, 1.0, Vec2(0.1, 0.05), Vec2(kicks * kick, 0.0), 0.05);
    auto sim = defaultModeSimulator(s, /*sleep=*/false);
    ASSERT_TRUE(stepClean(*sim, s));
    ASSERT_GT(sim->stats().heldParticles, 0) << "the column's solve should have held it";
    const Vec2 v = at(s.state.v, 10);
    if (kicks > kHeldStartFraction) EXPECT_NEAR((v - Vec2(kicks * kick, 0.0)).norm(), 0.0, 1e-12) << v.transpose();
    else EXPECT_LE(v.norm(), 1e-12) << v.transpose();  // stopped; rounding of the velocity's update
  }
}

// 8f. A zone that moves rigidly does not stop when it meets an obstacle. Thirty unit disks
// (radius 0.05) in a touching row 0.012 above a frictionless floor, no forces; hybrid, one
// impulse per particle. The row is squeezed (disk k moves 2 + 0.05 (14.5 - k) m/s along it) and
// turned (the left half moves up at 1 m/s, the right half down): no disk can reach the floor in
// the step (0.01 at most). The zone cannot settle its 29 contacts (Gauss-Seidel on that chain
// needs some 60,000 updates, 8c; the solves allowed before the last resort spend a few thousand),
// so it moves rigidly from t = 0: its centre-of-mass velocity (2, 0) and the angular velocity of
// its momentum, omega = L / I = -22.5 / 22.475 rad/s, which moves the right end down at
// 1.45 m/s: now it reaches the floor. Stopping the whole zone there (the reference's rule, which
// failsafe="rigid" keeps: the control) throws away the slide, which a frictionless floor cannot
// take: the row's momentum along the floor, 60, must survive the step exactly, and the floor must
// take the right end's fall. Without the floor the zone ends the step rigid: the
// control that the row went rigid before it met the floor.
TEST(ContactPhysics, ARigidZoneThatMeetsTheFloorKeepsItsSlide) {
  for (const Failsafe failsafe : {Failsafe::Projection, Failsafe::Rigid}) {
    for (const bool floor : {true, false}) {
      SCOPED_TRACE(std::string(failsafe == Failsafe::Rigid ? "rigid" : "projection") +
                   (floor ? ", floor" : ", no floor"));
      TestScene s = contactScene("hybrid", 0.0, 0.01, failsafe, /*maxIterations=*/1);
      for (int k = 0; k < 30; ++k)
        addBody(s, 1.0, Vec2(0.1 * k, 0.062), Vec2(2.0 + 0.05 * (14.5 - k), k < 15 ? 1.0 : -1.0), 0.05);
      if (floor) s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), Vec2(0, 1)});
      auto sim = defaultModeSimulator(s, /*sleep=*/false);
      ASSERT_TRUE(stepClean(*sim, s));
      double slide = 0;
      for (int k = 0; k < 30; ++k) slide += at(s.state.v, k).x();
      const double endFall = at(s.state.v, 29).y();
      if (!floor) {
        EXPECT_GT(sim->stats().rigidZones, 0);
        EXPECT_NEAR(slide, 60.0, 1e-12);
        EXPECT_NEAR(endFall, -22.5 / 22.475 * 1.45, 1e-12);  // omega r
      } else if (failsafe == Failsafe::Rigid) {
        EXPECT_NEAR(slide, 0.0, 1e-12);  // stopped whole
      } else {
        EXPECT_NEAR(slide, 60.0, 1e-12);
        EXPECT_GE(endFall, -1e-12);
      }
    }
  }
}

// 8g. The same when the rigid zone merges with a zone that touches an obstacle. Under gravity, a
// column of five disks rests on the floor under the row's right end; with no impulses at all
// (maxiters 0) its contacts, closing by a kick at t = 0, make it a zone of its own, touching the
// floor. The row starts 0.012 above it and goes rigid as in 8f; its right end then reaches the
// column, and the two zones merge. Stopping the
// merged zone whole (failsafe="rigid", the control) stops the row and the column; going back to
// the projection keeps the momentum along the floor, 60, which only the frictionless floor and
// vertical gravity act on from outside. Holding off: a held column disk would be an obstacle,
// and the row would meet it as it meets the floor in 8f.
TEST(ContactPhysics, ARigidZoneThatLandsOnARestingZoneKeepsItsSlide) {
  for (const Failsafe failsafe : {Failsafe::Projection, Failsafe::Rigid}) {
    SCOPED_TRACE(failsafe == Failsafe::Rigid ? "rigid" : "projection");
    TestScene s = contactScene("hybrid", 0.0, 0.01, failsafe, /*maxIterations=*/0);
    for (int k = 0; k < 5; ++k) addBody(s, 1.0, Vec2(2.9, 0.05 + 0.1 * k), Vec2::Zero(), 0.05);
    for (int k = 0; k < 30; ++k)
      addBody(s, 1.0, Vec2(0.1 * k, 0.562), Vec2(2.0 + 0.05 * (14.5 - k), k < 15 ? 1.0 : -1.0), 0.05);
    s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), Vec2(0, 1)});
    s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
    auto sim = defaultModeSimulator(s, /*sleep=*/false, 0, /*hold=*/false);
    ASSERT_TRUE(stepClean(*sim, s));
    double slide = 0;
    for (int k = 0; k < 35; ++k) slide += at(s.state.v, k).x();
    EXPECT_NEAR(slide, failsafe == Failsafe::Rigid ? 0.0 : 60.0, 1e-12);
  }
}

// 8h. The contacts a budget-ended solve leaves closing are solved at its instant, each once in a
// step (ContactZones::solvesNow). A row of n = kClusterBodies + 1 unit disks (radius 0.05) on the
// x axis, disk k moving right at (n - 1) / 4 - k / 2 m/s, h = 0.01, the gap after disk k
// 5e-5 + 1e-4 k: neighbours close at 0.5 m/s, 0.005 a step, so the left pair touches at
// t = 5e-5 / 0.005 = 0.01 of the step and its zone takes the pairs to its right (near: each
// closes more than its gap, at most 5e-5 + 1e-4 (n - 2) < 0.005, in the rest of the step).
// Gauss-Seidel on a chain of n - 1 rows of equal masses needs dozens of sweeps to reach the
// relative tolerance 1e-10, so with one update per row the solve's budget, 1 x max(n - 1, 8)
// updates, ends it; n bodies are one more than a solve about to end on its budget projects
// exactly. Every contact of the zone was queried again for that failure: each is brought forward
// at most once, and a pair without a row is not.
TEST(ContactPhysics, ContactsABudgetEndedSolveLeavesAreSolvedAtItsInstantOnce) {
  const int n = math::ContactProjector::kClusterBodies + 1;
  TestScene s = contactScene("hybrid", 0.0, 0.01, Failsafe::Projection, /*maxIterations=*/0);
  double x = 0.0;
  for (int k = 0; k < n; ++k) {
    addBody(s, 1.0, Vec2(x, 0.0), Vec2(0.25 * (n - 1) - 0.5 * k, 0.0), 0.05);
    x += 0.1 + 5e-5 + 1e-4 * k;
  }
  const double h = s.scene.dt, T = 0.01;
  StepZones step(s, /*updatesPerRow=*/1, /*hold=*/false);
  StepMotion& motion = step.motion;
  PairCandidates& candidates = step.candidates;
  ContactZones& zones = step.zones;
  const uint64_t left = particlePairKey(0, 1), right = particlePairKey(1, 2), outer = particlePairKey(0, 2);

  const int zone = zones.absorb(s.scene, motion, candidates, left, T, h);
  ASSERT_GE(zone, 0);
  for (int k = 1; k < n; ++k)
    EXPECT_EQ(zones.zoneOf(k), zones.zoneOf(0)) << "disk " << k << " is near: it joins the zone";
  EXPECT_FALSE(zones.solvesNow(left)) << "no solve has failed yet";
  VecX v = s.state.v;
  std::vector<int> changed;
  StepStats stats;
  zones.resolve(s.scene, motion, candidates, zone, T, h, v, changed, stats);
  EXPECT_EQ(stats.failsafeRounds, 1);
  bool closing = false;
  for (int k = 0; k + 1 < n; ++k) closing = closing || motion.rate(k).x() > motion.rate(k + 1).x();
  EXPECT_TRUE(closing) << "the solve should have ended on its budget, some pair still closing";

  EXPECT_TRUE(zones.solvesNow(left));
  EXPECT_TRUE(zones.solvesNow(right));
  EXPECT_FALSE(zones.solvesNow(left)) << "once in a step";
  EXPECT_FALSE(zones.solvesNow(right)) << "once in a step";
  EXPECT_FALSE(zones.solvesNow(outer)) << "a pair without a row";
}

// The state before the step's forces for 8i and 8j: each particle at half its velocity, so that
// its kick is the other half. Then none is held (each started faster than a quarter of its kick,
// kHeldStartFraction) and none is rescued exactly at a budget's end (each moves at two kicks, far
// below kRescueKicks): the budgets alone decide what the solves spend.
State kickedFromHalf(const TestScene& s) {
  State start = s.state;
  start.v *= 0.5;
  return start;
}

// 8i. With holding on, a zone against an obstacle halves its budget per row at each of its first
// two counts toward the jam limit (kRepeatBudgetHalvings). Five unit disks (radius 0.05) stacked
// exactly on the floor, all moving down at g h = 0.0981 m/s, half of it their kick
// (kickedFromHalf: nothing is held or rescued, only the budgets are looked at), 40 updates per row. The column's rows
// need about 1,150 updates to settle from cold (8c), so every solve below ends on its budget, spending it whole: the
// first solve of the step has a fifth of the budget per row (kFirstSolveBudgetDivisor) over its 5 rows, at least 8: 8 x
// 8 = 64. After each failure the contacts still closing come back at once (as the event loop brings them back; queried
// again for the failure, they do not count), at most 5 fresh rows, so at least 8: 40 / 2 x 8 = 160 after one failure,
// 40 / 4 x 8 = 80 after two and after three. With holding off (the control) every solve has the whole budget, 40 x 8 =
// 320 (three solves: the fourth would settle the column).
TEST(ContactPhysics, AZoneAgainstAnObstacleHalvesItsBudgetAfterEachOfItsFirstTwoFailures) {
  for (const bool hold : {true, false}) {
    SCOPED_TRACE(hold ? "holding on" : "holding off (control)");
    TestScene s = restingColumn(5);
    for (int k = 0; k < 5; ++k) at(s.state.v, k) = Vec2(0.0, -9.81 * 0.01);
    const double h = s.scene.dt;
    const State start = kickedFromHalf(s);
    StepZones step(s, /*updatesPerRow=*/40, hold, &start);
    StepMotion& motion = step.motion;
    PairCandidates& candidates = step.candidates;
    ContactZones& zones = step.zones;
    // The floor contact first, then every contact of the column still closing (the floor's, then
    // disk k's with disk k + 1: the upper one moving down relative to the lower one).
    auto closing = [&] {
      std::vector<uint64_t> keys;
      if (motion.rate(0).y() < 0.0) keys.push_back(pairKey(0, PairKind::ParticleHalfPlane, 0));
      for (int k = 0; k + 1 < 5; ++k)
        if (motion.rate(k + 1).y() < motion.rate(k).y()) keys.push_back(particlePairKey(k, k + 1));
      return keys;
    };
    VecX v = s.state.v;
    std::vector<int> changed;
    std::vector<long> spent;
    const int solves = hold ? 4 : 3;
    for (int solve = 0; solve < solves; ++solve) {
      const double T = 0.1 * solve;
      const std::vector<uint64_t> back =
          solve == 0 ? std::vector<uint64_t>{pairKey(0, PairKind::ParticleHalfPlane, 0)} : closing();
      ASSERT_FALSE(back.empty()) << "solve " << solve << ": the column should still be closing";
      int zone = -1;
      for (uint64_t key : back) zone = zones.absorb(s.scene, motion, candidates, key, T, h);
      ASSERT_GE(zone, 0);
      StepStats stats;
      zones.resolve(s.scene, motion, candidates, zone, T, h, v, changed, stats);
      ASSERT_EQ(stats.failsafeRounds, 1) << "solve " << solve;
      spent.push_back(stats.zoneUpdates);
    }
    const std::vector<long> expected = hold ? std::vector<long>{64, 160, 80, 80} : std::vector<long>{320, 320, 320};
    EXPECT_EQ(spent, expected);
  }
}

// 8j. A zone's first solve is budgeted on its own rows, not on every row of the step. The five-disk
// column of 8i (all moving down, half of it their kick, 40 updates per row, holding on) is a
// zone whose first solve comes at T = 0.1; its rows need about 1,150 updates from cold, so it spends
// its whole budget, 40 / 5 x max(5, 8) = 64 (8i). A column of 20 disks 10 m away, its own zone,
// solved first at t = 0, puts 20 rows into the projector both zones share: the near column's first
// solve must still spend 64, as it does alone (the control). Budgeted on the projector's rows, it
// spent 8 x 25 = 200: a small zone beside a large one paid the large one's budget (on a resting
// pile of 10^5 disks, a few such failures a step made most of the failsafe's work).
TEST(ContactPhysics, AZonesFirstSolveIsBudgetedOnItsOwnRows) {
  for (const bool farColumn : {false, true}) {
    SCOPED_TRACE(farColumn ? "beside a 20-disk column" : "alone (control)");
    TestScene s = restingColumn(5);
    if (farColumn)
      for (int k = 0; k < 20; ++k) addBody(s, 1.0, Vec2(10.0, 0.05 + 0.1 * k), Vec2::Zero(), 0.05);
    for (int p = 0; p < s.scene.numParticles(); ++p) at(s.state.v, p) = Vec2(0.0, -9.81 * 0.01);
    const double h = s.scene.dt;
    const State start = kickedFromHalf(s);
    StepZones step(s, /*updatesPerRow=*/40, /*hold=*/true, &start);
    VecX v = s.state.v;
    std::vector<int> changed;
    auto solveColumnFrom = [&](int bottom, double T) {
      const int zone = step.zones.absorb(s.scene, step.motion, step.candidates,
                                         pairKey(bottom, PairKind::ParticleHalfPlane, 0), T, h);
      if (zone < 0) {  // every particle of the pair fixed: nothing to solve (a broken set-up)
        ADD_FAILURE() << "the floor contact of disk " << bottom << " made no zone";
        return -1L;
      }
      StepStats stats;
      step.zones.resolve(s.scene, step.motion, step.candidates, zone, T, h, v, changed, stats);
      EXPECT_EQ(stats.failsafeRounds, 1);
      return stats.zoneUpdates;
    };
    if (farColumn) {
      EXPECT_EQ(solveColumnFrom(5, 0.0), 8 * 20);  // its own first solve: 20 rows
      EXPECT_NE(step.zones.zoneOf(5), step.zones.zoneOf(0));
    }
    EXPECT_EQ(solveColumnFrom(0, 0.1), 64);
  }
}

}  // namespace
}  // namespace fosssim::testing
