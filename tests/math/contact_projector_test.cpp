// The failsafe's worklist Gauss-Seidel (ContactProjector) against its promises: a batch solve is
// the single projection (checked against the active-set enumeration), incremental solves never
// add energy and end feasible, warm starts from the last impulses make a resting pile cheap (a
// replaced row's impulse counts in its total), a body in more rows than it keeps inline is
// solved as exactly, a spent budget is reported without gaining energy and leaves the rows it did
// not settle queued (to be dropped or set aside per problem), and rows grouped by speed scale each
// settle to their own group's tolerance, and a solve cut into small budgets ends exactly where one
// solve ends. Frozen and released bodies: contact_projector_bodies_test.cpp.
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <random>
#include <set>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kTol = 1e-12;
constexpr long kLargeBudget = 2000000;


// Random over-constrained zones can jam (v* = 0 with nearly dependent normals), where Gauss-Seidel
// contracts slowly and may spend even a large budget (ZoneProjection allows ~2% of them). Those
// must return false and still not add energy; all others must equal the single projection.
TEST(ContactProjector, BatchSolveEqualsTheActiveSetProjection) {
  std::mt19937 rng(20240601);
  ContactProjector cp;
  const int zones = 400;
  int unconverged = 0;
  for (int trial = 0; trial < zones; ++trial) {
    const Zone z = randomZone(rng);
    addBodies(cp, z);
    for (const ConstraintRow& r : z.rows) cp.addRow(r);
    const double scale = speedScale(z.v);
    const bool ok = cp.solve(scale, kTol, kLargeBudget);
    const std::vector<Vec2> v = velocities(cp, z.v.size());
    EXPECT_LE(kineticEnergy(z.invMass, v), kineticEnergy(z.invMass, z.v) * (1 + 1e-13)) << "trial " << trial;
    EXPECT_EQ(v[0], z.v[0]);
    unconverged += !ok;
    if (!ok) continue;
    std::vector<Vec2> ref = z.v;
    ASSERT_TRUE(projectByEnumeration(z.invMass, z.rows, ref)) << "trial " << trial;
    for (size_t b = 0; b < z.v.size(); ++b)
      EXPECT_LE((v[b] - ref[b]).norm(), 1e-7 * scale) << "trial " << trial << " body " << b;
  }
  EXPECT_LE(unconverged, zones / 20);
}

// Rows arriving in batches, each followed by a solve: a sequence of projections onto shrinking
// cones through 0, so energy is monotone; a converged last solve leaves every row satisfied
// (rows not revisited kept their bodies' velocities since they were last within tolerance).
TEST(ContactProjector, IncrementalSolvesStayFeasibleLoseEnergyAndKeepMomentum) {
  std::mt19937 rng(424242);
  ContactProjector cp;
  int unconverged = 0, trials = 0;
  for (const bool freeOnly : {false, true})
    for (int trial = 0; trial < 300; ++trial, ++trials) {
      const Zone z = randomZone(rng, freeOnly);
      addBodies(cp, z);
      const double scale = speedScale(z.v);
      double energy = kineticEnergy(z.invMass, z.v), mass = 0.0;
      for (double w : z.invMass) mass += w > 0.0 ? 1.0 / w : 0.0;
      bool allOk = true;
      for (size_t next = 0; next < z.rows.size();) {
        const size_t batch = std::uniform_int_distribution<size_t>(1, z.rows.size() - next)(rng);
        for (size_t k = 0; k < batch; ++k) cp.addRow(z.rows[next++]);
        allOk = cp.solve(scale, kTol, kLargeBudget) && allOk;
        const std::vector<Vec2> v = velocities(cp, z.v.size());
        const double e = kineticEnergy(z.invMass, v);
        EXPECT_LE(e, energy * (1 + 1e-13)) << "trial " << trial << " after row " << next;
        energy = e;
        if (!freeOnly) continue;  // fixed body or one-body rows: momentum is not kept
        EXPECT_LE((momentum(z.invMass, v) - momentum(z.invMass, z.v)).norm(), 1e-12 * mass * scale) << trial;
      }
      unconverged += !allOk;
      if (!allOk) continue;
      const std::vector<Vec2> v = velocities(cp, z.v.size());
      for (size_t k = 0; k < z.rows.size(); ++k)
        EXPECT_GE(rowVelocity(z.rows[k], v) / rowNorm(z.rows[k]), -2 * kTol * scale)
            << "trial " << trial << " row " << k << " freeOnly " << freeOnly;
    }
  EXPECT_LE(unconverged, trials / 20);
}

