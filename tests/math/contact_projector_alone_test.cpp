// One body alone against obstacles (ContactProjector::solveAlone): when a row's only movable body
// is in no row with another movable body, its rows are solved at once, exactly, instead of by
// Gauss-Seidel. Expected values come from
//   * a hand derivation: a disk driven into the tip of a narrow V stops (its velocity lies in
//     the polar cone of the walls' normals), and the walls' impulses are the two coefficients of
//     -m v on the normals (Cramer's rule);
//   * the active-set enumeration (projectByEnumeration, zone_projection.cpp), on random bodies
//     against up to eight random rows whose other bodies are immovable, at rest or frozen at a
//     velocity of their own.
#include "fosssim/math/contact_projector.h"
#include "fosssim/math/zone_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kTol = 1e-12;
constexpr long kLargeBudget = 2000000;
/// Enough for every row of a body to come back kAloneAfterUpdates times, and then some.
constexpr long kBudget = 2 * ContactProjector::kAloneRows * ContactProjector::kAloneAfterUpdates;

// Walls 2e-3 rad apart: Gauss-Seidel would contract by cos^2(2e-3) per pair of updates and spend
// any budget (contact_projector_test.cpp, SpentBudgetIsReportedAndAddsNoEnergy). Alone, the disk
// of mass 2 is stopped exactly once a row has come back kAloneAfterUpdates times; the walls'
// impulses l1, l2 solve l1 n1 + l2 n2 = -m v0.
TEST(ContactProjectorAlone, ADiskInTheTipOfANarrowVStopsWithinAFewUpdates) {
  const double a = 1e-3, m = 2.0;
  const Vec2 v0(0.3, -1.0), n1(std::cos(a), std::sin(a)), n2(-std::cos(a), std::sin(a));
  ContactProjector cp;
  cp.reset(1);
  cp.addBody(0, 1.0 / m, v0);
  const int r1 = cp.addRow(halfPlaneRow(0, n1)), r2 = cp.addRow(halfPlaneRow(0, n2));
  ASSERT_TRUE(cp.solve(v0.norm(), kTol, 2 * ContactProjector::kAloneAfterUpdates));  // both rows back that often
  EXPECT_LE(cp.velocity(0).norm(), 1e-12 * v0.norm());
  const Vec2 target = -m * v0;
  const double det = n1.x() * n2.y() - n1.y() * n2.x();
  const double l1 = (target.x() * n2.y() - target.y() * n2.x()) / det;
  const double l2 = (n1.x() * target.y() - n1.y() * target.x()) / det;
  EXPECT_NEAR(cp.impulse(r1), l1, 1e-9 * std::abs(l1));
  EXPECT_NEAR(cp.impulse(r2), l2, 1e-9 * std::abs(l2));
}

// A body against one to eight rows (half-plane rows, and pair and edge rows whose other bodies
// are immovable: at rest, or frozen at a velocity, which shifts the row's line off the origin),
// warm-started or not: one solve equals the enumeration's projection; against obstacles at rest,
// within a few updates per row (Gauss-Seidel alone may need thousands: the V above).
TEST(ContactProjectorAlone, EqualsTheActiveSetProjection) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586), unit01(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int obstacles = std::uniform_int_distribution<int>(1, 3)(rng);
    std::vector<double> invMass{1.0 / (0.1 + 10 * unit01(rng))};
    // Braced Vec2s: x is drawn before y under every compiler (a call's arguments come in an order
    // the compiler picks: gcc right to left, clang left to right).
    std::vector<Vec2> v{Vec2{u(rng), u(rng)}};
    const bool moving = unit01(rng) < 0.5;
    for (int b = 0; b < obstacles; ++b) {
      invMass.push_back(0.0);
      v.push_back(moving && unit01(rng) < 0.7 ? Vec2{u(rng), u(rng)} : Vec2::Zero());
    }
    std::vector<ConstraintRow> rows;
    const int count = std::uniform_int_distribution<int>(1, ContactProjector::kAloneRows)(rng);
    for (int k = 0; k < count; ++k) {
      const Vec2 n = unit(angle(rng));
      const int other = std::uniform_int_distribution<int>(1, obstacles)(rng);
      switch (std::uniform_int_distribution<int>(0, 2)(rng)) {
        case 0: rows.push_back(halfPlaneRow(0, n)); break;
        case 1: rows.push_back(pairRow(other, 0, n)); break;
        default: rows.push_back(edgeRow(0, other, 1 + (other % obstacles), unit01(rng), n)); break;
      }
    }
    std::vector<Vec2> want = v;
    if (!projectByEnumeration(invMass, rows, want)) continue;  // obstacles moving in: infeasible
    ContactProjector cp;
    cp.reset(static_cast<int>(v.size()));
    for (size_t b = 0; b < v.size(); ++b) cp.addBody(static_cast<int>(b), invMass[b], v[b]);
    const bool warm = unit01(rng) < 0.5;
    for (const ConstraintRow& r : rows) cp.addRow(r, warm ? unit01(rng) : 0.0);
    double scale = 0;
    for (const Vec2& x : v) scale = std::max(scale, x.norm());
    // At rest, the obstacles leave a cone through 0, whose projection is never faster than v:
    // solveAlone always takes it. Moving ones can push the body faster than it started, which
    // solveAlone leaves to Gauss-Seidel (the energy guard's rule): then only the result counts.
    ASSERT_TRUE(cp.solve(scale, kTol, moving ? kLargeBudget : kBudget)) << "trial " << trial;
    EXPECT_LE((cp.velocity(0) - want[0]).norm(), 1e-9 * scale) << "trial " << trial;
    for (size_t b = 1; b < v.size(); ++b) EXPECT_EQ(cp.velocity(static_cast<int>(b)), v[b]) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 1000);  // most draws are feasible: the comparison is not vacuous
}

// A second movable body in one of the body's rows: not alone, so Gauss-Seidel goes on (the
// narrow V with a disk riding on the first, tied by their pair's row) until its budget is about
// to end, and then the two bodies are projected exactly together (solveCluster's rescue). The
// projection by hand: the V (half-angle 1e-3 rad about the vertical) lets the first disk move only
// up within the V, v_y >= |v_x| cot(1e-3); the second may not move down relative to it. Both
// start at (0.3, -1): the nearest velocities allowed put the first at the V's vertex, (0, 0), and
// leave the second its sideways 0.3 with v_y = 0 (any v_y > 0 of the first costs both more).
TEST(ContactProjectorAlone, ARowWithASecondMovableBodyIsLeftToGaussSeidelThenTheRescue) {
  const double a = 1e-3;
  const Vec2 v0(0.3, -1.0), n1(std::cos(a), std::sin(a)), n2(-std::cos(a), std::sin(a));
  ContactProjector cp;
  cp.reset(2);
  cp.addBody(0, 1.0, v0);
  cp.addBody(1, 1.0, v0);
  cp.addRow(halfPlaneRow(0, n1));
  cp.addRow(halfPlaneRow(0, n2));
  cp.addRow(pairRow(0, 1, Vec2(0, 1)));
  ASSERT_TRUE(cp.solve(v0.norm(), kTol, 50));
  EXPECT_GT(cp.updates(), 50) << "Gauss-Seidel ran its budget first: not solved alone";
  EXPECT_LE(cp.velocity(0).norm(), 1e-9);
  EXPECT_LE((cp.velocity(1) - Vec2(0.3, 0.0)).norm(), 1e-9);
}

}  // namespace
}  // namespace fosssim::math
