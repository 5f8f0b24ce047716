// ContactProjector's instants (beginInstant, RowSource): a row set at an earlier instant is made
// again by the caller's source before a solve changes its multiplier, so that what the solve
// adds acts along the contact's line of now (angular momentum; see the header). Worked examples
// whose answers follow by hand, and random zones for what must hold whatever the rows: kinetic
// energy never grows, and every row ends satisfied along its new normal.
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kTol = 1e-12;
constexpr long kBudget = 100000;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Gives row `row` again as a pair row of bodies 0 and 1 along `normal`, or keeps every row
/// (keep); counts the calls per row.
class TurnedPair final : public ContactProjector::RowSource {
 public:
  TurnedPair(int row, const Vec2& normal, bool keep = false) : row_(row), normal_(normal), keep_(keep) {}
  bool rowNow(int index, ConstraintRow& out) override {
    ++asked[index];
    if (keep_ || index != row_) return false;
    out = pairRow(0, 1, normal_);
    return true;
  }
  std::vector<int> asked = std::vector<int>(8, 0);

 private:
  int row_;
  Vec2 normal_;
  bool keep_;
};

// Bodies 0 and 1 (unit masses) meet head on along x: v0 = 0, v1 = (-1, 0). The first instant's
// solve leaves both at (-0.5, 0) (equal masses, inelastic projection: the common velocity). At
// the second instant body 2 (unit mass, (-3, 0)) hits body 1 along x: its row is new there; the
// old row 0-1 then closes again and is stale. Made again along n2 = (0.6, 0.8) (the line of
// centres has turned), body 0's whole change at this instant lies along n2 (it has no other
// row): cross(dv0, n2) = 0. Kept as it was (a source that keeps it, or none), along x.
TEST(ContactProjectorInstants, AStaleRowIsMadeAgainBeforeItsMultiplierChanges) {
  const Vec2 n2(0.6, 0.8);
  for (int variant = 0; variant < 3; ++variant) {  // 0: made again, 1: source keeps it, 2: no source
    SCOPED_TRACE(variant);
    ContactProjector cp;
    cp.reset(3);
    cp.beginInstant();
    cp.addBody(0, 1.0, Vec2::Zero());
    cp.addBody(1, 1.0, Vec2(-1, 0));
    cp.addRow(pairRow(0, 1, Vec2(1, 0)));
    ASSERT_TRUE(cp.solve(1.0, kTol, kBudget));
    EXPECT_NEAR(cp.velocity(0).x(), -0.5, 1e-15);
    EXPECT_NEAR(cp.velocity(1).x(), -0.5, 1e-15);

    cp.beginInstant();
    cp.addBody(2, 1.0, Vec2(-3, 0));
    cp.addRow(pairRow(1, 2, Vec2(1, 0)));
    TurnedPair source(0, n2, variant == 1);
    const Vec2 before = cp.velocity(0);
    const double scale = 1.0;
    ASSERT_TRUE(cp.solve(&scale, 1.0, kTol, kBudget, variant == 2 ? nullptr : &source));
    const Vec2 dv0 = cp.velocity(0) - before;
    ASSERT_GT(dv0.norm(), 0.1) << "the old row did not act at the second instant";
    if (variant == 0) {
      EXPECT_NEAR(cross(dv0, n2), 0.0, 1e-15 * dv0.norm()) << dv0.transpose();
      EXPECT_GE(rowVelocity(pairRow(0, 1, n2), velocities(cp, 3)), -1e-12);  // satisfied along n2
    } else {
      EXPECT_EQ(dv0.y(), 0.0) << dv0.transpose();
    }
    // The source is asked about the stale row once in the instant, never about the new one.
    if (variant != 2) {
      EXPECT_EQ(source.asked[0], 1);
      EXPECT_EQ(source.asked[1], 0);
    }
    // The row's impulse so far stays applied and counted (setRow): its total is the first
    // instant's 0.5 plus what the second added.
    EXPECT_GT(cp.totalImpulse(0), 0.5);
  }
}

// Rows set at the current instant are never asked about, however often they are updated.
TEST(ContactProjectorInstants, RowsOfTheCurrentInstantAreNotMadeAgain) {
  ContactProjector cp;
  cp.reset(3);
  cp.beginInstant();
  cp.addBody(0, 0.0, Vec2::Zero());
  cp.addBody(1, 1.0, Vec2(0, -1));
  cp.addBody(2, 1.0, Vec2(0, -2));
  cp.addRow(halfPlaneRow(1, Vec2(0, 1)));
  cp.addRow(pairRow(1, 2, Vec2(0, 1)));  // 2 lands on 1, 1 on the floor (body 0 unused)
  TurnedPair source(0, Vec2(1, 0));
  const double scale = 1.0;
  ASSERT_TRUE(cp.solve(&scale, 1.0, kTol, kBudget, &source));
  EXPECT_EQ(source.asked[0] + source.asked[1], 0);
  EXPECT_NEAR(cp.velocity(1).y(), 0.0, 1e-12);
  EXPECT_NEAR(cp.velocity(2).y(), 0.0, 1e-12);
}

