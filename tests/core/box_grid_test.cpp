// The broad phase's grid against brute force: every indexed box that overlaps a query box is
// visited exactly once, nothing else is, for boxes of mixed sizes (some larger than the cell
// limit, some far-away outliers that make the grid trim its range), for every thread count (the
// threaded build files the boxes band by band and must give the same answers as the sequential
// one), and after boxes are re-filed (insert) any number of times: only each box's latest counts.
// Queries restricted to ids from a given one on (forEachOverlapFrom) give brute force's ids from there.
#include "core/collision/box_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace fosssim {
namespace {

std::vector<Box> randomBoxes(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Box> boxes(n);
  for (int k = 0; k < n; ++k) {
    const double x = 100 * unit(rng), y = 60 * unit(rng);
    double w = 0.05 + 0.3 * unit(rng), h = 0.05 + 0.3 * unit(rng);
    if (k % 97 == 0) w *= 40;                 // large: kept in the list every query tests
    const double far = k % 501 == 0 ? 1e6 : 0;  // outliers: the grid trims its range
    boxes[k] = Box{x + far, y - far, x + far + w, y - far + h};
  }
  return boxes;
}

/// The ids of the boxes that overlap q, by checking every box.
std::vector<int> bruteForce(const std::vector<Box>& boxes, const Box& q) {
  std::vector<int> out;
  for (int k = 0; k < static_cast<int>(boxes.size()); ++k)
    if (overlap(q, boxes[k])) out.push_back(k);
  return out;
}

/// A random query box in the boxes' region, every tenth one large.
Box randomQuery(std::mt19937& rng, int q) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double x = 110 * unit(rng) - 5, y = 70 * unit(rng) - 5, s = q % 10 == 0 ? 10.0 : 0.5;
  return Box{x, y, x + s * unit(rng), y + s * unit(rng)};
}

/// The ids visited for query q, sorted, failing on a repeat.
std::vector<int> visited(const BoxGrid& grid, const Box& q) {
  std::vector<int> out;
  grid.forEachOverlap(q, [&](int id) { out.push_back(id); });
  std::sort(out.begin(), out.end());
  EXPECT_TRUE(std::adjacent_find(out.begin(), out.end()) == out.end()) << "a box was visited twice";
  return out;
}

/// The ids >= first visited by forEachOverlapFrom for query q, sorted.
std::vector<int> visitedFrom(const BoxGrid& grid, const Box& q, int first) {
  std::vector<int> out;
  grid.forEachOverlapFrom(q, first, [&](int id) { out.push_back(id); });
  std::sort(out.begin(), out.end());
  return out;
}

/// bruteForce's ids >= first.
std::vector<int> bruteForceFrom(const std::vector<Box>& boxes, const Box& q, int first) {
  std::vector<int> out = bruteForce(boxes, q);
  out.erase(out.begin(), std::lower_bound(out.begin(), out.end(), first));
  return out;
}

TEST(BoxGrid, QueriesEqualBruteForceForAnyThreadCount) {
  std::mt19937 rng(7);
  const int n = 20000;  // several thousand boxes per thread: the threaded filing really runs
  const std::vector<Box> boxes = randomBoxes(rng, n);
  BoxGrid grids[3];
  for (int t = 0; t < 3; ++t) grids[t].build(boxes.data(), n, t + 1);
  for (int q = 0; q < 400; ++q) {
    const Box query = randomQuery(rng, q);
    const std::vector<int> expected = bruteForce(boxes, query);
    for (int t = 0; t < 3; ++t) ASSERT_EQ(visited(grids[t], query), expected) << "threads " << t + 1;
  }
  // The outliers are found too (filed in the border cells).
  const Box far{1e6, -1e6, 1e6 + 101, -1e6 + 61};
  std::vector<int> expected;
  for (int k = 0; k < n; k += 501) expected.push_back(k);
  for (int t = 0; t < 3; ++t) EXPECT_EQ(visited(grids[t], far), expected);
}

TEST(BoxGrid, ReFiledBoxesReplaceTheirEarlierOnes) {
  std::mt19937 rng(11);
  const int n = 5000;
  std::vector<Box> boxes = randomBoxes(rng, n);
  BoxGrid grid;
  grid.build(boxes.data(), n);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int round = 0; round < 6; ++round) {
    // Move a few hundred boxes (some several times, some far away or growing large); the grid
    // must answer with the latest boxes, before and after a rebuild.
    for (int m = 0; m < 300; ++m) {
      const int id = static_cast<int>(unit(rng) * n) % n;
      const double x = 110 * unit(rng) - 5, y = 70 * unit(rng) - 5;
      const double w = m % 50 == 0 ? 30.0 : 0.05 + 0.3 * unit(rng), far = m % 77 == 0 ? -1e5 : 0.0;
      boxes[id] = Box{x + far, y, x + far + w, y + 0.2};
      grid.insert(id, boxes[id]);
    }
    for (int q = 0; q < 200; ++q) {
      const Box query = randomQuery(rng, q);
      ASSERT_EQ(visited(grid, query), bruteForce(boxes, query)) << "round " << round;
      // Only the ids from `first` on (a row's query): sorted, large and re-filed entries alike.
      const int first = static_cast<int>(unit(rng) * n);
      ASSERT_EQ(visitedFrom(grid, query, first), bruteForceFrom(boxes, query, first)) << "round " << round;
    }
    if (round == 3) grid.build(boxes.data(), n);  // a rebuild forgets the insertions
  }
}

TEST(BoxGrid, EmptyAndAllLargeIndexes) {
  BoxGrid grid;
  grid.build(nullptr, 0, 2);
  EXPECT_TRUE(visited(grid, Box{-1, -1, 1, 1}).empty());
  // Boxes whose extents are all infinite go to the large list and are still found.
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Box> boxes = {Box{-inf, 0, inf, 1}, Box{0, -inf, 1, inf}};
  grid.build(boxes.data(), 2, 2);
  EXPECT_EQ(visited(grid, Box{5, 0.5, 6, 0.6}), std::vector<int>({0}));
  EXPECT_EQ(visited(grid, Box{0.5, 0.5, 0.6, 0.6}), std::vector<int>({0, 1}));
}

}  // namespace
}  // namespace fosssim