// A column of disks resting on a floor: each step gravity gives v~ = -g h, and the rows (floor,
// neighbours) must take it all back. From zero impulses the correction travels up and down the
// chain (O(n^2) updates); warm-started with the last impulses the column is already at rest.
TEST(ContactProjector, WarmStartFromTheLastImpulsesSettlesARestingColumnAtOnce) {
  const int disks = 20;
  const double gh = 9.81 / 60.0;
  const Vec2 up(0.0, 1.0);
  std::mt19937 rng(3);
  Zone z;
  for (int i = 0; i < disks; ++i) {
    z.invMass.push_back(1.0 / std::uniform_real_distribution<double>(0.5, 2.0)(rng));
    z.v.push_back(-gh * up);
  }
  z.rows.push_back(halfPlaneRow(0, up));
  for (int i = 0; i + 1 < disks; ++i) z.rows.push_back(pairRow(i, i + 1, up));
  const long small = 4L * static_cast<long>(z.rows.size());
  ContactProjector cold;
  addBodies(cold, z);
  for (const ConstraintRow& r : z.rows) cold.addRow(r);
  EXPECT_FALSE(cold.solve(gh, kTol, small));  // cold: the small budget is not enough
  addBodies(cold, z);
  for (const ConstraintRow& r : z.rows) cold.addRow(r);
  ASSERT_TRUE(cold.solve(gh, kTol, kLargeBudget));
  for (int i = 0; i < disks; ++i) EXPECT_LE(cold.velocity(i).norm(), 1e-9 * gh) << "disk " << i;
  // Closed form: row k carries the weight-step of every disk above it (disk k and up; row 0 is the floor).
  double above = 0.0;
  for (int k = disks - 1; k >= 0; --k) {
    above += gh / z.invMass[k];
    EXPECT_NEAR(cold.impulse(k), above, 1e-8 * above) << "row " << k;
  }
  ContactProjector warm;
  addBodies(warm, z);
  for (int k = 0; k < cold.rows(); ++k) warm.addRow(z.rows[k], cold.impulse(k));
  EXPECT_TRUE(warm.solve(gh, kTol, small));
  for (int i = 0; i < disks; ++i) EXPECT_LE((warm.velocity(i) - cold.velocity(i)).norm(), 1e-9 * gh) << "disk " << i;
}

// A replaced row (setRow: the contact's normal of a later time) restarts its multiplier at 0 and
// keeps the impulse it applied; totalImpulse counts both, the contact's whole impulse. Worked by
// hand: a unit mass falling at 1 m/s onto the floor row v_y >= 0 takes the impulse 1 and stops;
// replaced by the row 0.6 v_x + 0.8 v_y >= 0, which rest satisfies, it takes nothing more.
TEST(ContactProjector, ReplacedRowsKeepTheirImpulseInTheTotal) {
  ContactProjector cp;
  cp.reset(1);
  cp.addBody(0, 1.0, Vec2(0.0, -1.0));
  const int k = cp.addRow(halfPlaneRow(0, Vec2(0.0, 1.0)));
  ASSERT_TRUE(cp.solve(1.0, kTol, kLargeBudget));
  EXPECT_EQ(cp.impulse(k), 1.0);
  EXPECT_EQ(cp.totalImpulse(k), 1.0);
  EXPECT_EQ(cp.velocity(0), Vec2(0.0, 0.0));
  cp.setRow(k, halfPlaneRow(0, Vec2(0.6, 0.8)));
  ASSERT_TRUE(cp.solve(1.0, kTol, kLargeBudget));
  EXPECT_EQ(cp.impulse(k), 0.0);
  EXPECT_EQ(cp.totalImpulse(k), 1.0);
  EXPECT_EQ(cp.velocity(0), Vec2(0.0, 0.0));
}

// A disk jammed among many contacts (a hub: more rows than a body stores beside it) must still have
// every row revisited when any of them moves it: the batch solve equals the single projection.
TEST(ContactProjector, ABodyInMoreRowsThanItStoresInlineIsSolvedExactly) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> spread(-1.4, 1.4), speed(0.5, 2.0);
  for (int trial = 0; trial < 60; ++trial) {
    Zone z;
    z.invMass = {0.0, 1.0, 0.5};  // an obstacle, the hub, a neighbour
    // The speed drawn before the direction, in its own statement: a product's operands are
    // evaluated in an order the compiler picks (gcc right to left, clang left to right).
    const double hubSpeed = speed(rng);
    z.v = {Vec2::Zero(), hubSpeed * unit(spread(rng)), Vec2::Zero()};
    const int rows = 9 + trial % 4;  // 9-12 rows, all naming the hub
    for (int k = 0; k < rows; ++k) {
      const Vec2 n = unit(3.141592653589793 + spread(rng));  // pointing back against the hub's motion
      if (k % 3 == 2) z.rows.push_back(pairRow(1, 2, -n));
      else z.rows.push_back(halfPlaneRow(1, n));
    }
    ContactProjector cp;
    addBodies(cp, z);
    for (const ConstraintRow& r : z.rows) cp.addRow(r);
    ASSERT_TRUE(cp.solve(speedScale(z.v), kTol, kLargeBudget)) << "trial " << trial;
    std::vector<Vec2> ref = z.v;
    ASSERT_TRUE(projectByEnumeration(z.invMass, z.rows, ref)) << "trial " << trial;
    for (size_t b = 0; b < z.v.size(); ++b)
      EXPECT_LE((cp.velocity(static_cast<int>(b)) - ref[b]).norm(), 1e-7 * speedScale(z.v))
          << "trial " << trial << " body " << b;
  }
}

