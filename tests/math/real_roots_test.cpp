#include "fosssim/math/real_roots.h"

#include "test_polynomials.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <initializer_list>
#include <vector>

namespace fosssim::math {
namespace {

using testing::fromRoots;

std::vector<double> roots(const Polynomial& p, double tMax = 1.0) {
  double r[kMaxRoots];
  const int n = realRootsInInterval(p, tMax, r);
  return std::vector<double>(r, r + n);
}

TEST(QuadraticRoots, NoCancellationForTheSmallRoot) {
  // t^2 - 1e8 t + 1: roots 1e8 and 1e-8; the naive formula loses the small one entirely.
  double r[2];
  ASSERT_EQ(quadraticRoots(1.0, -1e8, 1.0, r), 2);
  EXPECT_NEAR(r[0], 1e-8, 1e-22);
  EXPECT_NEAR(r[1], 1e8, 1e-6);
}

TEST(QuadraticRoots, DoubleRootAndNoRoot) {
  double r[2];
  ASSERT_EQ(quadraticRoots(1.0, -1.0, 0.25, r), 1);  // (t - 1/2)^2, D = 0 exactly
  EXPECT_EQ(r[0], 0.5);
  const double third = 1.0 / 3.0;  // (t - 1/3)^2 after rounding: D is noise, still double
  ASSERT_EQ(quadraticRoots(1.0, -2.0 * third, third * third, r), 1);
  EXPECT_NEAR(r[0], third, 1e-15);
  EXPECT_EQ(quadraticRoots(1.0, 0.0, 1.0, r), 0);
  ASSERT_EQ(quadraticRoots(-2.0, 0.0, 0.0, r), 1);  // -2t^2: double root at 0, no 0/0
  EXPECT_EQ(r[0], 0.0);
}

TEST(Bernstein, CoefficientsOfKnownPolynomial) {
  // t^3 on [0,1] has Bernstein coefficients (0, 0, 0, 1); on [0,2] (0, 0, 0, 8).
  double b[Polynomial::kMaxCoeffs];
  const Polynomial p = Polynomial::fromHighestFirst({1.0, 0.0, 0.0, 0.0});
  ASSERT_EQ(bernsteinCoefficients(p, 1.0, b), 3);
  EXPECT_EQ(b[0], 0.0);
  EXPECT_EQ(b[1], 0.0);
  EXPECT_EQ(b[2], 0.0);
  EXPECT_EQ(b[3], 1.0);
  bernsteinCoefficients(p, 2.0, b);
  EXPECT_EQ(b[3], 8.0);
  // 1 - 3t + 3t^2 (degree 2): b = (1, -1/2, 1)
  bernsteinCoefficients(Polynomial::fromHighestFirst({3.0, -3.0, 1.0}), 1.0, b);
  EXPECT_DOUBLE_EQ(b[1], -0.5);
  EXPECT_DOUBLE_EQ(b[2], 1.0);
}

TEST(Bernstein, SignVariationsSkipZeros) {
  const double b[] = {1.0, 0.0, -2.0, 0.0, 0.0, 3.0};
  EXPECT_EQ(signVariations(b, 6), 2);
  EXPECT_EQ(signVariations(b + 1, 1), 0);
}

TEST(RealRoots, LinearAndOutsideInterval) {
  EXPECT_EQ(roots(Polynomial::fromHighestFirst({2.0, -1.0})), std::vector<double>{0.5});
  EXPECT_TRUE(roots(Polynomial::fromHighestFirst({1.0, 1.0})).empty());
  EXPECT_TRUE(roots(Polynomial::fromHighestFirst({3.0})).empty());
  EXPECT_TRUE(roots(Polynomial{}).empty());
}

TEST(RealRoots, QuinticWithFiveRootsInside) {
  const auto r = roots(fromRoots(1.0, {0.1, 0.3, 0.5, 0.7, 0.9}));
  ASSERT_EQ(r.size(), 5u);
  const double expected[] = {0.1, 0.3, 0.5, 0.7, 0.9};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(r[i], expected[i], 1e-14);
}

TEST(RealRoots, RootsAtTheEnds) {
  auto r = roots(fromRoots(1.0, {0.0, 0.5, 1.0}));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0], 0.0);
  EXPECT_NEAR(r[1], 0.5, 1e-15);
  EXPECT_EQ(r[2], 1.0);
  r = roots(fromRoots(-1.0, {0.0, 0.0, 1.0, 1.0}));  // double roots at both ends
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0], 0.0);
  EXPECT_EQ(r[1], 1.0);
}

TEST(RealRoots, DoubleRootIsFoundOnce) {
  const double third = 1.0 / 3.0;
  const auto r = roots(fromRoots(1.0, {third, third, 0.8}));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], third, 1e-8);
  EXPECT_NEAR(r[1], 0.8, 1e-14);
}