/// Gives every stale row again with its coefficients turned by a fixed small angle per row.
class TurnedRows final : public ContactProjector::RowSource {
 public:
  TurnedRows(const std::vector<ConstraintRow>& rows, std::mt19937& rng) : rows_(rows) {
    std::uniform_real_distribution<double> a(-0.3, 0.3);
    for (size_t k = 0; k < rows.size(); ++k) angle_.push_back(a(rng));
  }
  bool rowNow(int index, ConstraintRow& out) override {
    out = rows_[static_cast<size_t>(index)];
    const Eigen::Rotation2Dd turn(angle_[static_cast<size_t>(index)]);
    for (int m = 0; m < out.count; ++m) out.coef[m] = turn * out.coef[m];
    turned.push_back(out);
    return true;
  }
  bool mayRescue(const int*, int) override { return rescue; }
  std::vector<ConstraintRow> turned;
  bool rescue = true;  ///< whether a budget-ended solve may project its cluster exactly

 private:
  const std::vector<ConstraintRow>& rows_;
  std::vector<double> angle_;
};

/// Ends the current instant (the energy guard starts afresh) and begins the next with a kick of
/// up to 1 m/s each way to every movable body: new closing, the bodies' velocities moved by
/// freeze-and-release (the projector's only setter).
void nextInstantWithKick(ContactProjector& cp, const Zone& z, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<int> changed;
  cp.takeChanged(changed);
  cp.beginInstant();
  for (size_t b = 0; b < z.v.size(); ++b) {
    if (z.invMass[b] == 0.0) continue;
    const int id = static_cast<int>(b);
    // Braced: x is drawn before y under every compiler (a call's arguments come in an order the
    // compiler picks: gcc right to left, clang left to right).
    const Vec2 kicked = cp.velocity(id) + Vec2{u(rng), u(rng)};
    cp.freeze(id, kicked);
    cp.release(id, z.invMass[b], kicked);
  }
  cp.takeChanged(changed);
}

// 300 random zones: solved at one instant, then at the next with a kick to every movable body
// (new closing), their rows made again turned by up to 0.3 rad. The second solve never adds
// kinetic energy to the kicked velocities (every update is still a projection onto a half-space
// through v = 0), and each row made again ends satisfied along its turned normal.
TEST(ContactProjectorInstants, RowsMadeAgainNeverAddEnergyAndEndSatisfied) {
  std::mt19937 rng(4242);
  int turnedRows = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Zone z = randomZone(rng);
    ContactProjector cp;
    cp.beginInstant();
    addBodies(cp, z);  // resets it
    for (const ConstraintRow& r : z.rows) cp.addRow(r);
    if (!cp.solve(speedScale(z.v), kTol, kBudget)) continue;
    nextInstantWithKick(cp, z, rng);
    const double before = kineticEnergy(z.invMass, velocities(cp, z.v.size()));
    TurnedRows source(z.rows, rng);
    const double scale = speedScale(velocities(cp, z.v.size())) + 1.0;
    if (!cp.solve(&scale, 1.0, kTol, kBudget, &source)) continue;
    EXPECT_LE(kineticEnergy(z.invMass, velocities(cp, z.v.size())), before * (1 + 1e-12)) << "trial " << trial;
    const std::vector<Vec2> v = velocities(cp, z.v.size());
    for (const ConstraintRow& r : source.turned) {
      ++turnedRows;
      EXPECT_GE(rowVelocity(r, v), -1e-9 * scale * rowNorm(r)) << "trial " << trial;
    }
  }
  EXPECT_GE(turnedRows, 300) << "too few rows made again to test anything";
}

// The energy guard over rows made again: random zones whose second instant warm-starts new rows
// with random impulses (half of them far too large) and solves on a starved budget with every
// stale row made again turned. After capEnergy the kinetic energy is no more than at the
// instant's start (the kicked velocities), and every row's whole impulse stays non-negative.
TEST(ContactProjectorInstants, StarvedSolvesWithRowsMadeAgainAreCappedWithoutEnergyGain) {
  std::mt19937 rng(5150);
  std::uniform_real_distribution<double> impulse(0.0, 4.0);
  int madeAgain = 0, capped = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Zone z = randomZone(rng);
    ContactProjector cp;
    cp.beginInstant();
    addBodies(cp, z);  // resets it
    const int old = static_cast<int>(z.rows.size());
    for (const ConstraintRow& r : z.rows) cp.addRow(r, impulse(rng));
    cp.solve(speedScale(z.v), kTol, 2);
    cp.capEnergy();
    nextInstantWithKick(cp, z, rng);
    const double start = kineticEnergy(z.invMass, velocities(cp, z.v.size()));
    for (int k = 0; k < old; ++k) cp.addRow(z.rows[static_cast<size_t>(k)], impulse(rng));  // new rows, warm
    TurnedRows source(z.rows, rng);
    // Starved for good: the rescue would project a small zone exactly (any of up to
    // kClusterRows rows) and leave the guard nothing to do.
    source.rescue = false;
    const double scale = speedScale(velocities(cp, z.v.size())) + 1.0;
    cp.solve(&scale, 1.0, kTol, 2, &source);
    madeAgain += static_cast<int>(source.turned.size());
    capped += cp.capEnergy() < 1.0;
    EXPECT_LE(kineticEnergy(z.invMass, velocities(cp, z.v.size())), start * (1 + 1e-12)) << "trial " << trial;
    for (int k = 0; k < cp.rows(); ++k) EXPECT_GE(cp.totalImpulse(k), -1e-12) << "trial " << trial << " row " << k;
  }
  EXPECT_GT(capped, 100);     // the guard had work to do (193 of the 300, the rescue off)
  EXPECT_GT(madeAgain, 300);  // and rows were made again under it (765)
}

}  // namespace
}  // namespace fosssim::math