// A disk driven into the tip of a narrow V (v* = 0, walls 2e-3 rad apart), a column of disks
// moving with it on top (pair rows tie them: none is alone, so this is Gauss-Seidel's, not
// solveAlone's; one more disk than the exact rescue of a budget about to end takes,
// kClusterBodies), contracts by about cos^2(2a) per pair of updates: a small budget runs out,
// says so, and has only removed energy.
TEST(ContactProjector, SpentBudgetIsReportedAndAddsNoEnergy) {
  const int disks = ContactProjector::kClusterBodies + 1;
  const double a = 1e-3;  // half-angle of the V
  const Vec2 v0(0.3, -1.0), n1(std::cos(a), std::sin(a)), n2(-std::cos(a), std::sin(a));
  for (const long budget : {0L, 1L, 2L, 5L, 50L, 1000L}) {
    ContactProjector cp;
    cp.reset(disks);
    for (int b = 0; b < disks; ++b) cp.addBody(b, 1.0, v0);
    for (const Vec2& n : {n1, n2}) cp.addRow(halfPlaneRow(0, n));
    for (int b = 0; b + 1 < disks; ++b) cp.addRow(pairRow(b, b + 1, Vec2(0, 1)));
    EXPECT_FALSE(cp.solve(v0.norm(), kTol, budget)) << "budget " << budget;
    double energy = 0;
    for (int b = 0; b < disks; ++b) energy += cp.velocity(b).squaredNorm();
    EXPECT_LE(energy, disks * v0.squaredNorm() * (1 + 1e-15)) << "budget " << budget;
  }
  std::mt19937 rng(99);  // random zones stopped after 0-4 updates: never more energy
  for (int trial = 0; trial < 200; ++trial) {
    const Zone z = randomZone(rng);
    for (long budget = 0; budget <= 4; ++budget) {
      ContactProjector cp;
      addBodies(cp, z);
      for (const ConstraintRow& r : z.rows) cp.addRow(r);
      cp.solve(speedScale(z.v), kTol, budget);
      EXPECT_LE(kineticEnergy(z.invMass, velocities(cp, z.v.size())), kineticEnergy(z.invMass, z.v) * (1 + 1e-14))
          << "trial " << trial << " budget " << budget;
    }
  }
}

// A spent budget keeps the worklist as it was (the row it stopped at stays at the front), so a
// solve cut into many small budgets makes the same updates in the same order as one solve and
// ends on the same floating-point numbers. The cold 20-disk column needs about 1,150 updates,
// far more than its 20 rows, so the queue's window slides back to the front of its storage on
// the way; both solves slide alike, so the comparison alone would not see a slide that lost a
// row: the impulses are also checked against the column's closed form (row k carries the
// weight-step of every disk above it, as in the warm-start test above).
TEST(ContactProjector, ASolveCutIntoBudgetsEndsExactlyWhereOneSolveEnds) {
  const int disks = 20;
  const double gh = 9.81 / 60.0;
  const Vec2 up(0.0, 1.0);
  Zone z;
  for (int i = 0; i < disks; ++i) {
    z.invMass.push_back(1.0 / (1.0 + 0.05 * i));
    z.v.push_back(-gh * up);
  }
  z.rows.push_back(halfPlaneRow(0, up));
  for (int i = 0; i + 1 < disks; ++i) z.rows.push_back(pairRow(i, i + 1, up));
  ContactProjector whole, cut;
  for (ContactProjector* cp : {&whole, &cut}) {
    addBodies(*cp, z);
    for (const ConstraintRow& r : z.rows) cp->addRow(r);
  }
  ASSERT_TRUE(whole.solve(gh, kTol, kLargeBudget));
  ASSERT_GT(whole.updates(), 20L * disks);
  int solves = 1;
  while (!cut.solve(gh, kTol, 7)) {
    EXPECT_EQ(cut.updates(), 7L * solves);
    ASSERT_LT(++solves, 100000);
  }
  EXPECT_EQ(cut.updates(), whole.updates());
  for (int i = 0; i < disks; ++i) EXPECT_EQ(cut.velocity(i), whole.velocity(i)) << "disk " << i;
  for (int k = 0; k < whole.rows(); ++k) EXPECT_EQ(cut.impulse(k), whole.impulse(k)) << "row " << k;
  double above = 0.0;
  for (int k = disks - 1; k >= 0; --k) {
    above += gh / z.invMass[k];
    EXPECT_NEAR(cut.impulse(k), above, 1e-8 * above) << "row " << k;
  }
}

