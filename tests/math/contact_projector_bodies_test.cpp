// ContactProjector's bodies that stop being movable or become movable again within a solve
// sequence: a frozen body keeps its velocity whatever rows and solves follow (freezing is a
// state: freezing again at the same velocity changes nothing), a row naming a body twice stays
// exact after a freeze, and a released body (a sleeper met as an obstacle, woken later in the
// step) is solved with its own velocity from then on; a solve taken back (rollBack, for a zone
// that then wakes a sleeper it hit) leaves what the next solve would have found.
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kTol = 1e-12;

void expectChangedOnce(ContactProjector& cp, const std::vector<Vec2>& before, int trial) {
  std::vector<int> changed;
  cp.takeChanged(changed);
  const std::set<int> listed(changed.begin(), changed.end());
  EXPECT_EQ(listed.size(), changed.size()) << "trial " << trial << ": a body listed twice";
  for (size_t b = 0; b < before.size(); ++b) {
    if (cp.velocity(static_cast<int>(b)) == before[b]) continue;
    EXPECT_TRUE(listed.count(static_cast<int>(b))) << "trial " << trial << " body " << b << " changed, unlisted";
  }
}

// Freezing body b at u before the solve is the projection with b fixed at u (the enumeration
// sees inverse mass 0 there); later rows and solves never move it. A moving frozen body can make
// the zone infeasible, where Gauss-Seidel only spends its budget: a smaller one keeps this fast.
constexpr long kFrozenBudget = 100000;
TEST(ContactProjector, FrozenBodiesKeepTheirVelocityAndChangesAreListedOnce) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  ContactProjector cp;
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Zone z = randomZone(rng);
    const int b = std::uniform_int_distribution<int>(1, static_cast<int>(z.v.size()) - 1)(rng);
    // Braced: x is drawn before y under every compiler (a call's arguments come in an order the
    // compiler picks: gcc right to left, clang left to right).
    const Vec2 frozen{u(rng), u(rng)};
    addBodies(cp, z);
    for (const ConstraintRow& r : z.rows) cp.addRow(r);
    cp.freeze(b, frozen);
    const double scale = std::max(speedScale(z.v), frozen.norm());
    const bool ok = cp.solve(scale, kTol, kFrozenBudget);
    expectChangedOnce(cp, z.v, trial);
    EXPECT_EQ(cp.velocity(b), frozen);
    z.invMass[b] = 0.0;
    z.v[b] = frozen;
    std::vector<Vec2> ref = z.v;
    if (ok && projectByEnumeration(z.invMass, z.rows, ref)) {  // infeasible when fixed bodies approach
      ++compared;
      for (size_t c = 0; c < z.v.size(); ++c)
        EXPECT_LE((cp.velocity(static_cast<int>(c)) - ref[c]).norm(), 1e-7 * scale) << "trial " << trial;
    }
    // More rows on the frozen body, solved: it does not move, others are listed once if moved.
    const std::vector<Vec2> before = velocities(cp, z.v.size());
    const Zone more = randomZone(rng);
    for (ConstraintRow r : more.rows) {
      r.body[0] = b;
      for (int m = 1; m < r.count; ++m) r.body[m] = (b + m) % static_cast<int>(z.v.size());
      cp.addRow(r);
    }
    cp.solve(scale, kTol, kFrozenBudget);
    EXPECT_EQ(cp.velocity(b), frozen) << "trial " << trial;
    expectChangedOnce(cp, before, trial);
  }
  EXPECT_GE(compared, 120);  // 152 of 300 here; others infeasible or out of budget
}

// Freezing is a state, not an action: freezing a body again at the same velocity (a rigid zone
// moved again, whose members are frozen each time) changes nothing, before or after rows that
// name it were added, and freezing it again at another velocity is freezing it there.
TEST(ContactProjector, FreezingAgainAtTheSameVelocityChangesNothing) {
  std::mt19937 rng(778);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Zone z = randomZone(rng), more = randomZone(rng);
    const int b = std::uniform_int_distribution<int>(1, static_cast<int>(z.v.size()) - 1)(rng);
    const Vec2 frozen{u(rng), u(rng)}, moved{u(rng), u(rng)};  // braced: x then y (see above)
    ContactProjector once, twice;
    for (ContactProjector* cp : {&once, &twice}) {
      addBodies(*cp, z);
      for (const ConstraintRow& r : z.rows) cp->addRow(r);
      cp->freeze(b, frozen);
      if (cp == &twice) cp->freeze(b, frozen);
      for (ConstraintRow r : more.rows) {
        r.body[0] = b;
        for (int m = 1; m < r.count; ++m) r.body[m] = (b + m) % static_cast<int>(z.v.size());
        cp->addRow(r);
      }
      if (cp == &twice) cp->freeze(b, frozen);
      cp->solve(speedScale(z.v) + 1.0, kTol, kFrozenBudget);
      cp->freeze(b, moved);
      cp->solve(speedScale(z.v) + 1.0, kTol, kFrozenBudget);
    }
    EXPECT_EQ(twice.velocity(b), moved) << "trial " << trial;
    for (size_t c = 0; c < z.v.size(); ++c)
      EXPECT_EQ(twice.velocity(static_cast<int>(c)), once.velocity(static_cast<int>(c))) << "trial " << trial;
  }
}

