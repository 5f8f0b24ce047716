// A few bodies whose rows move no other body (ContactProjector::solveCluster): when Gauss-Seidel
// keeps coming back to one of their rows, they are projected at once, exactly. Expected values
// come from
//   * a hand derivation: a light disk squeezed between a heavy one and a wall stops across the
//     wall with the heavy one (both rows active), keeping its motion along the wall;
//   * the projection's optimality (KKT) conditions, checked directly on random clusters of bodies
//     whose masses differ by 10 to 10^4: v = v0 + M^-1 G^T lambda, lambda >= 0, G v >= 0, and
//     lambda_k (G v)_k = 0, which hold at the projection and nowhere else (independent of how
//     it was found).
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kTol = 1e-10;  // the zones' (kZoneProjectionTolerance)
/// Enough for a cluster's rows to come back kAloneAfterUpdates times each, and then some; far
/// below what Gauss-Seidel alone needs on the squeezes below (tens of thousands of updates).
constexpr long kBudget = 4 * ContactProjector::kClusterRows * ContactProjector::kAloneAfterUpdates;

// A heavy disk (mass M) moving left at 1 m/s and up at 0.5 pushes a light one (mass m = M / 1000,
// moving up at 2) against a wall x >= 0. Rows: the wall's, n = (1, 0) on the light disk, and the
// pair's, n = (1, 0) from the light disk to the heavy one. The projection stops both across the
// wall (the heavy one's -1 cannot go into the light one, nor the light one into the wall) and
// leaves what is along it: (0, 0.5) and (0, 2). Gauss-Seidel passes a share of about m / M of
// what is left between the two rows per update and would need thousands of sweeps.
TEST(ContactProjectorCluster, ALightDiskSqueezedAgainstAWallStopsWithTheHeavyOne) {
  for (double ratio : {10.0, 1000.0, 1e4}) {
    ContactProjector cp;
    cp.reset(2);
    cp.addBody(0, ratio, Vec2(0.0, 2.0));  // light: inverse mass ratio / M, M = 1
    cp.addBody(1, 1.0, Vec2(-1.0, 0.5));   // heavy
    cp.addRow(halfPlaneRow(0, Vec2(1, 0)));
    cp.addRow(pairRow(0, 1, Vec2(1, 0)));
    ASSERT_TRUE(cp.solve(2.0, kTol, kBudget)) << "ratio " << ratio;
    EXPECT_LE((cp.velocity(0) - Vec2(0.0, 2.0)).norm(), 1e-9) << "ratio " << ratio;
    EXPECT_LE((cp.velocity(1) - Vec2(0.0, 0.5)).norm(), 1e-9) << "ratio " << ratio;
  }
}

// Random clusters: 2 or 3 free bodies with masses between 10^-2 and 10^2, the heaviest at least
// kClusterMassRatio times the lightest, against up to two obstacles at rest, with 2 to 10 rows of
// pairs and half-planes. Every solve ends within the budget and at the projection (KKT, above),
// to the solve's tolerance.
TEST(ContactProjectorCluster, RandomClustersOfVeryDifferentMassesEndAtTheProjection) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586), unit01(0.0, 1.0);
  std::uniform_real_distribution<double> logMass(std::log(1e-2), std::log(1e2));
  int solved = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int free = std::uniform_int_distribution<int>(2, ContactProjector::kClusterBodies)(rng);
    const int obstacles = std::uniform_int_distribution<int>(0, 2)(rng);
    std::vector<double> invMass;
    std::vector<Vec2> v;
    for (int b = 0; b < free; ++b) invMass.push_back(std::exp(-logMass(rng))), v.push_back(Vec2(u(rng), u(rng)));
    const auto [least, most] = std::minmax_element(invMass.begin(), invMass.end());  // inverse masses
    if (*most < ContactProjector::kClusterMassRatio * *least) continue;  // alike: Gauss-Seidel's
    for (int b = 0; b < obstacles; ++b) invMass.push_back(0.0), v.push_back(Vec2::Zero());
    const int bodies = free + obstacles;
    std::vector<ConstraintRow> rows;
    const int count = std::uniform_int_distribution<int>(2, ContactProjector::kClusterRows)(rng);
    for (int k = 0; k < count; ++k) {
      const int i = std::uniform_int_distribution<int>(0, free - 1)(rng);
      int j = std::uniform_int_distribution<int>(0, bodies - 1)(rng);
      if (j == i) j = (i + 1) % bodies;
      const Vec2 n = unit(angle(rng));
      if (unit01(rng) < 0.3) rows.push_back(halfPlaneRow(i, n));
      else rows.push_back(pairRow(i, j, n));
    }
    ContactProjector cp;
    cp.reset(bodies);
    for (int b = 0; b < bodies; ++b) cp.addBody(b, invMass[b], v[b]);
    for (const ConstraintRow& r : rows) cp.addRow(r);
    const double scale = speedScale(v);
    ASSERT_TRUE(cp.solve(scale, kTol, kBudget)) << "trial " << trial;
    ++solved;
    // KKT: the multipliers are the rows' impulses; v* - v0 is what they apply.
    std::vector<Vec2> applied(bodies, Vec2::Zero());
    for (int k = 0; k < count; ++k) {
      const double lambda = cp.impulse(k);
      EXPECT_GE(lambda, 0.0) << "trial " << trial;
      for (int m = 0; m < rows[k].count; ++m)
        applied[rows[k].body[m]] += invMass[rows[k].body[m]] * lambda * rows[k].coef[m];
    }
    const std::vector<Vec2> now = velocities(cp, bodies);
    for (int b = 0; b < bodies; ++b) EXPECT_LE((now[b] - v[b] - applied[b]).norm(), 1e-9 * scale) << "trial " << trial;
    for (int k = 0; k < count; ++k) {
      const double w = rowVelocity(rows[k], now), slack = 1e-9 * rowNorm(rows[k]) * scale;
      EXPECT_GE(w, -slack) << "trial " << trial << " row " << k;
      // Complementarity, scaled: an impulse's row ends with no approach and no separation.
      const double a = cp.impulse(k) * rowNorm(rows[k]) * rowNorm(rows[k]) * *std::max_element(invMass.begin(), invMass.end());
      EXPECT_LE(std::min(a, w), slack) << "trial " << trial << " row " << k;
    }
  }
  EXPECT_GT(solved, 250);
}

}  // namespace
}  // namespace fosssim::math
