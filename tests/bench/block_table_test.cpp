// The block tables' measure of a scene's contacts (block_table.h's touchingPairs): the pairs of
// disks within kTouchingGap of their radius sum, counted the same way for every engine. Checked on
// configurations whose count is known by construction, and against a count over every pair.
#include "block_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace fosssim {
namespace {

/// A scene of disks with the given radii (unit masses), and positions laid out as given.
struct Disks {
  Scene scene;
  VecX x;
  void add(double px, double py, double r) {
    const int n = scene.numParticles();
    scene.radius.push_back(r);
    scene.fixed.push_back(0);
    scene.mass.conservativeResize(2 * n + 2);
    scene.mass.tail<2>().setOnes();
    x.conservativeResize(2 * n + 2);
    x.tail<2>() << px, py;
  }
};

long everyPair(const Disks& d) {
  long pairs = 0;
  const int n = d.scene.numParticles();
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const double reach = (1 + bench::kTouchingGap) * (d.scene.radius[i] + d.scene.radius[j]);
      pairs += (d.x.segment<2>(2 * j) - d.x.segment<2>(2 * i)).squaredNorm() <= reach * reach;
    }
  return pairs;
}

// Seven unit disks in a hexagon (a centre and six around it at distance 2) touch in 12 pairs:
// six spokes and the six sides of the ring (neighbours on a circle of radius 2, 60 degrees apart,
// are 2 apart). Placed across the origin, so the cells run negative.
TEST(TouchingPairs, AHexagonOfSevenDisksTouchesInTwelvePairs) {
  Disks d;
  d.add(-0.3, 0.2, 1.0);
  for (int k = 0; k < 6; ++k) {
    const double a = k * M_PI / 3;
    d.add(-0.3 + 2 * std::cos(a), 0.2 + 2 * std::sin(a), 1.0);
  }
  EXPECT_EQ(bench::touchingPairs(d.scene, d.x), 12);
}

// The gap: within 1% of the radius sum counts (Box2D's resting overlap and FOSSSim's resting gap
// both are), beyond it does not; different radii use their own sum.
TEST(TouchingPairs, CountsGapsWithinTheFractionAndOverlapsOnly) {
  Disks d;
  d.add(0, 0, 1.0);
  d.add(2.0 * 1.005, 0, 1.0);  // gap of half a per cent: touching
  Disks far;
  far.add(0, 0, 1.0);
  far.add(2.0 * 1.015, 0, 1.0);  // 1.5%: not
  Disks overlap;
  overlap.add(10, 10, 0.5);
  overlap.add(10, 10.9, 0.5);  // overlapping by a tenth
  Disks sizes;
  sizes.add(0, 0, 1.0);
  sizes.add(0, 1.5, 0.5);    // a small disk resting on a large one
  sizes.add(0, 1.5 + 1.0 + 1e-9, 0.5);  // and another small one on it (gap of 1e-9)
  EXPECT_EQ(bench::touchingPairs(d.scene, d.x), 1);
  EXPECT_EQ(bench::touchingPairs(far.scene, far.x), 0);
  EXPECT_EQ(bench::touchingPairs(overlap.scene, overlap.x), 1);
  EXPECT_EQ(bench::touchingPairs(sizes.scene, sizes.x), 2);
}

// NaN and infinite coordinates, and (as documented) one beyond 10^15 cells from the origin, are
// left out; the two finite disks near the origin still touch.
TEST(TouchingPairs, NonFinitePositionsTouchNothing) {
  Disks d;
  d.add(0, 0, 1.0);
  d.add(std::numeric_limits<double>::quiet_NaN(), 0, 1.0);
  d.add(1.9, 0, 1.0);
  d.add(std::numeric_limits<double>::infinity(), 0, 1.0);
  d.add(1e300, 0, 1.0);
  EXPECT_EQ(bench::touchingPairs(d.scene, d.x), 1);
}

// Random piles of disks of two sizes, dense enough that most disks touch something, against the
// count over every pair.
TEST(TouchingPairs, MatchesACountOverEveryPairOnRandomPiles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-6.0, 6.0);
  for (int trial = 0; trial < 20; ++trial) {
    Disks d;
    for (int i = 0; i < 400; ++i) {
      // x drawn before y, in separate statements: a call's arguments are evaluated in an order the
      // compiler picks (gcc right to left, clang left to right), and both must build the same piles.
      const double x = coordinate(rng);
      const double y = coordinate(rng);
      d.add(x, y, i % 3 == 0 ? 0.5 : 0.3);
    }
    const long expected = everyPair(d);
    EXPECT_GT(expected, 100);
    EXPECT_EQ(bench::touchingPairs(d.scene, d.x), expected) << "trial " << trial;
  }
}

}  // namespace
}  // namespace fosssim