// A row may name a body twice (an edge whose ends are one particle acts as a pair contact); after
// freezing the row's other body it must still stop the approach exactly like the pair row does.
TEST(ContactProjector, FreezeKeepsARowThatNamesABodyTwiceExact) {
  const Vec2 n = unit(0.8);
  for (const double alpha : {0.5, 0.2}) {
    ContactProjector asEdge, asPair;  // the same contact written both ways
    for (ContactProjector* cp : {&asEdge, &asPair}) {
      cp->reset(2);
      cp->addBody(0, 1.0, n);  // moving toward body 1 along n
      cp->addBody(1, 1.0, Vec2::Zero());
      cp->addRow(cp == &asEdge ? edgeRow(1, 0, 0, alpha, n) : pairRow(0, 1, n));
      cp->freeze(1, Vec2::Zero());
      EXPECT_TRUE(cp->solve(1.0, kTol, 100));
    }
    EXPECT_LE(asPair.velocity(0).norm(), 1e-14);
    EXPECT_LE((asEdge.velocity(0) - asPair.velocity(0)).norm(), 1e-12)
        << "alpha " << alpha << ": edge row gives (" << asEdge.velocity(0).transpose() << ")";
  }
}

// A body met as an obstacle (inverse mass 0, at rest) and released with a velocity toward a
// resting body it touches: the two now share the approach like any two equal disks (COR 0 along
// the normal: both at half the speed), and both are listed as changed. Still immovable, it would
// keep its zero velocity and the other would not move either. Releasing a movable body changes
// nothing.
TEST(ContactProjector, AReleasedBodyIsSolvedWithItsOwnVelocity) {
  const Vec2 n = unit(0.3);
  ContactProjector cp;
  cp.reset(2);
  cp.addBody(0, 0.0, Vec2::Zero());  // the sleeper, met as an obstacle
  cp.addBody(1, 1.0, Vec2::Zero());  // touching it, at rest
  cp.addRow(pairRow(0, 1, n));
  EXPECT_TRUE(cp.solve(1.0, kTol, 100));
  std::vector<int> changed;
  cp.takeChanged(changed);
  EXPECT_TRUE(changed.empty());
  cp.release(0, 1.0, n);  // woken, moving into body 1
  cp.release(1, 2.0, Vec2(5, 5));  // movable already: no-op
  EXPECT_TRUE(cp.solve(1.0, kTol, 100));
  EXPECT_LE((cp.velocity(0) - 0.5 * n).norm(), 1e-14) << cp.velocity(0).transpose();
  EXPECT_LE((cp.velocity(1) - 0.5 * n).norm(), 1e-14) << cp.velocity(1).transpose();
  cp.takeChanged(changed);
  EXPECT_EQ(std::set<int>(changed.begin(), changed.end()), (std::set<int>{0, 1}));
}

// A body moving into an obstacle (a sleeper): the solve stops it. Taken back, the velocities and
// the multiplier are where they were before the solve; with the obstacle released as a body of
// equal mass, the next solve is the projection of the original velocities onto the released
// problem: the two move off together at half the speed (momentum kept), as if the first solve
// had never run.
TEST(ContactProjector, ASolveTakenBackLeavesTheNextSolveTheOriginalVelocities) {
  const Vec2 n = unit(0.3);
  ContactProjector cp;
  cp.reset(2);
  cp.addBody(0, 0.0, Vec2::Zero());  // the sleeper
  cp.addBody(1, 1.0, -2.0 * n);      // moving into it: the row's normal points from 0 to 1
  const int row = cp.addRow(pairRow(0, 1, n));
  EXPECT_TRUE(cp.solve(1.0, kTol, 100));
  EXPECT_LE(cp.velocity(1).norm(), 1e-14) << "stopped against the obstacle";
  EXPECT_GT(cp.impulse(row), 0.0);
  cp.rollBack();
  EXPECT_EQ(cp.velocity(1), Vec2(-2.0 * n));
  EXPECT_EQ(cp.impulse(row), 0.0);
  cp.release(0, 1.0, Vec2::Zero());
  EXPECT_TRUE(cp.solve(1.0, kTol, 100));
  EXPECT_LE((cp.velocity(0) + n).norm(), 1e-14) << cp.velocity(0).transpose();
  EXPECT_LE((cp.velocity(1) + n).norm(), 1e-14) << cp.velocity(1).transpose();
}

}  // namespace
}  // namespace fosssim::math
