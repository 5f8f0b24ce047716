#include "fosssim/math/ccd.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace fosssim::math {
namespace {

std::vector<double> coeffs(const Polynomial& p) { return std::vector<double>(p.c.begin(), p.c.begin() + p.size); }

PEInput pe(Vec2 x1, Vec2 d1, double rv, Vec2 x2, Vec2 d2, Vec2 x3, Vec2 d3, double re) {
  PEInput in;
  in.x1 = x1;
  in.d1 = d1;
  in.rv = rv;
  in.x2 = x2;
  in.d2 = d2;
  in.x3 = x3;
  in.d3 = d3;
  in.re = re;
  return in;
}

PPInput pp(Vec2 x1, Vec2 d1, double r1, Vec2 x2, Vec2 d2, double r2) {
  PPInput in;
  in.x1 = x1;
  in.d1 = d1;
  in.r1 = r1;
  in.x2 = x2;
  in.d2 = d2;
  in.r2 = r2;
  return in;
}

PHInput ph(Vec2 x1, Vec2 d1, double r, Vec2 p, Vec2 m) {
  PHInput in;
  in.x1 = x1;
  in.d1 = d1;
  in.r = r;
  in.p = p;
  in.m = m;
  return in;
}

// ------------------------------------------------------------ coefficients, exact examples

TEST(CcdCoefficients, PPCheckFromSpec) {
  const PPInput in = pp({-4.5, 0.0}, {1.0, 0.0}, 0.2, {0.0, 0.0}, {0.0, 0.0}, 0.2);
  const Polynomial pos = ppPosition(in);
  ASSERT_EQ(pos.size, 3);
  EXPECT_EQ(pos.c[0], -1.0);
  EXPECT_EQ(pos.c[1], 9.0);
  EXPECT_DOUBLE_EQ(pos.c[2], -20.09);
  EXPECT_EQ(coeffs(ppApproach(in)), (std::vector<double>{-1.0, 4.5}));
}

TEST(CcdCoefficients, PEQuarticWorkedExampleOne) {
  const PEInput in = pe({3, 1}, {4, 1}, 1.0, {5, 9}, {2, 6}, {5, 3}, {5, 8}, 1.0);
  EXPECT_EQ(coeffs(peDistance(in)), (std::vector<double>{-361, -304, -468, -288, 0}));
}

TEST(CcdCoefficients, PEQuarticWorkedExampleTwo) {
  const PEInput in = pe({1, 4}, {1, 4}, 1.0, {2, 1}, {3, 5}, {6, 2}, {3, 7}, 2.0);
  EXPECT_EQ(coeffs(peDistance(in)), (std::vector<double>{-16, 0, -68, 36, -16}));
}

TEST(CcdCoefficients, PEReferenceOutputCheck) {
  const PEInput in = pe({0, 0}, {0, -0.01}, 0.2, {-1, -1}, {0, 0}, {1, -1}, {0, 0}, 0.075);
  const Polynomial q = peDistance(in);
  ASSERT_EQ(q.size, 3);
  EXPECT_DOUBLE_EQ(q.c[0], -0.0004);
  EXPECT_DOUBLE_EQ(q.c[1], 0.08);
  EXPECT_DOUBLE_EQ(q.c[2], -3.6975);
  EXPECT_EQ(coeffs(peAlphaAboveZero(in)), std::vector<double>{2.0});
  EXPECT_EQ(coeffs(peAlphaBelowOne(in)), std::vector<double>{2.0});
  for (QuinticForm form : {QuinticForm::Exact, QuinticForm::Reference}) {
    const Polynomial a = peApproach(in, form);
    ASSERT_EQ(a.size, 2);
    EXPECT_DOUBLE_EQ(a.c[0], -0.0016);
    EXPECT_DOUBLE_EQ(a.c[1], 0.16);
  }
}

TEST(CcdCoefficients, PHSmallExample) {
  // P = (p - x1).m = -2, D = d1.m = -4, r^2|m|^2 = 1.
  const PHInput in = ph({0, 1}, {0, -2}, 0.5, {0, 0}, {0, 2});
  EXPECT_EQ(coeffs(phDistance(in)), (std::vector<double>{-16, 16, -3}));
  EXPECT_EQ(coeffs(phApproach(in)), (std::vector<double>{-16, 8}));
}

TEST(CcdCoefficients, StaticPairsGiveShortLists) {
  const PPInput p = pp({0, 0}, {1, 0}, 0.2, {0, 1}, {1, 0}, 0.2);  // same motion
  EXPECT_EQ(ppPosition(p).size, 1);
  EXPECT_EQ(ppApproach(p).size, 0);
  const PEInput e = pe({0, 1}, {0, 0}, 0.1, {-1, 0}, {0, 0}, {1, 0}, {0, 0}, 0.1);
  EXPECT_EQ(peDistance(e).size, 1);
  EXPECT_EQ(peApproach(e).size, 0);
  const PHInput h = ph({0, 1}, {1, 0}, 0.1, {0, 0}, {0, 1});  // sliding along the plane
  EXPECT_EQ(phDistance(h).size, 1);
  EXPECT_EQ(phApproach(h).size, 0);
}

TEST(CcdCoefficients, NegligibleLeadingCoefficientsAreDropped) {
  // Relative displacement 5e-7 per step: |D21|^2 = 2.5e-13 < 1e-12 leads both PP lists.
  const PPInput slow = pp({0, 0}, {5e-7, 0}, 0.2, {1, 0}, {0, 0}, 0.2);
  EXPECT_EQ(ppPosition(slow).size, 2);
  EXPECT_EQ(ppApproach(slow).size, 1);
  // 2e-6: |D21|^2 = 4e-12 stays.
  const PPInput slower = pp({0, 0}, {2e-6, 0}, 0.2, {1, 0}, {0, 0}, 0.2);
  EXPECT_EQ(ppPosition(slower).size, 3);
  EXPECT_EQ(ppApproach(slower).size, 2);
}

TEST(CcdCoefficients, ReferenceQuinticDiffersOnlyInTCubed) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    // Drawn into named points first, left to right: a call's arguments are evaluated in an order
    // the compiler picks (gcc right to left, clang left to right), and both must see the same inputs.
    const Vec2 x1{u(rng), u(rng)}, d1{u(rng), u(rng)}, x2{u(rng), u(rng)}, d2{u(rng), u(rng)};
    const Vec2 x3{u(rng), u(rng)}, d3{u(rng), u(rng)};
    const PEInput in = pe(x1, d1, 0.1, x2, d2, x3, d3, 0.05);
    const Polynomial exact = peApproach(in, QuinticForm::Exact);
    const Polynomial ref = peApproach(in, QuinticForm::Reference);
    ASSERT_EQ(exact.size, 6);
    ASSERT_EQ(ref.size, 6);
    for (int k : {0, 1, 3, 4, 5}) EXPECT_EQ(exact.c[k], ref.c[k]);
    EXPECT_NE(exact.c[2], ref.c[2]);
  }
}

