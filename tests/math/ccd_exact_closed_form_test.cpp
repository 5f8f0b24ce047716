// exactPP/PE/PH on contacts worked out by hand: a head-on pair, a disk onto a capsule's cap or
// straight above an endpoint, a degenerate edge, grazing and separating pairs, pairs that start
// overlapping; and at extreme scales: normals of any magnitude, tiny disks, huge speeds, non-finite
// input. (Random scenes against the reference and brute force: ccd_exact_test.cpp.)
#include "fosssim/math/ccd.h"
#include "fosssim/math/ccd_exact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fosssim::math {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(ExactCcdClosedForm, HeadOnPair) {
  // Centres 3 apart, radii 0.25 + 0.75: gap 2, closing 0.5 + 2.5 per step: tau = 2/3.
  ExactContact c;
  ASSERT_EQ(exactPP({{0.0, 0.0}, {0.5, 0.0}, 0.25, {3.0, 0.0}, {-2.5, 0.0}, 0.75}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR((c.normal - Vec2(1.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(c.alpha, 0.0);
}

TEST(ExactCcdClosedForm, DiskOntoCapsuleCap) {
  // Edge (0,0)-(1,0) of radius 0.1 (its endpoint particles' radius 0.01 plays no part), disk of
  // radius 0.05 falling by 1 from 0.5 above a point 0.03 beyond an end. Contact when the distance
  // to the endpoint reaches 0.15: 0.03^2 + y^2 = 0.15^2, y = sqrt(0.0216), tau = 0.5 - y.
  const double y = std::sqrt(0.0216);
  for (int end = 0; end < 2; ++end) {
    const double x = end == 0 ? -0.03 : 1.03;
    const Vec2 endpoint(end == 0 ? 0.0 : 1.0, 0.0);
    PEInput in{{x, 0.5}, {0.0, -1.0}, 0.05, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 0.1};
    ExactContact c;
    ASSERT_EQ(exactPE(in, &c), CcdOutcome::Hit);
    EXPECT_NEAR(c.tau, 0.5 - y, 1e-14);
    EXPECT_EQ(c.alpha, static_cast<double>(end));
    EXPECT_NEAR((c.normal - (endpoint - Vec2(x, y)) / 0.15).norm(), 0.0, 1e-13);
    EXPECT_FALSE(detectPE(in, nullptr));  // the reference protects only alpha in (0, 1)
    // The same contact seen from the edge's frame: the edge rises into a resting disk.
    in.d2 = in.d3 = -in.d1;
    in.d1 = Vec2::Zero();
    ASSERT_EQ(exactPE(in, &c), CcdOutcome::Hit);
    EXPECT_NEAR(c.tau, 0.5 - y, 1e-14);
    EXPECT_EQ(c.alpha, static_cast<double>(end));
  }
}

TEST(ExactCcdClosedForm, DiskStraightAboveAnEndpoint) {
  // alpha is exactly 1 throughout: the cap's side condition is the zero polynomial and is
  // skipped. Contact at height 0.15: tau = 0.35. Rotated by 30 degrees (alpha then 1 only to
  // rounding) the same contact must be found.
  for (double angle : {0.0, M_PI / 6.0}) {
    Eigen::Matrix2d rot;
    rot << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    const PEInput in{rot * Vec2(1.0, 0.5), rot * Vec2(0.0, -1.0), 0.05, {0.0, 0.0}, {0.0, 0.0},
                     rot * Vec2(1.0, 0.0), {0.0, 0.0}, 0.1};
    ExactContact c;
    ASSERT_EQ(exactPE(in, &c), CcdOutcome::Hit) << angle;
    EXPECT_NEAR(c.tau, 0.35, 1e-14) << angle;
    EXPECT_NEAR(c.alpha, 1.0, 1e-12) << angle;
    EXPECT_NEAR((c.normal - rot * Vec2(0.0, -1.0)).norm(), 0.0, 1e-12) << angle;
  }
}

TEST(ExactCcdClosedForm, DegenerateEdgeIsADisk) {
  // x2 = x3: a disk of radius re. Head on: gap 2 - 0.3, closing 2: tau = 0.85.
  const PEInput in{{-1.0, 0.0}, {2.0, 0.0}, 0.2, {1.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 0.1};
  ExactContact c;
  ASSERT_EQ(exactPE(in, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.85, 1e-15);
}

TEST(ExactCcdClosedForm, GrazingAndSeparatingPairsMiss) {
  // Passing at exactly the radius sum (a tangent graze), and just outside it.
  EXPECT_EQ(exactPP({{0.0, 0.0}, {0.0, 0.0}, 0.5, {-1.0, 1.0}, {2.0, 0.0}, 0.5}, nullptr), CcdOutcome::Miss);
  EXPECT_EQ(exactPP({{0.0, 0.0}, {0.0, 0.0}, 0.5, {-1.0, 1.01}, {2.0, 0.0}, 0.5}, nullptr), CcdOutcome::Miss);
  EXPECT_EQ(exactPH({{0.0, 0.1}, {1.0, 0.0}, 0.1, {0.0, 0.0}, {0.0, 1.0}}, nullptr), CcdOutcome::Miss);
  // Sliding along the capsule's surface, then past its cap.
  EXPECT_EQ(exactPE({{-0.5, 0.25}, {2.0, 0.0}, 0.125, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 0.125},
                    nullptr),
            CcdOutcome::Miss);
  // Moving apart.
  EXPECT_EQ(exactPP({{0.0, 0.0}, {-1.0, 0.0}, 0.5, {2.0, 0.0}, {1.0, 0.0}, 0.5}, nullptr), CcdOutcome::Miss);
}

TEST(ExactCcdClosedForm, OverlapAtStartApproachingIsZeroSeparatingIsMiss) {
  ExactContact c;
  EXPECT_EQ(exactPP({{0.0, 0.0}, {0.0, 0.0}, 0.5, {0.5, 0.0}, {-0.1, 0.0}, 0.5}, &c), CcdOutcome::Hit);
  EXPECT_EQ(c.tau, 0.0);
  EXPECT_EQ(exactPP({{0.0, 0.0}, {0.0, 0.0}, 0.5, {0.5, 0.0}, {0.1, 0.0}, 0.5}, &c), CcdOutcome::Miss);
  const PEInput towards{{0.4, 0.1}, {0.0, -0.1}, 0.1, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 0.05};
  ASSERT_EQ(exactPE(towards, &c), CcdOutcome::Hit);
  EXPECT_EQ(c.tau, 0.0);
  EXPECT_NEAR(c.alpha, 0.4, 1e-15);
  EXPECT_NEAR((c.normal - Vec2(0.0, -1.0)).norm(), 0.0, 1e-15);
  PEInput away = towards;
  away.d1 = Vec2(0.0, 0.1);
  EXPECT_EQ(exactPE(away, &c), CcdOutcome::Miss);
  // Overlapping a cap at the start: approaching is 0, leaving is a miss.
  const PEInput cap{{1.1, 0.0}, {-0.1, 0.0}, 0.1, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 0.05};
  ASSERT_EQ(exactPE(cap, &c), CcdOutcome::Hit);
  EXPECT_EQ(c.tau, 0.0);
  EXPECT_EQ(c.alpha, 1.0);
  PEInput capAway = cap;
  capAway.d1 = Vec2(0.1, 0.05);
  EXPECT_EQ(exactPE(capAway, &c), CcdOutcome::Miss);
  EXPECT_EQ(exactPH({{0.0, 0.05}, {0.0, -0.1}, 0.1, {0.0, 0.0}, {0.0, 2.0}}, &c), CcdOutcome::Hit);
  EXPECT_EQ(c.tau, 0.0);
  EXPECT_EQ(exactPH({{0.0, 0.05}, {0.0, 0.1}, 0.1, {0.0, 0.0}, {0.0, 2.0}}, &c), CcdOutcome::Miss);
}

// ------------------------------------------------------------ extreme scales

TEST(ExactCcdScale, HalfPlaneNormalMagnitudeDoesNotMatter) {
  // Ball at height 0.5 (radius 0.1) falling by 1 onto y = 0: (0.5 - t)^2 = 0.1^2 at t = 0.4.
  for (double k : {1e-5, 1.0, 1e5, 1e155, 1e200}) {
    ExactContact c;
    ASSERT_EQ(exactPH({{0.3, 0.5}, {0.0, -1.0}, 0.1, {7.0, 0.0}, {0.0, k}}, &c), CcdOutcome::Hit) << k;
    EXPECT_NEAR(c.tau, 0.4, 1e-15) << k;
    EXPECT_EQ(c.normal, Vec2(0.0, -1.0)) << k;
    // A tilted normal (3, 4)/5 and a ball 0.5 above the boundary along it.
    const Vec2 n(0.6, 0.8);
    ASSERT_EQ(exactPH({Vec2(1.0, 2.0) + 0.5 * n, -n, 0.1, {1.0, 2.0}, k * Vec2(3.0, 4.0)}, &c), CcdOutcome::Hit);
    EXPECT_NEAR(c.tau, 0.4, 1e-14) << k;
    EXPECT_NEAR((c.normal + n).norm(), 0.0, 1e-15) << k;
  }
}

TEST(ExactCcdScale, TinyDisksAndTinyPairs) {
  ExactContact c;
  // Radius 1e-9 disks at unit coordinates, 3e-9 apart, closing by 2e-9: gap 1e-9, tau 1/2.
  ASSERT_EQ(exactPP({{1.0, 1.0}, {0.0, 0.0}, 1e-9, {1.0 + 3e-9, 1.0}, {-2e-9, 0.0}, 1e-9}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5, 1e-6);  // the coordinates themselves carry rounding of 1e-16 / 1e-9
  // The same at the origin: exact to rounding.
  ASSERT_EQ(exactPP({{0.0, 0.0}, {0.0, 0.0}, 1e-9, {3e-9, 0.0}, {-2e-9, 0.0}, 1e-9}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5, 1e-12);
  // A head-on pair at the 1e-6 scale: gap 2e-6 - 1e-6, closing 4e-6.
  ASSERT_EQ(exactPP({{0.0, 0.0}, {2e-6, 0.0}, 0.5e-6, {2e-6, 0.0}, {-2e-6, 0.0}, 0.5e-6}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.25, 1e-12);
  EXPECT_NEAR((c.normal - Vec2(1.0, 0.0)).norm(), 0.0, 1e-15);
}

TEST(ExactCcdScale, SmallFastDisksDoNotTunnel) {
  // Radius 1e-9 moving 2 per step toward a target 1 away: expanded, R^2 - |x|^2 rounds to
  // -|x|^2 and the overlap interval (about 1e-9 long) vanishes. Gap 1 - 2e-9, closing 2.
  ExactContact c;
  ASSERT_EQ(exactPP({{0.0, 0.0}, {2.0, 0.0}, 1e-9, {1.0, 0.0}, {0.0, 0.0}, 1e-9}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5 - 1e-9, 1e-15);
  // Off-centre by 1.5e-9 (< 2e-9): contact when the centres are 2e-9 apart, i.e. 1.3228757e-9
  // before the centres align along x: tau = (1 - sqrt(4 - 2.25) 1e-9) / 2.
  ASSERT_EQ(exactPP({{0.0, 0.0}, {2.0, 0.0}, 1e-9, {1.0, 1.5e-9}, {0.0, 0.0}, 1e-9}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, (1.0 - std::sqrt(1.75) * 1e-9) / 2.0, 1e-15);
  EXPECT_EQ(exactPP({{0.0, 0.0}, {2.0, 0.0}, 1e-9, {1.0, 2.5e-9}, {0.0, 0.0}, 1e-9}, &c), CcdOutcome::Miss);
  ASSERT_EQ(exactPH({{0.0, 1.0}, {0.0, -2.0}, 1e-9, {0.0, 0.0}, {0.0, 1.0}}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5 - 0.5e-9, 1e-15);
  // A cap: the same bullet along the edge's line onto its end (closest point the endpoint).
  ASSERT_EQ(exactPE({{-1.0, 0.0}, {2.0, 0.0}, 1e-9, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 1e-9}, &c),
            CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5 - 1e-9, 1e-15);
  EXPECT_EQ(c.alpha, 0.0);
}

// A thin disk falling straight onto the middle of a long, thin edge: contact when its centre is
// R = rv + re above the line, tau = (y0 - R) / speed, whatever the edge's length. The interior's
// distance condition, expanded as |e|^2 |w|^2 - (w.e)^2, cancelled R^2 away once R fell below
// some 1e-8 of the edge's half-length L: the disk crossed the edge unseen (L = 1, r = 1e-8), hit
// late, or took a ghost impulse 100 radii away (R/L = 1e-11). Lagrange's form (w x e)^2 keeps it.
TEST(ExactCcdScale, ThinDisksOntoTheMiddleOfLongEdges) {
  for (double L : {1.0, 100.0, 1e4, 1e6}) {
    for (double r : {1e-3, 1e-6, 1e-8, 1e-10}) {
      const double re = r / 100, R = r + re, y0 = 100 * r, speed = 300 * r;
      SCOPED_TRACE("L " + std::to_string(L) + ", r " + std::to_string(r));
      ExactContact c;
      const PEInput in{{0.0, y0}, {0.0, -speed}, r, {-L, 0.0}, {0.0, 0.0}, {L, 0.0}, {0.0, 0.0}, re};
      ASSERT_EQ(exactPE(in, &c), CcdOutcome::Hit);
      EXPECT_NEAR(c.tau, (y0 - R) / speed, 1e-12);
      EXPECT_NEAR(c.alpha, 0.5, 1e-12);
      EXPECT_NEAR(std::fabs(c.normal.y()), 1.0, 1e-12);
      // The same disk passing R / 2 beside the edge's line, parallel to it, never touches.
      const PEInput beside{{-L / 2, 1.5 * R}, {L, 0.0}, r, {-L, 0.0}, {0.0, 0.0}, {L, 0.0}, {0.0, 0.0}, re};
      EXPECT_EQ(exactPE(beside, &c), CcdOutcome::Miss);
    }
  }
}

TEST(ExactCcdScale, HugeSpeedsAndNormalsStillDetect) {
  // Displacements of 1e160 (their squares overflow in ccd.h's polynomials). What normalisation
  // cannot remove is the ratio within one pair: a radius below ~1e-16 of the displacement
  // makes the contact shorter than the resolution of tau, so the scenes are commensurate.
  ExactContact c;
  // Gap 0.5e160 - 1e150, closing 1e160 per step: tau = 0.5 - 1e-10.
  ASSERT_EQ(exactPP({{0.0, 0.0}, {0.0, 0.0}, 0.5e150, {0.5e160, 0.0}, {-1e160, 0.0}, 0.5e150}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5 - 1e-10, 1e-15);
  ASSERT_EQ(exactPH({{0.0, 0.5e160}, {0.0, -1e160}, 1e150, {0.0, 0.0}, {0.0, 1.0}}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.5 - 1e-10, 1e-15);
  // Edge of length 1e159 and radius 0.25e159, disk of that radius falling 1e160 from
  // 0.5e160 above its middle: contact at height 0.5e159, tau = 0.45.
  ASSERT_EQ(exactPE({{0.5e159, 0.5e160}, {0.0, -1e160}, 0.25e159, {0.0, 0.0}, {0.0, 0.0}, {1e159, 0.0}, {0.0, 0.0},
                     0.25e159},
                    &c),
            CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, 0.45, 1e-15);
  EXPECT_NEAR(c.alpha, 0.5, 1e-15);
  // Normals of 1e155 (|m|^2 overflows): distance 0.5 along (1, 1)/sqrt 2 is 0.5/sqrt 2.
  ASSERT_EQ(exactPH({{0.0, 0.5}, {0.0, -1.0}, 0.1, {0.0, 0.0}, {1e155, 1e155}}, &c), CcdOutcome::Hit);
  EXPECT_NEAR(c.tau, (0.5 * std::sqrt(0.5) - 0.1) / (std::sqrt(0.5)), 1e-14);
}

TEST(ExactCcdScale, PairsAtTheEndsOfTheDoubleRangeKeepTheirAnswer) {
  // HeadOnPair's numbers made integers (centres 12 apart, radii 1 and 3, closing 2 + 10 per
  // step: gap 8, tau = 2/3) and scaled by 2^k. A power of two is exact for integer multiples of
  // the smallest subnormal, 2^-1074, and below 2^1024: so the pair's largest magnitude lies in
  // the subnormal range (k = -1070: 12 2^-1070 < 2^-1022) or above 2^1022 (k = 1019), where
  // 2^-e is not a normal double and the normalisation takes two halves. Its answer is the
  // unit-scale pair's, and 2/3 to rounding.
  const auto scaled = [](int k) {
    const auto v = [k](double x, double y) { return Vec2(std::ldexp(x, k), std::ldexp(y, k)); };
    return PPInput{v(0, 0), v(2, 0), std::ldexp(1.0, k), v(12, 0), v(-10, 0), std::ldexp(3.0, k)};
  };
  ExactContact unit;
  ASSERT_EQ(exactPP(scaled(0), &unit), CcdOutcome::Hit);
  EXPECT_NEAR(unit.tau, 2.0 / 3.0, 1e-15);
  for (int k : {-1070, -1060, -1030, 1000, 1019}) {
    SCOPED_TRACE(k);
    const PPInput in = scaled(k);
    ASSERT_EQ(std::ldexp(in.x2.x(), -k), 12.0);  // represented exactly
    ExactContact c;
    ASSERT_EQ(exactPP(in, &c), CcdOutcome::Hit);
    EXPECT_EQ(c.tau, unit.tau);
    EXPECT_EQ(c.normal, unit.normal);
  }
  EXPECT_LT(std::ldexp(12.0, -1070), std::numeric_limits<double>::min());  // subnormal indeed
  EXPECT_GT(std::ldexp(12.0, 1019), std::ldexp(1.0, 1022));
}

TEST(ExactCcdScale, NonFiniteGivesOverflow) {
  const PPInput pp{{0.0, 0.0}, {1.0, 0.0}, 0.5, {2.0, 0.0}, {0.0, 0.0}, 0.5};
  const PEInput pe{{0.5, 1.0}, {0.0, -1.0}, 0.1, {0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}, {0.0, 0.0}, 0.1};
  const PHInput ph{{0.0, 1.0}, {0.0, -1.0}, 0.1, {0.0, 0.0}, {0.0, 1.0}};
  for (double bad : {kNaN, kInf, -kInf})
    for (int field = 0; field < 3; ++field) {  // one input field of each query made non-finite
      PPInput a = pp;
      PEInput b = pe;
      PHInput h = ph;
      double* const aField[] = {&a.x1.x(), &a.d2.y(), &a.r2};
      double* const bField[] = {&b.x3.y(), &b.d1.x(), &b.re};
      double* const hField[] = {&h.m.x(), &h.p.y(), &h.d1.y()};
      *aField[field] = *bField[field] = *hField[field] = bad;
      EXPECT_EQ(exactPP(a, nullptr), CcdOutcome::Overflow) << "field " << field << " = " << bad;
      EXPECT_EQ(exactPE(b, nullptr), CcdOutcome::Overflow) << "field " << field << " = " << bad;
      EXPECT_EQ(exactPH(h, nullptr), CcdOutcome::Overflow) << "field " << field << " = " << bad;
    }
  // Finite inputs whose difference overflows, and a normal that cannot be normalised.
  EXPECT_EQ(exactPP({{-1.5e308, 0.0}, {0.0, 0.0}, 0.5, {1.5e308, 0.0}, {0.0, 0.0}, 0.5}, nullptr),
            CcdOutcome::Overflow);
  EXPECT_EQ(exactPH({{0.0, 1.0}, {0.0, -1.0}, 0.1, {0.0, 0.0}, {0.0, 0.0}}, nullptr), CcdOutcome::Overflow);
}

}  // namespace
}  // namespace fosssim::math
