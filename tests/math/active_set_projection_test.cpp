// The exact projection by the dual active-set method against what it promises: the enumeration's
// answer on random zones, the KKT conditions checked from scratch on zones too large to
// enumerate (for this convex problem they certify the optimum, whoever computed it), closed forms
// derived by hand, honest failure on infeasible rows, and independence of the units.
#include "fosssim/math/active_set_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h

constexpr double kSlack = 1e-9;  // the feasibility slack asked of the solver, relative (as the projector asks)

// Every random zone has a body fixed at rest, so v = 0 satisfies all its rows: the solver must
// find the optimum, and it must be the enumeration's (v* is unique; the impulses need not be).
TEST(ActiveSetProjection, MatchesTheEnumerationOnRandomZones) {
  std::mt19937 rng(1983);
  for (int trial = 0; trial < 2000; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Zone z = randomZone(rng, /*freeOnly=*/trial % 4 == 3);
    std::vector<Vec2> ref = z.v, v = z.v;
    std::vector<double> refImpulses, impulses;
    const bool enumerated = projectByEnumeration(z.invMass, z.rows, ref, kSlack, refImpulses);
    ASSERT_TRUE(projectByActiveSet(z.invMass, z.rows, v, kSlack, impulses));
    expectKkt(z, v, impulses, 10 * kSlack);
    EXPECT_LE(kineticEnergy(z.invMass, v), kineticEnergy(z.invMass, z.v) * (1 + 1e-12));
    if (!enumerated) continue;  // the enumeration's own rounding on nearly dependent rows
    for (size_t b = 0; b < z.v.size(); ++b) EXPECT_LE((v[b] - ref[b]).norm(), 1e-7 * speedScale(z.v)) << "body " << b;
  }
}

// Zones of 8 to 16 movable bodies and 20 to 64 rows (2^64 active sets: no enumeration), checked
// by their KKT conditions, and against Gauss-Seidel (ZoneProjector) where that converges.
TEST(ActiveSetProjection, SatisfiesKktOnZonesTooLargeToEnumerate) {
  std::mt19937 rng(2005);
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586), logMass(-2.0, 2.0);
  ZoneProjector gaussSeidel;
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    Zone z;
    const int movable = std::uniform_int_distribution<int>(8, kMaxActiveSetMovable)(rng);
    z.invMass.push_back(0.0), z.v.push_back(Vec2::Zero());  // body 0: an obstacle at rest
    for (int b = 0; b < movable; ++b) {
      z.invMass.push_back(std::exp(-logMass(rng)));
      z.v.push_back(Vec2{u(rng), u(rng)});
    }
    const int rows = std::uniform_int_distribution<int>(20, kMaxActiveSetRows)(rng);
    std::uniform_int_distribution<int> body(0, movable);
    for (int k = 0; k < rows; ++k) {
      const int i = body(rng);
      int j = body(rng);
      while (j == i) j = body(rng);
      const Vec2 n = unit(angle(rng));
      z.rows.push_back(i == 0 ? halfPlaneRow(j, n) : pairRow(i, j, n));
    }
    std::vector<Vec2> v = z.v, pgs = z.v;
    std::vector<double> impulses;
    ASSERT_TRUE(projectByActiveSet(z.invMass, z.rows, v, kSlack, impulses));
    expectKkt(z, v, impulses, 10 * kSlack);
    EXPECT_LE(kineticEnergy(z.invMass, v), kineticEnergy(z.invMass, z.v) * (1 + 1e-12));
    if (!gaussSeidel.project(z.invMass, z.rows, pgs).converged) continue;
    ++compared;
    for (size_t b = 0; b < z.v.size(); ++b) EXPECT_LE((v[b] - pgs[b]).norm(), 1e-6 * speedScale(z.v)) << "body " << b;
  }
  EXPECT_GT(compared, 20);  // Gauss-Seidel converges on enough of them to be a second witness
}

// Two disks head-on along x, masses 1 and 3 at +1 and -1 m/s: a perfectly inelastic collision,
// both at the centre of mass's (1 - 3) / 4 = -0.5 m/s; the impulse is the first disk's momentum
// change, 1 * (1 - (-0.5)) = 1.5.
TEST(ActiveSetProjection, HeadOnDisksMeetAtTheirCentreOfMassVelocity) {
  std::vector<Vec2> v = {Vec2(1, 0.25), Vec2(-1, 0)};
  std::vector<double> impulses;
  ASSERT_TRUE(projectByActiveSet({1.0, 1.0 / 3.0}, {pairRow(0, 1, Vec2(1, 0))}, v, kSlack, impulses));
  EXPECT_NEAR(v[0].x(), -0.5, 1e-14);
  EXPECT_NEAR(v[1].x(), -0.5, 1e-14);
  EXPECT_EQ(v[0].y(), 0.25);  // across the normal: kept
  EXPECT_NEAR(impulses[0], 1.5, 1e-14);
}

// A heavy disk (10^6 kg, +1 m/s) drives a light one (1 kg, at rest) into a wall on its right:
// rows v_l - v_h >= 0 and -v_l >= 0 allow only v_h <= v_l <= 0, and the closest such velocities
// in the mass norm are both 0. The pair's impulse stops the heavy disk, 10^6 * 1; the light disk
// keeps 0, so the wall's impulse equals the pair's. Gauss-Seidel passes on a share of 10^-6 per
// update here and stalls.
TEST(ActiveSetProjection, ALightDiskBetweenAHeavyOneAndAWallStopsBoth) {
  std::vector<Vec2> v = {Vec2(1, 0), Vec2(0, 0)};
  std::vector<double> impulses;
  ASSERT_TRUE(projectByActiveSet({1e-6, 1.0}, {pairRow(0, 1, Vec2(1, 0)), halfPlaneRow(1, Vec2(-1, 0))}, v, kSlack,
                                 impulses));
  EXPECT_NEAR(v[0].x(), 0.0, 1e-12);
  // The light disk's velocity is the difference of two impulses of 10^6 over its mass of 1: an
  // ulp of 10^6 is 1.2e-10, within the slack asked for (1e-9 of the speed 1).
  EXPECT_NEAR(v[1].x(), 0.0, kSlack);
  EXPECT_NEAR(impulses[0], 1e6, 1e-6);
  EXPECT_NEAR(impulses[1], 1e6, 1e-6);
}