// ------------------------------------------------------------ contact times and vectors

TEST(CcdDetect, HeadOnParticles) {
  // Gap 2, closing speed 4 per step, radii sum 0.5: contact when 2 - 4t = 0.5.
  Contact hit;
  ASSERT_TRUE(detectPP(pp({-1, 0}, {2, 0}, 0.25, {1, 0}, {-2, 0}, 0.25), &hit));
  EXPECT_DOUBLE_EQ(hit.tau, 0.375);
  EXPECT_DOUBLE_EQ(hit.n.x(), 0.5);
  EXPECT_EQ(hit.n.y(), 0.0);
}

TEST(CcdDetect, ParticlesOffsetHeadOn) {
  // Relative motion along x with lateral offset 0.3, radii sum 0.5:
  // contact when dx = sqrt(0.25 - 0.09) = 0.4, i.e. at 2 - 4t = 0.4.
  Contact hit;
  ASSERT_TRUE(detectPP(pp({-1, 0}, {2, 0}, 0.25, {1, 0.3}, {-2, 0}, 0.25), &hit));
  EXPECT_NEAR(hit.tau, 0.4, 1e-15);
  EXPECT_NEAR(hit.n.x(), 0.4, 1e-15);
  EXPECT_NEAR(hit.n.y(), 0.3, 1e-15);
}

TEST(CcdDetect, ParticlesOverlappingAndApproachingAtStartCollideAtZero) {
  Contact hit;
  ASSERT_TRUE(detectPP(pp({0, 0}, {0.1, 0}, 0.2, {0.3, 0}, {0, 0}, 0.2), &hit));
  EXPECT_EQ(hit.tau, 0.0);
  EXPECT_EQ(hit.n, Vec2(0.3, 0.0));
  // Overlapping but separating: no collision.
  EXPECT_FALSE(detectPP(pp({0, 0}, {-0.1, 0}, 0.2, {0.3, 0}, {0, 0}, 0.2), nullptr));
}

TEST(CcdDetect, ParallelParticlesMiss) {
  EXPECT_FALSE(detectPP(pp({0, 0}, {1, 0}, 0.2, {0, 1}, {1, 0}, 0.2), nullptr));
  // Relative motion parallel to the offset-free axis, offset 1 > radii sum: a miss.
  EXPECT_FALSE(detectPP(pp({-1, 0}, {2, 0}, 0.2, {1, 1}, {-2, 0}, 0.2), nullptr));
}

