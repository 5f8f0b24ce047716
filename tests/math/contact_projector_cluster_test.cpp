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

// A random cluster: 2 to kClusterBodies free bodies with masses between 10^-2 and 10^2 (log-
// uniform), against up to two obstacles at rest, with 2 to kClusterRows rows of pairs and
// half-planes at random angles.
struct Cluster {
  int free = 0, bodies = 0;
  std::vector<double> invMass;
  std::vector<Vec2> v;
  std::vector<ConstraintRow> rows;
};

Cluster randomCluster(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586), unit01(0.0, 1.0);
  std::uniform_real_distribution<double> logMass(std::log(1e-2), std::log(1e2));
  Cluster c;
  c.free = std::uniform_int_distribution<int>(2, ContactProjector::kClusterBodies)(rng);
  const int obstacles = std::uniform_int_distribution<int>(0, 2)(rng);
  for (int b = 0; b < c.free; ++b) {
    c.invMass.push_back(std::exp(-logMass(rng)));
    c.v.push_back(Vec2{u(rng), u(rng)});  // braced: x drawn before y under every compiler
  }
  for (int b = 0; b < obstacles; ++b) c.invMass.push_back(0.0), c.v.push_back(Vec2::Zero());
  c.bodies = c.free + obstacles;
  const int count = std::uniform_int_distribution<int>(2, ContactProjector::kClusterRows)(rng);
  for (int k = 0; k < count; ++k) {
    const int i = std::uniform_int_distribution<int>(0, c.free - 1)(rng);
    int j = std::uniform_int_distribution<int>(0, c.bodies - 1)(rng);
    if (j == i) j = (i + 1) % c.bodies;
    const Vec2 n = unit(angle(rng));
    if (unit01(rng) < 0.3) c.rows.push_back(halfPlaneRow(i, n));
    else c.rows.push_back(pairRow(i, j, n));
  }
  return c;
}

double massRatio(const Cluster& c) {  // heaviest over lightest free body
  const auto [least, most] = std::minmax_element(c.invMass.begin(), c.invMass.begin() + c.free);
  return *most / *least;
}

// The projection's optimality (KKT) conditions at the solve's end, to its tolerance.
void expectProjection(const ContactProjector& cp, const Cluster& c, int trial) {
  const double scale = speedScale(c.v);
  std::vector<Vec2> applied(c.bodies, Vec2::Zero());  // v* - v0: what the multipliers apply
  for (size_t k = 0; k < c.rows.size(); ++k) {
    const double lambda = cp.impulse(static_cast<int>(k));
    EXPECT_GE(lambda, 0.0) << "trial " << trial;
    for (int m = 0; m < c.rows[k].count; ++m)
      applied[c.rows[k].body[m]] += c.invMass[c.rows[k].body[m]] * lambda * c.rows[k].coef[m];
  }
  const std::vector<Vec2> now = velocities(cp, c.bodies);
  for (int b = 0; b < c.bodies; ++b)
    EXPECT_LE((now[b] - c.v[b] - applied[b]).norm(), 1e-9 * scale) << "trial " << trial;
  const double heaviestInverse = *std::max_element(c.invMass.begin(), c.invMass.end());
  for (size_t k = 0; k < c.rows.size(); ++k) {
    const double w = rowVelocity(c.rows[k], now), slack = 1e-9 * rowNorm(c.rows[k]) * scale;
    EXPECT_GE(w, -slack) << "trial " << trial << " row " << k;
    // Complementarity, scaled: an impulse's row ends with no approach and no separation.
    const double a = cp.impulse(static_cast<int>(k)) * rowNorm(c.rows[k]) * rowNorm(c.rows[k]) * heaviestInverse;
    EXPECT_LE(std::min(a, w), slack) << "trial " << trial << " row " << k;
  }
}

ContactProjector projectorFor(const Cluster& c) {
  ContactProjector cp;
  cp.reset(c.bodies);
  for (int b = 0; b < c.bodies; ++b) cp.addBody(b, c.invMass[b], c.v[b]);
  for (const ConstraintRow& r : c.rows) cp.addRow(r);
  return cp;
}

// Clusters whose heaviest body is at least kClusterMassRatio times the lightest: every solve ends
// within the budget (the cluster is solved exactly when Gauss-Seidel keeps coming back) and at
// the projection.
TEST(ContactProjectorCluster, RandomClustersOfVeryDifferentMassesEndAtTheProjection) {
  std::mt19937 rng(17);
  int solved = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Cluster c = randomCluster(rng);
    if (massRatio(c) < ContactProjector::kClusterMassRatio) continue;  // alike: Gauss-Seidel's
    ContactProjector cp = projectorFor(c);
    ASSERT_TRUE(cp.solve(speedScale(c.v), kTol, kBudget)) << "trial " << trial;
    ++solved;
    expectProjection(cp, c, trial);
  }
  EXPECT_GT(solved, 250);
}

// Any masses, and a budget of 4 updates that Gauss-Seidel alone runs out of on most clusters: a
// solve about to end on its budget solves a cluster this small exactly, and then ends at the
// projection too (a budget-ended solve is a zone's failure, and failures make jams that stop
// particles). Rescued solves are those that made more updates than their budget.
TEST(ContactProjectorCluster, ASolveRunningOutOfBudgetOnASmallClusterEndsAtTheProjection) {
  std::mt19937 rng(29);
  constexpr long kTinyBudget = 4;
  int solved = 0, rescued = 0, trials = 0;
  for (int trial = 0; trial < 400; ++trial, ++trials) {
    const Cluster c = randomCluster(rng);
    ContactProjector cp = projectorFor(c);
    if (!cp.solve(speedScale(c.v), kTol, kTinyBudget)) continue;  // degenerate rows: the zones' budgets go on
    ++solved;
    rescued += cp.updates() > kTinyBudget;
    expectProjection(cp, c, trial);
  }
  EXPECT_GE(solved, trials * 95 / 100);
  EXPECT_GT(rescued, trials / 2);
}

}  // namespace
}  // namespace fosssim::math