TEST(RealRoots, TripleRoot) {
  const auto r = roots(fromRoots(1.0, {0.25, 0.25, 0.25}));
  ASSERT_GE(r.size(), 1u);
  for (double x : r) EXPECT_NEAR(x, 0.25, 1e-5);
}

TEST(RealRoots, ComplexPairsOnlyGiveNoRoots) {
  // (t^2 + 1)((t - 0.5)^2 + 0.01): positive everywhere, Bernstein coefficients all positive.
  const Polynomial p = Polynomial::fromHighestFirst({1.0, -1.0, 2.26, -1.0, 0.26});
  EXPECT_TRUE(roots(p).empty());
}

TEST(RealRoots, OtherIntervalLengths) {
  const Polynomial p = fromRoots(1.0, {0.5, 1.5, 2.5});
  EXPECT_EQ(roots(p, 1.0).size(), 1u);
  EXPECT_EQ(roots(p, 2.0).size(), 2u);
  const auto r = roots(p, 3.0);
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[2], 2.5, 1e-14);
}

TEST(BracketedRoot, FullPrecision) {
  // t^5 + t - 1 has one real root; Newton polish from the bracket reaches the last ulp.
  const Polynomial p = Polynomial::fromHighestFirst({1.0, 0.0, 0.0, 0.0, 1.0, -1.0});
  const double r = bracketedRoot(p, 0.0, 1.0, -1.0, 1.0);
  EXPECT_LE(std::abs(p(r)), 4.0 * DBL_EPSILON);
  EXPECT_NEAR(r, 0.75487766624669276, 2e-16);
}

TEST(BracketedRoot, TerminatesOnFlatFunctions) {
  // (t - 0.3)^5: derivative vanishes at the root, Newton is linear; bisection bounds it.
  const Polynomial p = fromRoots(1.0, {0.3, 0.3, 0.3, 0.3, 0.3});
  const double r = bracketedRoot(p, 0.0, 1.0, p(0.0), p(1.0));
  EXPECT_NEAR(r, 0.3, 1e-2);  // rounding allows the computed polynomial to vanish nearby
  EXPECT_GT(r, 0.0);
  EXPECT_LT(r, 1.0);
}

TEST(EvaluateSnapped, RoundingNoiseIsZero) {
  const double third = 1.0 / 3.0;
  const Polynomial p = fromRoots(-1.0, {third, third});
  EXPECT_EQ(evaluateSnapped(p, third), 0.0);
  EXPECT_LT(evaluateSnapped(p, 0.5), 0.0);
}

// The reference's closed forms (rpoly's degree 1 and 2 paths). Expected values: an independent
// Python emulation of rpoly's Quad (tests/core/compat_boundary_test.cpp says more).
std::vector<double> referenceRoots(std::initializer_list<double> c) {
  double r[2];
  const int n = referenceRealRoots(Polynomial::fromHighestFirst(c), r);
  return std::vector<double>(r, r + n);
}

TEST(ReferenceRoots, QuadRoundsDifferentlyFromTheOwnFormula) {
  // The tracker's step-6 polynomial: the exact root is 1.00000000000000087; quadraticRoots gives
  // the nearest double 1.0000000000000009 (1 + 4 ulps), rpoly's Quad 1.000000000000001 (1 + 5).
  const double a = -0.0024999999999999988, b = 0.025, c = -0.02250000000000002;
  EXPECT_EQ(referenceRoots({a, b, c}), (std::vector<double>{1.000000000000001, 9.000000000000004}));
  double own[2];
  ASSERT_EQ(quadraticRoots(a, b, c, own), 2);
  EXPECT_EQ(own[0], 1.0000000000000009);
}

TEST(ReferenceRoots, LinearZeroAndComplexCases) {
  EXPECT_EQ(referenceRoots({-4.0, 1.0}), (std::vector<double>{0.25}));  // -p1/p0
  EXPECT_EQ(referenceRoots({-1.0, 0.5, 0.0}), (std::vector<double>{0.0, 0.5}));  // root at 0 stripped first
  EXPECT_EQ(referenceRoots({-1.0, 0.0}), (std::vector<double>{}));  // only roots at 0: rpoly fails
  EXPECT_EQ(referenceRoots({2.0, 0.0, 0.0}), (std::vector<double>{}));
  EXPECT_EQ(referenceRoots({1.0, 0.0, 1.0}), (std::vector<double>{}));  // +-i
  // A complex pair with an imaginary part below kReferenceImaginaryTolerance counts as real,
  // twice: t^2 - 0.002t + (1e-6 + 1e-17) has roots 0.001 +- 3.2e-9 i; with + 1e-15, 3.2e-8 i.
  EXPECT_EQ(referenceRoots({1.0, -2e-3, 1e-6 + 1e-17}), (std::vector<double>{0.001, 0.001}));
  EXPECT_EQ(referenceRoots({1.0, -2e-3, 1e-6 + 1e-15}), (std::vector<double>{}));
}

}  // namespace
}  // namespace fosssim::math
