#include "fosssim/math/interval_solver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "test_polynomials.h"

namespace fosssim::math {
namespace {

using testing::expand;
using testing::fromRoots;

double solve(std::initializer_list<Polynomial> polys, double tMax = 1.0) {
  std::vector<Polynomial> v(polys);
  return firstPositiveTime(v.data(), static_cast<int>(v.size()), tMax);
}

Polynomial poly(std::initializer_list<double> c) { return Polynomial::fromHighestFirst(c); }

// ------------------------------------------------------------ named degenerate cases

TEST(IntervalSolver, NoPolynomialsHoldsAtZero) { EXPECT_EQ(firstPositiveTime(nullptr, 0), 0.0); }

TEST(IntervalSolver, ZeroPolynomialIsNeverPositive) {
  EXPECT_EQ(solve({Polynomial{}}), kNever);
  EXPECT_EQ(solve({poly({1.0}), Polynomial{}}), kNever);
  EXPECT_EQ(solve({poly({0.0, 0.0, 0.0})}), kNever);  // all-zero input drops to size 0
}

TEST(IntervalSolver, Constants) {
  EXPECT_EQ(solve({poly({2.0})}), 0.0);
  EXPECT_EQ(solve({poly({-2.0})}), kNever);
  EXPECT_EQ(solve({poly({2.0}), poly({1.0, -0.5})}), 0.5);
}

TEST(IntervalSolver, LinearCrossings) {
  EXPECT_EQ(solve({poly({2.0, -1.0})}), 0.5);   // positive after 0.5
  EXPECT_EQ(solve({poly({-2.0, 1.0})}), 0.0);   // positive until 0.5
  EXPECT_EQ(solve({poly({-1.0, -1.0})}), kNever);
  EXPECT_EQ(solve({poly({1.0, -3.0})}), kNever);  // starts at 3 > tMax
  EXPECT_EQ(solve({poly({1.0, -3.0})}, 4.0), 3.0);
}

TEST(IntervalSolver, RootTouchingZeroCounts) {
  EXPECT_EQ(solve({poly({1.0, 0.0})}), 0.0);              // t
  EXPECT_EQ(solve({poly({-1.0, 0.0})}), kNever);          // -t
  EXPECT_EQ(solve({fromRoots(-1.0, {0.0, 0.5})}), 0.0);   // -t(t - 0.5) > 0 on (0, 0.5)
  EXPECT_EQ(solve({fromRoots(1.0, {0.0, 0.5})}), 0.5);
  EXPECT_EQ(solve({fromRoots(1.0, {0.0, 0.3, 0.6})}), 0.0);
  EXPECT_EQ(solve({fromRoots(-1.0, {0.0, 0.25, 0.5})}), 0.25);
}

TEST(IntervalSolver, DoubleRootAtZero) {
  EXPECT_EQ(solve({poly({1.0, 0.0, 0.0})}), 0.0);         // t^2: positive right after 0
  EXPECT_EQ(solve({poly({-1.0, 0.0, 0.0})}), kNever);     // -t^2
  EXPECT_EQ(solve({fromRoots(-1.0, {0.0, 0.0, 2.0})}), 0.0);  // -t^2 (t - 2) > 0 on (0, 2)
  EXPECT_EQ(solve({fromRoots(1.0, {0.0, 0.0, 0.5})}), 0.5);
}

TEST(IntervalSolver, DoubleRootTouchingFromAboveExcludesOneInstant) {
  const double third = 1.0 / 3.0;
  EXPECT_EQ(solve({fromRoots(1.0, {0.5, 0.5})}), 0.0);
  EXPECT_EQ(solve({fromRoots(1.0, {third, third})}), 0.0);
  EXPECT_EQ(solve({fromRoots(1.0, {0.5, 0.5}), poly({1.0, -0.5})}), 0.5);  // meets t > 0.5
  EXPECT_NEAR(solve({fromRoots(1.0, {third, third, -1.0}), fromRoots(1.0, {third})}), third, 1e-15);
  EXPECT_EQ(solve({fromRoots(1.0, {0.5, 0.5, -2.0, -3.0, -4.0})}), 0.0);  // quintic
}

TEST(IntervalSolver, DoubleRootTouchingFromBelowIsNeverPositive) {
  const double third = 1.0 / 3.0;
  EXPECT_EQ(solve({fromRoots(-1.0, {0.5, 0.5})}), kNever);
  EXPECT_EQ(solve({fromRoots(-1.0, {third, third})}), kNever);
  EXPECT_EQ(solve({fromRoots(-1.0, {third, third, -1.0})}), kNever);  // cubic
  EXPECT_EQ(solve({fromRoots(-1.0, {0.3, 0.3, 0.7, 0.7})}), kNever);  // quartic, two touches
  EXPECT_EQ(solve({expand(-1.0, {0.3, 0.3, -2.0}, {{0.5, 0.5}})}), kNever);  // quintic
  EXPECT_EQ(solve({expand(-1.0, {0.7, 0.7}, {{0.2, 0.1}})}), kNever);          // quartic
}

TEST(IntervalSolver, TangentGraze) {
  // -(t - 1/2)^2 written out: the discriminant is exactly 0.
  EXPECT_EQ(solve({poly({-1.0, 1.0, -0.25})}), kNever);
  // -(t - 0.1)^2: 0.1 is not representable, the discriminant is rounding noise.
  EXPECT_EQ(solve({poly({-1.0, 0.2, -0.01})}), kNever);
  // Degree 4 graze: -(t - 0.3)^2 ((t - 0.5)^2 + 0.04), extremum value computes to noise.
  EXPECT_EQ(solve({expand(-1.0, {0.3, 0.3}, {{0.5, 0.2}})}), kNever);
}

TEST(IntervalSolver, RootsAtExactlyOne) {
  EXPECT_EQ(solve({poly({-1.0, 1.0})}), 0.0);                 // 1 - t
  EXPECT_EQ(solve({fromRoots(-1.0, {1.0, 1.0})}), kNever);    // -(t - 1)^2
  EXPECT_EQ(solve({fromRoots(1.0, {1.0, 1.0})}), 0.0);        // (t - 1)^2
  EXPECT_EQ(solve({fromRoots(1.0, {0.5, 1.0}), poly({-1.0, 0.75})}), 0.0);
  EXPECT_EQ(solve({fromRoots(-1.0, {0.5, 1.0})}), 0.5);       // positive on (0.5, 1)
  EXPECT_NEAR(solve({fromRoots(-1.0, {-0.2, 0.6, 1.0})}), 0.6, 1e-15);  // cubic: positive on (0.6, 1)
}

TEST(IntervalSolver, IntervalBeginningExactlyAtTMaxIsAHit) {
  EXPECT_EQ(solve({poly({1.0, -1.0})}), 1.0);                 // t - 1
  EXPECT_EQ(solve({fromRoots(1.0, {1.0, 1.0, 1.0})}), 1.0);   // (t - 1)^3 (derivatives decide)
  EXPECT_EQ(solve({fromRoots(1.0, {-0.5, 1.0, 3.0, 4.0})}, 1.0), 1.0);
  EXPECT_EQ(solve({poly({1.0, -1.0})}, 0.5), kNever);
  EXPECT_EQ(solve({poly({1.0, -0.5})}, 0.5), 0.5);
  // Ends at tMax for one, starts there for the other: they never overlap.
  EXPECT_EQ(solve({poly({1.0, -1.0}), poly({-1.0, 1.0})}), kNever);
  // (t - 1)^2 touches 0 at tMax but is positive just after: still a hit at 1.
  EXPECT_EQ(solve({poly({1.0, -1.0}), fromRoots(1.0, {1.0, 1.0})}), 1.0);
}

TEST(IntervalSolver, DisjointIntervalsNeverMeet) {
  EXPECT_EQ(solve({fromRoots(-1.0, {0.2, 0.4}), fromRoots(-1.0, {0.5, 0.7})}), kNever);
}

TEST(IntervalSolver, FirstOverlapOfSeveralIntervals) {
  // p1 > 0 on (0.1, 0.3) and (0.6, 1); p2 > 0 on (0.35, 0.4) and (0.65, 0.8).
  const Polynomial p1 = fromRoots(1.0, {0.1, 0.3, 0.6});
  const Polynomial p2 = fromRoots(-1.0, {0.35, 0.4, 0.65, 0.8});
  // The computed quartic's root sits ~1e-14 from 0.65 (its coefficients are rounded).
  EXPECT_NEAR(solve({p1, p2}), 0.65, 1e-13);
  EXPECT_EQ(solve({p2, p1}), solve({p1, p2}));  // order-free
}

TEST(IntervalSolver, OneNeverPositiveStopsTheSolve) {
  EXPECT_EQ(solve({fromRoots(1.0, {0.1, 0.3, 0.6, 0.9, 0.95}), poly({-1.0})}), kNever);
}

TEST(IntervalSolver, NonFiniteCoefficientsAreNeverPositive) {
  EXPECT_EQ(solve({poly({std::numeric_limits<double>::quiet_NaN(), 1.0})}), kNever);
  EXPECT_EQ(solve({poly({1.0, std::numeric_limits<double>::infinity()})}), kNever);
}

TEST(IntervalSolver, AllPositiveAtStartGivesZero) {
  EXPECT_EQ(solve({fromRoots(-1.0, {-1.0, 0.5, 2.0, 3.0}), poly({1.0, 1.0}), poly({3.0})}), 0.0);
}

TEST(PositiveSet, Shape) {
  const PositiveSet s = positiveSet(fromRoots(1.0, {0.1, 0.3, 0.6}));
  ASSERT_EQ(s.count, 2);
  EXPECT_NEAR(s.lo[0], 0.1, 1e-15);
  EXPECT_NEAR(s.hi[0], 0.3, 1e-15);
  EXPECT_NEAR(s.lo[1], 0.6, 1e-15);
  EXPECT_EQ(s.hi[1], kNever);
  // A touching root from above does not split the set.
  const PositiveSet t = positiveSet(fromRoots(1.0, {0.5, 0.5, -1.0}));
  ASSERT_EQ(t.count, 1);
  EXPECT_EQ(t.lo[0], 0.0);
  EXPECT_EQ(t.hi[0], kNever);
}

// ------------------------------------------------------------ random: exact sign oracle

// A polynomial known by its factors: sign(p(t)) = s * prod sign(t - r_i) exactly (the
// complex-pair factors are positive), whatever the rounding of the expanded coefficients.
struct Factored {
  double s;
  std::vector<double> roots;
  std::vector<std::pair<double, double>> pairs;
  // Sign of p on (t, t + eps).
  int signJustAfter(double t) const {
    int sign = s > 0 ? 1 : -1;
    for (double r : roots) sign *= (r <= t) ? 1 : -1;
    return sign;
  }
};

std::string describe(const std::vector<Factored>& fs) {
  std::ostringstream out;
  out.precision(17);
  for (const auto& f : fs) {
    out << "\n  s=" << f.s << " roots";
    for (double r : f.roots) out << ' ' << r;
    out << " pairs";
    for (const auto& [c, d] : f.pairs) out << ' ' << c << '+' << d << 'i';
  }
  return out.str();
}

double oracle(const std::vector<Factored>& polys, double tMax) {
  std::vector<double> candidates{0.0};
  for (const auto& p : polys)
    for (double r : p.roots)
      if (r >= 0.0 && r <= tMax) candidates.push_back(r);
  std::sort(candidates.begin(), candidates.end());
  for (double c : candidates) {
    bool all = true;
    for (const auto& p : polys) all = all && p.signJustAfter(c) > 0;
    if (all) return c;
  }
  return kNever;
}

TEST(IntervalSolverRandom, MatchesExactSignOracleOnChosenRoots) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> uni(-0.5, 1.5);
  std::uniform_int_distribution<int> pick(0, 9);
  int hits = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double tMax = (trial % 5 == 4) ? 0.5 : 1.0;
    const int count = 1 + trial % 4;
    std::vector<Factored> fs;
    std::vector<Polynomial> ps;
    for (int k = 0; k < count; ++k) {
      Factored f{pick(rng) < 5 ? 1.0 : -1.0, {}, {}};
      const int degree = pick(rng) % 6;
      while (static_cast<int>(f.roots.size()) + 2 * static_cast<int>(f.pairs.size()) < degree) {
        const int kind = pick(rng);
        const int room = degree - static_cast<int>(f.roots.size()) - 2 * static_cast<int>(f.pairs.size());
        if (kind == 0) {
          f.roots.push_back(0.0);
        } else if (kind == 1) {
          f.roots.push_back(tMax);
        } else if (kind == 2 && room >= 2) {  // double root
          const double r = (pick(rng) < 3) ? 0.25 * pick(rng) : uni(rng);
          f.roots.push_back(r);
          f.roots.push_back(r);
        } else if (kind == 3 && room >= 2) {
          f.pairs.push_back({uni(rng), 0.05 + 0.5 * std::abs(uni(rng))});
        } else {
          // Keep distinct roots apart, or their tiny interval is below numerical resolution.
          double r = uni(rng);
          bool close = false;
          for (double q : f.roots) close = close || (q != r && std::abs(q - r) < 1e-3);
          if (!close) f.roots.push_back(r);
        }
      }
      // Roots shared between polynomials (e.g. both exactly at tMax) are kept: the sign
      // oracle handles them, and so must the solver.
      ps.push_back(expand(f.s, f.roots, f.pairs));
      fs.push_back(f);
    }
    const double expected = oracle(fs, tMax);
    const double got = firstPositiveTime(ps.data(), count, tMax);
    if (expected == kNever) {
      EXPECT_EQ(got, kNever) << "trial " << trial << describe(fs);
    } else {
      ++hits;
      // Double roots move by ~sqrt(rounding) when the coefficients are rounded.
      EXPECT_NEAR(got, expected, 2e-7) << "trial " << trial << describe(fs);
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(hits, 2000);
}

// ------------------------------------------------------------ random: dense sampling

TEST(IntervalSolverRandom, MatchesDenseSamplingOnRandomCoefficients) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  constexpr int kSamples = 4000;
  int hits = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int count = 1 + trial % 3;
    std::vector<Polynomial> ps;
    for (int k = 0; k < count; ++k) {
      double c[Polynomial::kMaxCoeffs];
      const int n = 1 + (trial / 3 + k) % 6;
      for (int i = 0; i < n; ++i) c[i] = uni(rng) * (i == n - 1 ? 0.3 : 1.0);
      ps.push_back(Polynomial::fromHighestFirst(c, n));
    }
    const double got = firstPositiveTime(ps.data(), count, 1.0);
    auto allPositive = [&](double t) {
      for (const auto& p : ps)
        if (!(p(t) > 0.0)) return false;
      return true;
    };
    // No sample clearly before the answer may have all positive.
    double firstSample = kNever;
    for (int i = 0; i <= kSamples; ++i) {
      const double t = static_cast<double>(i) / kSamples;
      if (allPositive(t)) {
        firstSample = t;
        break;
      }
    }
    if (got == kNever) {
      EXPECT_EQ(firstSample, kNever) << "trial " << trial;
    } else {
      ++hits;
      EXPECT_GE(firstSample, got - 1e-12) << "trial " << trial;
      // And positivity right after the answer (unless the stretch is thinner than a sample).
      bool after = false;
      for (double eps : {1e-12, 1e-10, 1e-8, 1e-6, 1e-4})
        after = after || (got + eps <= 1.0 + 1e-4 && allPositive(got + eps));
      EXPECT_TRUE(after || firstSample == kNever) << "trial " << trial << " got " << got;
      if (firstSample != kNever) {
        EXPECT_LE(firstSample - got, 1.0 / kSamples) << "trial " << trial;
      }
    }
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(hits, 500);
}

// ------------------------------------------------------------ IntervalRule::Reference (--compat)

double solveWith(IntervalRule rule, std::initializer_list<Polynomial> polys, double tMax = 1.0) {
  std::vector<Polynomial> v(polys);
  return firstPositiveTime(v.data(), static_cast<int>(v.size()), tMax, rule);
}

// The tracker's scenario (tests/core/compat_boundary_test.cpp): two disks of radius 0.1 meeting
// exactly at the end of step 6. These are the particle-particle polynomials FOSSSim and the
// reference build for steps 6 and 7. Expected values under the Reference rule come from an
// independent emulation of the reference's arithmetic (rpoly's Quad path and its
// ContinuousTimeUtilities interval logic, written in Python from the published algorithms),
// not from this code: step 6 roots 1.000000000000001 and 9.000000000000004, so no collision;
// step 7 the first root, 1.0408340855860843e-15, is the collision time.
TEST(IntervalSolverReference, ContactAtTheEndOfTheStepIsLeftToTheNextStep) {
  const Polynomial position6 = poly({-0.0024999999999999988, 0.025, -0.02250000000000002});
  const Polynomial approach6 = poly({-0.0024999999999999988, 0.0125});
  const Polynomial position7 = poly({-0.0024999999999999988, 0.020000000000000004, -2.0816681711721685e-17});
  const Polynomial approach7 = poly({-0.0024999999999999988, 0.010000000000000002});
  // FOSSSim's own rule: p(1) is within Horner's rounding error of 0, the root is snapped onto 1.
  EXPECT_EQ(solveWith(IntervalRule::Exact, {position6, approach6}), 1.0);
  // The reference's: its root lies 5 ulps past 1 (the exact root of these coefficients,
  // 1.00000000000000087, lies past 1 as well), so nothing in this step...
  EXPECT_EQ(solveWith(IntervalRule::Reference, {position6, approach6}), kNever);
  EXPECT_EQ(positiveSet(position6, 1.0, IntervalRule::Reference).count, 0);
  // ... and the collision at the start of the next one.
  EXPECT_EQ(solveWith(IntervalRule::Reference, {position7, approach7}), 1.0408340855860843e-15);
  // A root computed at or before 1 is a hit at that root, never moved onto 1.
  EXPECT_EQ(solveWith(IntervalRule::Reference, {poly({-1.0, 2.0, -0.9999999999999998}), poly({-1.0, 1.0})}),
            solveWith(IntervalRule::Reference, {poly({-1.0, 2.0, -0.9999999999999998})}));
}

// The reference intersects CLOSED intervals: stretches that only touch meet at the touching
// point (its overlap test is b.s <= a.e && a.s <= b.e). FOSSSim's own rule needs a common
// right-neighbourhood.
TEST(IntervalSolverReference, TouchingStretchesMeet) {
  const Polynomial before = poly({-1.0, 0.5});  // > 0 on (-inf, 0.5)
  const Polynomial after = poly({1.0, -0.5});   // > 0 on (0.5, inf)
  EXPECT_EQ(solveWith(IntervalRule::Exact, {before, after}), kNever);
  EXPECT_EQ(solveWith(IntervalRule::Reference, {before, after}), 0.5);
  // At the end of the step: a hit at 1 exactly.
  EXPECT_EQ(solveWith(IntervalRule::Reference, {poly({-1.0, 1.0}), poly({1.0, -1.0})}), 1.0);
  // Touching at 0 or before gives nothing: the reference skips intervals ending at or before 0.
  EXPECT_EQ(solveWith(IntervalRule::Reference, {poly({-1.0, 0.0}), poly({1.0, 0.0})}), kNever);
  EXPECT_EQ(solveWith(IntervalRule::Reference, {poly({-1.0, -0.5}), poly({1.0, 0.5})}), kNever);
}

// Where no root is at stake the two rules agree.
TEST(IntervalSolverReference, AgreesWithTheOwnRuleAwayFromBoundaries) {
  const std::vector<std::vector<Polynomial>> cases = {
      {poly({2.0})},
      {poly({-2.0})},
      {poly({-1.0, 0.25})},                                // positive at 0
      {poly({1.0, -0.25})},                                // from 0.25
      {poly({-1.0, 1.0, -0.1875}), poly({-1.0, 0.5})},     // a downward parabola, roots 0.25, 0.75
      {poly({1.0, -1.0, 0.1875})},                         // upward: positive at 0
      {poly({1.0, 0.0, 1.0})},                             // no real root, positive
      {poly({-1.0, 0.0, -1.0})},                           // no real root, negative
      {poly({-1.0, 0.5, 0.0})},                            // a root at 0 (stripped by rpoly), then 0.5
      {poly({1.0, -3.0})},                                 // from 3: after the step
      {fromRoots(-1.0, {0.2, 0.4, 0.9}), poly({-1.0, 0.8})},  // a cubic: FOSSSim's roots
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const auto& c = cases[k];
    EXPECT_EQ(firstPositiveTime(c.data(), static_cast<int>(c.size()), 1.0, IntervalRule::Exact),
              firstPositiveTime(c.data(), static_cast<int>(c.size()), 1.0, IntervalRule::Reference))
        << "case " << k;
  }
}

// Capacities are contracts checked in every build (FOSSSIM_ASSERT, contract.h): going past one
// stops the program with a message instead of dropping an interval or a coefficient silently.
TEST(IntervalSolverDeathTest, AppendPastTheCapacityIsReportedNotDropped) {
  PositiveSet set;
  for (int k = 0; k < PositiveSet::kMaxIntervals; ++k) set.append(2.0 * k, 2.0 * k + 1.0);
  EXPECT_EQ(set.count, PositiveSet::kMaxIntervals);
  set.append(2.0 * PositiveSet::kMaxIntervals - 1.0, 100.0);  // touches the last one: merged
  EXPECT_EQ(set.count, PositiveSet::kMaxIntervals) << "a touching interval extends the last one";
  EXPECT_EQ(set.hi[PositiveSet::kMaxIntervals - 1], 100.0);
  EXPECT_DEATH(set.append(1000.0, 1001.0), "contract 'count < kMaxIntervals'");
}

TEST(IntervalSolverDeathTest, MoreCoefficientsThanTheDegreeAllowsAreReported) {
  const double seven[7] = {1, 2, 3, 4, 5, 6, 7};
  EXPECT_DEATH(Polynomial::fromHighestFirst(seven, 7), "contract .*kMaxCoeffs");
  const double sixAfterZeros[8] = {0, 0, 1, 2, 3, 4, 5, 6};
  EXPECT_EQ(Polynomial::fromHighestFirst(sixAfterZeros, 8).size, 6) << "leading zeros do not count";
}

TEST(IntervalSolverDeathTest, MorePolynomialsThanTheSolverHoldsAreReported) {
  std::vector<Polynomial> many(kMaxSolverPolynomials + 1, Polynomial::fromHighestFirst({1.0}));
  EXPECT_EQ(firstPositiveTime(many.data(), kMaxSolverPolynomials), 0.0);
  EXPECT_DEATH(firstPositiveTime(many.data(), kMaxSolverPolynomials + 1), "contract");
}

}  // namespace
}  // namespace fosssim::math
