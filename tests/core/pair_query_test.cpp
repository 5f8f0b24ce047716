// The bound behind cannotDeepen (src/core/collision/pair_query.h): a disk-disk or disk-half-plane
// pair whose particles move in straight lines deepens its overlap over [t, 1] by at most its
// closing rate at t times (1 - t), because its distance is convex in time (linear against a
// half-plane) and its depth therefore lies below its tangent at t. Checked against
// pairDeepening's own samples on random pairs (apart, touching and overlapping; parting, sliding
// and closing, many of them sliding with a closing rate of rounding size, where the shortcut is
// taken), and a particle-edge pair, whose edge may rotate, is never settled by the bound.
#include "../../src/core/collision/pair_query.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace fosssim::testing {
namespace {

Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }
Vec2 unit(const Vec2& a) { return a / a.norm(); }

TEST(PairQuery, AStraightDiskPairDeepensAtMostItsClosingRateTimesTheTimeLeft) {
  std::mt19937 rng(20261203);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int shortcuts = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    TestScene s;
    // Draws in separate statements or braces, left to right: a call's arguments are evaluated in an
    // order the compiler picks (gcc right to left, clang left to right).
    const Vec2 start0{u(rng), u(rng)};
    addBody(s, 1.0, start0, Vec2::Zero(), 0.4 + 0.2 * u(rng));
    const Vec2 start1{u(rng), u(rng)};
    addBody(s, 1.0, start1, Vec2::Zero(), 0.4 + 0.2 * u(rng));
    s.scene.halfplanes.push_back(HalfPlane{Vec2{u(rng), u(rng)}, Vec2{u(rng), 1.5 + u(rng)}});  // not unit
    const double t = 0.5 * (1.0 + u(rng));  // [0, 1)
    // Rates (displacement per unit of t): particle 0 at random; particle 1 relative to it either
    // at random or sliding along the contact normal at t with a closing rate of rounding size.
    Vec2 rate[2];
    rate[0] = Vec2{u(rng), u(rng)};
    const bool sliding = trial % 2 == 0;
    const Vec2 x0 = at(s.state.x, 0) + t * rate[0];
    const Vec2 xt1 = at(s.state.x, 1);  // particle 1's position at t, kept: its start is set below
    const Vec2 n = unit(xt1 - x0);
    if (sliding) {
      const double slide = u(rng);
      const double approach = u(rng);
      rate[1] = rate[0] + slide * perp(n) - 1e-10 * approach * n;
    } else {
      rate[1] = Vec2{u(rng), u(rng)};
    }
    at(s.state.x, 1) = xt1 - t * rate[1];
    const auto position = [&](int p, double time) { return Vec2(at(s.state.x, p) + time * rate[p]); };
    const auto rateOf = [&](int p) { return rate[p]; };
    struct Case {
      uint64_t key;
      Vec2 normal;  // from the particle toward the other object, at t
    };
    const Case cases[] = {{pairKey(0, PairKind::ParticleParticle, 1), n},
                          {pairKey(0, PairKind::ParticleHalfPlane, 0), Vec2(-unit(s.scene.halfplanes[0].normal))}};
    for (const Case& c : cases) {
      double scale = 0, length = 0;
      const double closing = closingSpeed(s.scene, c.key, c.normal, 0.0, rateOf, scale);
      const double deepening = pairDeepening(s.scene, c.key, position, t, 1.0, length);
      // The bound, up to the rounding of the depths (coordinates of order 1: 1e-14).
      ASSERT_LE(deepening, std::max(closing, 0.0) * (1.0 - t) + 1e-14 * length)
          << "trial " << trial << ", " << pairKindName(keyKind(c.key)) << ", closing " << closing << ", t " << t;
      if (cannotDeepen(keyKind(c.key), closing, t, 1.0, length)) {
        ++shortcuts;
        ASSERT_LE(deepening, kDepthTolerance * length) << "trial " << trial << ", " << pairKindName(keyKind(c.key));
      }
    }
  }
  EXPECT_GT(shortcuts, 1000);  // the shortcut's own regime was reached, not only parting pairs
}

TEST(PairQuery, AParticleEdgePairIsNeverSettledByTheBound) {
  EXPECT_FALSE(cannotDeepen(PairKind::ParticleEdge, -1.0, 0.0, 1.0, 1.0));
  EXPECT_FALSE(cannotDeepen(PairKind::ParticleEdge, 0.0, 0.5, 1.0, 1e300));
  EXPECT_TRUE(cannotDeepen(PairKind::ParticleParticle, 0.0, 0.5, 1.0, 1.0));
  EXPECT_FALSE(cannotDeepen(PairKind::ParticleHalfPlane, 1.0, 0.5, 1.0, 1.0));
}

// A disk of radius 0.1 overlapping a still edge along the x axis (radius 0) 0.08 deep eases to
// 0.01 deep at t = 0.5 and sinks back to 0.05 deep at t = 1, along straight pieces. Its overlap
// at the end is shallower than at the start, yet it deepened by 0.04 after it eased: that is
// the deepening (--verify reports such a second approach). Depth is 0.1 - y, so the least depth
// before t = 1 is 0.01 (at the sample t = 0.5) and the rise is 0.05 - 0.01.
TEST(PairQuery, AnOverlapThatEasesAndDeepensAgainDeepensFromWhereItEased) {
  TestScene s;
  addBody(s, 1.0, Vec2(0, 0.02), Vec2::Zero(), 0.1);
  addBody(s, 1.0, Vec2(-1, 0), Vec2::Zero(), 0.0);
  addBody(s, 1.0, Vec2(1, 0), Vec2::Zero(), 0.0);
  s.scene.edges.push_back(Edge{1, 2, 0.0});
  const auto position = [&](int p, double t) -> Vec2 {
    if (p != 0) return at(s.state.x, p);
    const double y = t <= 0.5 ? 0.02 + (t / 0.5) * 0.07 : 0.09 - ((t - 0.5) / 0.5) * 0.04;
    return Vec2(0.0, y);
  };
  const uint64_t key = pairKey(0, PairKind::ParticleEdge, 0);
  double length = 0, when = -1;
  EXPECT_NEAR(pairDeepening(s.scene, key, position, 0.0, 1.0, length, &when), 0.04, 1e-15);
  EXPECT_EQ(when, 1.0);
  // From t = 0.5 on, it only sinks: 0.04 as well, from an overlap of 0.01 at t.
  EXPECT_NEAR(pairDeepening(s.scene, key, position, 0.5, 1.0, length), 0.04, 1e-15);
  // Easing all the way (t up to 0.5) is no deepening.
  EXPECT_LT(pairDeepening(s.scene, key, position, 0.0, 0.5, length), 0.0);
}

}  // namespace
}  // namespace fosssim::testing