TEST(CcdDetect, ParticlesGrazing) {
  // Lateral offset exactly the radii sum (0.5 = 0.25 + 0.25): they touch at one instant
  // without overlapping, which is not a collision.
  EXPECT_FALSE(detectPP(pp({-1, 0}, {2, 0}, 0.25, {1, 0.5}, {-2, 0}, 0.25), nullptr));
}

TEST(CcdDetect, ParticleHitsEdgeInteriorAtRightAngle) {
  // Edge y = 0 from x = -1 to 1, radii sum 0.25, particle falls from y = 1 by 2 per step:
  // touches when 1 - 2t = 0.25.
  Contact hit;
  const PEInput in = pe({0.2, 1}, {0, -2}, 0.15, {-1, 0}, {0, 0}, {1, 0}, {0, 0}, 0.1);
  ASSERT_TRUE(detectPE(in, &hit));
  EXPECT_NEAR(hit.tau, 0.375, 1e-15);
  EXPECT_NEAR(hit.n.x(), 0.0, 1e-15);
  EXPECT_NEAR(hit.n.y(), -0.25, 1e-15);
}

TEST(CcdDetect, MovingEdgeHitsRestingParticle) {
  // The same collision seen from the particle: the edge rises by 2 per step.
  Contact hit;
  const PEInput in = pe({0.2, 0}, {0, 0}, 0.15, {-1, -1}, {0, 2}, {1, -1}, {0, 2}, 0.1);
  ASSERT_TRUE(detectPE(in, &hit));
  EXPECT_NEAR(hit.tau, 0.375, 1e-15);
  EXPECT_NEAR(hit.n.y(), -0.25, 1e-15);
}

TEST(CcdDetect, EdgeEndpointRegionEntersAtAlphaOne) {
  // The particle is within reach of the edge's LINE from the start but beyond endpoint 3
  // (alpha > 1); the PE conditions hold once it passes x = 1 (alpha = 1) at t = 0.5, and the
  // contact vector (alpha unclamped, = 1 there) points at the endpoint. Contacts beyond the
  // ends are the PP test's business with the endpoint particles.
  Contact hit;
  const PEInput in = pe({1.5, 0.2}, {-1, -0.1}, 0.15, {-1, 0}, {0, 0}, {1, 0}, {0, 0}, 0.1);
  ASSERT_TRUE(detectPE(in, &hit));
  EXPECT_EQ(hit.tau, 0.5);
  EXPECT_NEAR(hit.n.x(), 0.0, 1e-15);
  EXPECT_NEAR(hit.n.y(), -0.15, 1e-15);
}

TEST(CcdDetect, ParticleMovingParallelToEdgeMisses) {
  EXPECT_FALSE(detectPE(pe({-0.5, 1}, {1, 0}, 0.15, {-1, 0}, {0, 0}, {1, 0}, {0, 0}, 0.1), nullptr));
  // Even inside reach of the line, sliding parallel is not an approach.
  EXPECT_FALSE(detectPE(pe({-0.5, 0.2}, {1, 0}, 0.15, {-1, 0}, {0, 0}, {1, 0}, {0, 0}, 0.1), nullptr));
}

TEST(CcdDetect, PEContactVectorUsesUnclampedAlpha) {
  const PEInput in = pe({3, 1}, {0, 0}, 0.1, {0, 0}, {0, 0}, {2, 0}, {0, 0}, 0.1);
  EXPECT_EQ(peContactVector(in, 0.0), Vec2(0.0, -1.0));  // alpha = 1.5, point (3, 0)
}

TEST(CcdDetect, HalfPlaneBounce) {
  // Plane y = 0 (raw normal (0, 2)), particle radius 0.5 falling from y = 1 by 2 per step.
  Contact hit;
  ASSERT_TRUE(detectPH(ph({0, 1}, {0, -2}, 0.5, {0, 0}, {0, 2}), &hit));
  EXPECT_DOUBLE_EQ(hit.tau, 0.25);
  EXPECT_DOUBLE_EQ(hit.n.x(), 0.0);
  EXPECT_DOUBLE_EQ(hit.n.y(), -0.5);
  EXPECT_FALSE(detectPH(ph({0, 1}, {0, 2}, 0.5, {0, 0}, {0, 2}), nullptr));    // leaving
  EXPECT_FALSE(detectPH(ph({0, 1}, {3, 0}, 0.5, {0, 0}, {0, 2}), nullptr));    // sliding
  EXPECT_FALSE(detectPH(ph({0, 3}, {0, -1}, 0.5, {0, 0}, {0, 2}), nullptr));   // too short
}

