#include "fosssim/math/polynomial.h"

#include <gtest/gtest.h>

#include <cfloat>

namespace fosssim::math {
namespace {

TEST(Polynomial, DropsExactZeroLeadingCoefficients) {
  const Polynomial p = Polynomial::fromHighestFirst({0.0, -0.0, 2.0, 0.0, 3.0});
  ASSERT_EQ(p.size, 3);
  EXPECT_EQ(p.c[0], 2.0);
  EXPECT_EQ(p.c[1], 0.0);  // inner zeros stay
  EXPECT_EQ(p.c[2], 3.0);
  EXPECT_EQ(p.degree(), 2);
}

TEST(Polynomial, KeepsTinyNonzeroLeadingCoefficient) {
  const Polynomial p = Polynomial::fromHighestFirst({1e-300, 1.0});
  EXPECT_EQ(p.size, 2);
}

TEST(Polynomial, AssignWithLeadingCutoff) {
  Polynomial p;
  p.assign({5e-13, -9e-13, 1e-12, 1e-20, 2.0}, 1e-12);  // inner tiny coefficients stay
  ASSERT_EQ(p.size, 3);
  EXPECT_EQ(p.c[0], 1e-12);
  EXPECT_EQ(p.c[1], 1e-20);
  EXPECT_EQ(p.c[3], 0.0);  // entries past size are zero
  p.assign({1e-13, 1e-14}, 1e-12);
  EXPECT_EQ(p.size, 0);
  p.assign({1e-13, 1.0});  // no cutoff: only exact zeros go
  EXPECT_EQ(p.size, 2);
}

TEST(Polynomial, AllZerosIsTheEmptyPolynomial) {
  const Polynomial p = Polynomial::fromHighestFirst({0.0, 0.0, 0.0});
  EXPECT_EQ(p.size, 0);
  EXPECT_EQ(p.degree(), -1);
  EXPECT_EQ(p(0.7), 0.0);
  EXPECT_EQ(p.signJustAfterZero(), 0);
}

TEST(Polynomial, FromPointerAndCount) {
  const double c[6] = {0.0, 1.0, -2.0, 3.0, -4.0, 5.0};
  const Polynomial p = Polynomial::fromHighestFirst(c, 6);
  ASSERT_EQ(p.size, 5);
  EXPECT_EQ(p.c[4], 5.0);
  EXPECT_EQ(Polynomial::fromHighestFirst(c, 0).size, 0);
}

TEST(Polynomial, HornerAndDerivative) {
  // p = 2t^3 - 3t + 1, p' = 6t^2 - 3
  const Polynomial p = Polynomial::fromHighestFirst({2.0, 0.0, -3.0, 1.0});
  EXPECT_DOUBLE_EQ(p(2.0), 11.0);
  double v = 0.0, d = 0.0;
  p.evaluate(2.0, &v, &d);
  EXPECT_DOUBLE_EQ(v, 11.0);
  EXPECT_DOUBLE_EQ(d, 21.0);
  const Polynomial dp = p.derivative();
  ASSERT_EQ(dp.size, 3);
  EXPECT_DOUBLE_EQ(dp(2.0), 21.0);
  EXPECT_EQ(Polynomial::fromHighestFirst({5.0}).derivative().size, 0);
  EXPECT_EQ(p.coefficientOfPower(3), 2.0);
  EXPECT_EQ(p.coefficientOfPower(0), 1.0);
  EXPECT_EQ(p.coefficientOfPower(4), 0.0);
}

TEST(Polynomial, SignJustAfterZeroReadsLowestNonzeroCoefficient) {
  EXPECT_EQ(Polynomial::fromHighestFirst({-1.0, 2.0, 0.0}).signJustAfterZero(), 1);   // 2t - t^2
  EXPECT_EQ(Polynomial::fromHighestFirst({1.0, -2.0, 0.0}).signJustAfterZero(), -1);
  EXPECT_EQ(Polynomial::fromHighestFirst({1.0, 0.0, 0.0}).signJustAfterZero(), 1);    // t^2
  EXPECT_EQ(Polynomial::fromHighestFirst({-3.0}).signJustAfterZero(), -1);
}

TEST(Polynomial, ErrorBoundCoversCancellation) {
  // (t - 1/3)^2 evaluated at its double root: the computed value is rounding noise and
  // must lie inside the bound.
  const double r = 1.0 / 3.0;
  const Polynomial p = Polynomial::fromHighestFirst({1.0, -2.0 * r, r * r});
  double bound = 0.0;
  const double v = p.evaluateWithErrorBound(r, &bound);
  EXPECT_LE(std::abs(v), bound);
  EXPECT_LT(bound, 1e-14);
}

}  // namespace
}  // namespace fosssim::math