// Two independent problems sharing the worklist, a fast one (a disk at 1 m/s into a wall) and a
// slow one (the same at 10^-12 m/s: the first at another unit of length). Measured against one
// scale, the fast one's, the slow disk's closing speed 10^-12 is below the tolerance (10^-12 of
// 1 m/s) and its row passes as settled while it still approaches; with a scale per group each row
// is held to its own problem's tolerance and the slow disk stops approaching as the fast one does.
TEST(ContactProjector, EachGroupSettlesToItsOwnSpeedScale) {
  const Vec2 n(0.0, 1.0);  // both walls' normals
  const double fast = 1.0, slow = 1e-12;
  const auto run = [&](bool grouped) {
    ContactProjector cp;
    cp.reset(2);
    cp.addBody(0, 1.0, Vec2(0.5, -fast));
    cp.addBody(1, 1.0, Vec2(0.5 * slow, -slow));
    cp.addRow(halfPlaneRow(0, n), 0.0, 0);
    cp.addRow(halfPlaneRow(1, n), 0.0, grouped ? 1 : 0);
    const double scales[2] = {fast, slow};
    EXPECT_TRUE(cp.solve(scales, 1.0, kTol, kLargeBudget));
    return cp;
  };
  const ContactProjector grouped = run(true);
  EXPECT_GE(grouped.velocity(0).dot(n), -kTol * fast);
  EXPECT_GE(grouped.velocity(1).dot(n), -kTol * slow);
  EXPECT_EQ(grouped.velocity(1).x(), 0.5 * slow);  // tangential motion kept
  // Control: one scale for both leaves the slow disk approaching at its full speed.
  const ContactProjector shared = run(false);
  EXPECT_EQ(shared.velocity(1).dot(n), -slow);
}

// Independent problems share the worklist, and a spent budget is one problem's failure: the
// rows it leaves stay queued, the caller drops that problem's (unqueueIf) and sets the other's
// aside (takeQueued) until their own solve (queueRow). A disk in a V with a second disk on it
// (two rows, queued first; the pair's row, queued last, ties the disks, so Gauss-Seidel solves
// the V row by row) and a disk over a floor (one row): two updates settle neither the V nor reach
// the floor.
TEST(ContactProjector, SpentBudgetLeavesOtherProblemsQueued) {
  const double a = 0.1;
  const Vec2 down(0.0, -1.0), floor(0.0, 1.0);
  ContactProjector cp;
  cp.reset(3);
  cp.addBody(0, 1.0, down);
  cp.addBody(1, 1.0, down);
  cp.addBody(2, 1.0, down);
  cp.addRow(halfPlaneRow(0, Vec2(std::sin(a), std::cos(a))));
  cp.addRow(halfPlaneRow(0, Vec2(-std::sin(a), std::cos(a))));
  cp.addRow(halfPlaneRow(1, floor));
  cp.addRow(pairRow(0, 2, floor));
  ASSERT_FALSE(cp.solve(1.0, kTol, 2));
  EXPECT_EQ(cp.velocity(1), down);  // the floor's row was not reached
  cp.unqueueIf([](int body) { return body == 0; });
  EXPECT_EQ(cp.queuedRows(), 1);  // only the floor's row is left
  EXPECT_TRUE(cp.moves(2, [](int body) { return body == 1; }));
  EXPECT_FALSE(cp.moves(2, [](int body) { return body == 0; }));
  std::vector<int> aside;
  cp.takeQueued(aside);
  EXPECT_EQ(aside, std::vector<int>{2});
  EXPECT_EQ(cp.queuedRows(), 0);
  const Vec2 inV = cp.velocity(0);
  ASSERT_TRUE(cp.solve(1.0, kTol, 0));  // nothing queued: no update needed
  EXPECT_EQ(cp.velocity(1), down);
  cp.queueRow(aside[0]);
  ASSERT_TRUE(cp.solve(1.0, kTol, kLargeBudget));
  EXPECT_EQ(cp.velocity(0), inV);  // the V's rows were dropped: not solved again
  EXPECT_GE(cp.velocity(1).dot(floor), -kTol);
}

}  // namespace
}  // namespace fosssim::math
