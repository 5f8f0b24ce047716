// Rows with a bias (ConstraintRow::bias <= 0): a pair still apart may close its gap in the time
// left, and no faster. Closed forms derived by hand, the three solvers (Gauss-Seidel in
// ContactProjector, the active set, the enumeration) against them, against each other and against
// the optimality (KKT) conditions recomputed here from the rows, and kinetic energy that never
// grows (v = 0 is still allowed: a projection onto a convex set holding 0 is non-expansive).
#include "fosssim/math/active_set_projection.h"
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kSlack = 1e-9;  // the feasibility slack asked of the exact solvers, relative

/// The velocities the three solvers give zone z (false: that solver gave none).
struct Answers {
  std::vector<Vec2> gaussSeidel, activeSet, enumeration;
  bool gaussSeidelSolved = false, activeSetSolved = false, enumerated = false;
  std::vector<double> activeSetImpulses;
};
Answers solveAllWays(const Zone& z) {
  Answers a;
  ContactProjector cp;
  addBodies(cp, z);
  for (const ConstraintRow& r : z.rows) cp.addRow(r);
  a.gaussSeidelSolved = cp.solve(std::max(speedScale(z.v), 1e-300), 1e-12, 1000000);
  a.gaussSeidel = velocities(cp, z.v.size());
  a.activeSet = a.enumeration = z.v;
  a.activeSetSolved = projectByActiveSet(z.invMass, z.rows, a.activeSet, kSlack, a.activeSetImpulses);
  std::vector<double> impulses;
  a.enumerated = projectByEnumeration(z.invMass, z.rows, a.enumeration, kSlack, impulses);
  return a;
}

// Two free disks head-on along n = (1, 0): disk 1 at u1 = 2, disk 2 at u2 = -1, closing at
// c = u1 - u2 = 3. Row n . (v2 - v1) >= b. If c <= -b the pair closes slowly enough and nothing
// changes. Otherwise an impulse l along the row: v1 = u1 - w1 l, v2 = u2 + w2 l, and the row is
// tight, v2 - v1 = b, so l = (c + b) / (w1 + w2): the pair closes at exactly -b, momentum
// m1 v1 + m2 v2 = m1 u1 + m2 u2 is kept, and kinetic energy falls.
TEST(SpeculativeRows, AHeadOnPairClosesItsGapNoFaster) {
  const double u1 = 2.0, u2 = -1.0;
  for (const auto& [m1, m2] : {std::pair{1.0, 1.0}, std::pair{1.0, 3.0}, std::pair{0.2, 5.0}})
    for (double b : {0.0, -0.5, -2.5, -3.0, -5.0}) {
      SCOPED_TRACE("masses " + std::to_string(m1) + ", " + std::to_string(m2) + ", bias " + std::to_string(b));
      Zone z;
      z.invMass = {1.0 / m1, 1.0 / m2};
      z.v = {Vec2(u1, 0.0), Vec2(u2, 0.0)};
      ConstraintRow row = pairRow(0, 1, Vec2(1.0, 0.0));
      row.bias = b;
      z.rows = {row};
      const double l = std::max(0.0, (u1 - u2 + b) / (1.0 / m1 + 1.0 / m2));
      const Vec2 v1(u1 - l / m1, 0.0), v2(u2 + l / m2, 0.0);
      const Answers a = solveAllWays(z);
      ASSERT_TRUE(a.gaussSeidelSolved && a.activeSetSolved && a.enumerated);
      for (const auto* v : {&a.gaussSeidel, &a.activeSet, &a.enumeration}) {
        EXPECT_LT(((*v)[0] - v1).norm(), 1e-9);
        EXPECT_LT(((*v)[1] - v2).norm(), 1e-9);
      }
    }
}

// A disk of mass 1 at v~ = (-2, -3) against a floor (n = (0, 1)) it may approach at 1 and a wall
// (n = (1, 0)) it touches. The rows are orthogonal, so each acts alone: v_y = max(-3, -1) = -1,
// v_x = max(-2, 0) = 0.
TEST(SpeculativeRows, ADiskAgainstAFloorItMayApproachAndAWallItTouches) {
  Zone z;
  z.invMass = {0.0, 1.0};
  z.v = {Vec2::Zero(), Vec2(-2.0, -3.0)};
  ConstraintRow floor = halfPlaneRow(1, Vec2(0.0, 1.0));
  floor.bias = -1.0;
  z.rows = {floor, halfPlaneRow(1, Vec2(1.0, 0.0))};
  const Answers a = solveAllWays(z);
  ASSERT_TRUE(a.gaussSeidelSolved && a.activeSetSolved && a.enumerated);
  for (const auto* v : {&a.gaussSeidel, &a.activeSet, &a.enumeration})
    EXPECT_LT(((*v)[1] - Vec2(0.0, -1.0)).norm(), 1e-9);
}

// Random zones, some rows with a bias of up to the zone's speed: the three solvers agree, the
// active set's answer satisfies the biased KKT conditions (recomputed here: v - v~ = M^-1 G^T l,
// l >= 0, G v >= b, and a row with an impulse is tight), and kinetic energy never grows.
TEST(SpeculativeRows, TheSolversAgreeOnRandomZonesAndGainNoEnergy) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> share(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Zone z = randomZone(rng, /*freeOnly=*/trial % 4 == 3);
    const double scale = speedScale(z.v);
    for (ConstraintRow& r : z.rows) {
      const double draw = share(rng);
      r.bias = draw < 0.5 ? 0.0 : -(draw - 0.5) * 2.0 * scale;
    }
    const Answers a = solveAllWays(z);
    ASSERT_TRUE(a.activeSetSolved);
    const double before = kineticEnergy(z.invMass, z.v);
    EXPECT_LE(kineticEnergy(z.invMass, a.activeSet), before * (1 + 1e-12));
    if (a.gaussSeidelSolved) {
      EXPECT_LE(kineticEnergy(z.invMass, a.gaussSeidel), before * (1 + 1e-12));
    }
    std::vector<Vec2> change(z.v.size(), Vec2::Zero());
    for (size_t k = 0; k < z.rows.size(); ++k)
      for (int j = 0; j < z.rows[k].count; ++j)
        change[z.rows[k].body[j]] += z.invMass[z.rows[k].body[j]] * a.activeSetImpulses[k] * z.rows[k].coef[j];
    for (size_t b = 0; b < z.v.size(); ++b) EXPECT_LE((a.activeSet[b] - z.v[b] - change[b]).norm(), 1e-12 * scale);
    for (size_t k = 0; k < z.rows.size(); ++k) {
      const double w = rowVelocity(z.rows[k], a.activeSet) - z.rows[k].bias;  // G v - b, from the rows
      const double tol = 10 * kSlack * rowNorm(z.rows[k]) * scale;
      EXPECT_GE(a.activeSetImpulses[k], 0.0) << "row " << k;
      EXPECT_GE(w, -tol) << "row " << k;
      if (a.activeSetImpulses[k] > 0.0) {
        EXPECT_LE(w, tol) << "row " << k;
      }
    }
    if (!a.enumerated || !a.gaussSeidelSolved) continue;  // rounding on nearly dependent rows
    ++compared;
    for (size_t b = 0; b < z.v.size(); ++b) {
      EXPECT_LE((a.activeSet[b] - a.enumeration[b]).norm(), 1e-7 * scale) << "body " << b;
      EXPECT_LE((a.gaussSeidel[b] - a.enumeration[b]).norm(), 1e-7 * scale) << "body " << b;
    }
  }
  EXPECT_GT(compared, 900);
}

}  // namespace
}  // namespace fosssim::math