// A disk moving at (-1, -1) into the corner of a floor and a wall, with a third row through the
// corner at 45 degrees and the floor's row twice: four rows on two unknowns, so dependent active
// sets are met. v* = 0, and the impulses together take the disk's momentum along each axis.
TEST(ActiveSetProjection, DependentAndRepeatedRowsInACorner) {
  const Vec2 diagonal = Vec2(1, 1).normalized();
  const std::vector<ConstraintRow> rows = {halfPlaneRow(0, Vec2(0, 1)), halfPlaneRow(0, Vec2(1, 0)),
                                           halfPlaneRow(0, diagonal), halfPlaneRow(0, Vec2(0, 1))};
  std::vector<Vec2> v = {Vec2(-1, -1)};
  std::vector<double> impulses;
  ASSERT_TRUE(projectByActiveSet({0.5}, rows, v, kSlack, impulses));
  EXPECT_LE(v[0].norm(), 1e-14);
  Vec2 total = Vec2::Zero();  // m (v* - v~) = sum of impulses along their normals = 2 * (1, 1)
  for (size_t k = 0; k < rows.size(); ++k) total += impulses[k] * rows[k].coef[0];
  EXPECT_NEAR(total.x(), 2.0, 1e-13);
  EXPECT_NEAR(total.y(), 2.0, 1e-13);
}

// A row closing by less than the slack the caller accepts is still solved (kActiveSetJoin): a
// disk at (1, -1e-11) m/s on a floor, slack 1e-9, ends at (1, 0) with an impulse of m 1e-11. Left
// closing, such rows came back to the failsafe as contacts that still close.
TEST(ActiveSetProjection, ARowClosingWithinTheSlackIsStillSolved) {
  std::vector<Vec2> v = {Vec2(1.0, -1e-11)};
  std::vector<double> impulses;
  ASSERT_TRUE(projectByActiveSet({0.5}, {halfPlaneRow(0, Vec2(0, 1))}, v, kSlack, impulses));
  EXPECT_EQ(v[0].x(), 1.0);
  EXPECT_GE(v[0].y(), -kActiveSetJoin);
  EXPECT_NEAR(impulses[0], 2e-11, 1e-24);
}

// A disk between two obstacles that close on it (each at 1 m/s): v >= 1 and v <= -1 along x. No
// velocity satisfies both: false, and the velocities untouched.
TEST(ActiveSetProjection, RowsThatCannotAllHoldReturnFalse) {
  const std::vector<Vec2> start = {Vec2(0, 0), Vec2(1, 0), Vec2(-1, 0)};
  std::vector<Vec2> v = start;
  std::vector<double> impulses;
  EXPECT_FALSE(projectByActiveSet({1.0, 0.0, 0.0}, {pairRow(1, 0, Vec2(1, 0)), pairRow(0, 2, Vec2(1, 0))}, v, kSlack,
                                  impulses));
  EXPECT_EQ(v, start);
  // Obstacles alone closing on each other: nothing can be moved to satisfy them.
  EXPECT_FALSE(projectByActiveSet({0.0, 0.0}, {pairRow(0, 1, Vec2(1, 0))}, v = {Vec2(1, 0), Vec2(-1, 0)}, kSlack,
                                  impulses));
}

TEST(ActiveSetProjection, MoreMovableBodiesThanItsLimitReturnFalse) {
  std::vector<double> invMass(kMaxActiveSetMovable + 1, 1.0);
  std::vector<Vec2> v(invMass.size(), Vec2(1, 0));
  std::vector<double> impulses;
  EXPECT_FALSE(projectByActiveSet(invMass, {pairRow(0, 1, Vec2(1, 0))}, v, kSlack, impulses));
}

// Velocities times s, masses over s and every coefficient times s (a row's normal need not be
// unit), for s of 1e-6 and 1e6: the problem scales its velocities by s, and so must v*.
TEST(ActiveSetProjection, TheAnswerDoesNotDependOnTheUnits) {
  std::mt19937 rng(61);
  for (int trial = 0; trial < 100; ++trial) {
    const Zone z = randomZone(rng);
    std::vector<Vec2> base = z.v;
    std::vector<double> impulses;
    ASSERT_TRUE(projectByActiveSet(z.invMass, z.rows, base, kSlack, impulses));
    for (const double s : {1e-6, 1e6}) {
      Zone scaled = z;
      for (Vec2& x : scaled.v) x *= s;
      for (double& w : scaled.invMass) w *= s;  // masses over s
      for (ConstraintRow& r : scaled.rows)
        for (int j = 0; j < r.count; ++j) r.coef[j] *= s;
      std::vector<Vec2> v = scaled.v;
      ASSERT_TRUE(projectByActiveSet(scaled.invMass, scaled.rows, v, kSlack, impulses));
      for (size_t b = 0; b < v.size(); ++b)
        EXPECT_LE((v[b] / s - base[b]).norm(), 1e-9 * speedScale(z.v)) << "trial " << trial << " s " << s;
    }
  }
}

}  // namespace
}  // namespace fosssim::math