TEST(CcdDetect, SlantedHalfPlane) {
  // Plane x + y = 0 with m = (1, 1); particle at (1, 1), distance sqrt(2), moving (-1, -1):
  // distance sqrt(2)(1 - t) = r = sqrt(2)/2 at t = 1/2.
  Contact hit;
  ASSERT_TRUE(detectPH(ph({1, 1}, {-1, -1}, std::sqrt(0.5), {0, 0}, {1, 1}), &hit));
  EXPECT_NEAR(hit.tau, 0.5, 1e-15);
  EXPECT_NEAR(hit.n.x(), -0.5, 1e-15);
  EXPECT_NEAR(hit.n.y(), -0.5, 1e-15);
}

// ------------------------------------------------------------ logging and the fast path

TEST(CcdDetect, LogHoldsAllPolynomialsEvenWhenRejectedEarly) {
  PairPolynomials log;
  // Far apart and separating: the fast path would stop at once.
  EXPECT_FALSE(detectPE(pe({10, 10}, {1, 1}, 0.1, {-1, 0}, {0, 0}, {1, 0}, {0, 0}, 0.1), nullptr, &log));
  ASSERT_EQ(log.count, 4);
  EXPECT_EQ(log.polys[0].size, 3);
  EXPECT_EQ(log.polys[1].size, 2);
  EXPECT_EQ(log.polys[2].size, 2);
  EXPECT_EQ(log.polys[3].size, 2);
  EXPECT_FALSE(detectPP(pp({0, 0}, {-1, 0}, 0.1, {1, 0}, {1, 0}, 0.1), nullptr, &log));
  ASSERT_EQ(log.count, 2);
  EXPECT_EQ(coeffs(log.polys[0]), coeffs(ppPosition(pp({0, 0}, {-1, 0}, 0.1, {1, 0}, {1, 0}, 0.1))));
  EXPECT_FALSE(detectPH(ph({0, 1}, {0, 2}, 0.5, {0, 0}, {0, 2}), nullptr, &log));
  ASSERT_EQ(log.count, 2);
}

// The fast path's early exits must not change any answer: compare with the logging path
// on random pairs placed so that hits, near misses and far misses all occur.
TEST(CcdDetect, FastPathAgreesWithLoggingPath) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits[3] = {0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    const double reach = (i % 3 == 0) ? 0.05 : 0.6;  // some far, some close
    Contact a, b;
    PairPolynomials log;
    // Drawn into named points first, left to right: a call's arguments are evaluated in an order
    // the compiler picks (gcc right to left, clang left to right), and both must see the same pairs.
    const Vec2 px1{u(rng), u(rng)}, pd1{reach * u(rng), reach * u(rng)};
    const double pr1 = 0.1 + 0.1 * u(rng);
    const Vec2 px2{u(rng), u(rng)}, pd2{reach * u(rng), reach * u(rng)};
    const PPInput p = pp(px1, pd1, pr1, px2, pd2, 0.15);
    const bool fp = detectPP(p, &a);
    ASSERT_EQ(fp, detectPP(p, &b, &log)) << i;
    if (fp) {
      ++hits[0];
      ASSERT_EQ(a.tau, b.tau);
      ASSERT_EQ(a.n, b.n);
    }
    const Vec2 ex1{u(rng), u(rng)}, ed1{reach * u(rng), reach * u(rng)};
    const Vec2 ex2{u(rng), u(rng)}, ed2{reach * u(rng), reach * u(rng)};
    const Vec2 ex3{u(rng), u(rng)}, ed3{reach * u(rng), reach * u(rng)};
    const PEInput e = pe(ex1, ed1, 0.1, ex2, ed2, ex3, ed3, 0.05);
    const bool fe = detectPE(e, &a);
    ASSERT_EQ(fe, detectPE(e, &b, &log)) << i;
    if (fe) {
      ++hits[1];
      ASSERT_EQ(a.tau, b.tau);
      ASSERT_EQ(a.n, b.n);
    }
    const Vec2 hx1{u(rng), u(rng)}, hd1{reach * u(rng), reach * u(rng)}, hp{u(rng), u(rng)}, hm{u(rng), u(rng)};
    const PHInput h = ph(hx1, hd1, 0.1, hp, hm);
    const bool fh = detectPH(h, &a);
    ASSERT_EQ(fh, detectPH(h, &b, &log)) << i;
    if (fh) {
      ++hits[2];
      ASSERT_EQ(a.tau, b.tau);
      ASSERT_EQ(a.n, b.n);
    }
  }
  EXPECT_GT(hits[0], 100);
  EXPECT_GT(hits[1], 100);
  EXPECT_GT(hits[2], 100);
}

}  // namespace
}  // namespace fosssim::math
