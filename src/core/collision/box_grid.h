// Internal header: the broad phase's index, a spatial hash of axis-aligned boxes.
//
// Boxes are registered in every cell of a uniform grid they cover; cells are hashed into a
// bucket table stored contiguously (compressed rows, rebuilt per use, storage kept between
// builds so that memory stays flat over a run). A query visits the cells its box covers and
// reports every registered box that overlaps it exactly once: a pair is reported only from the
// cell holding the lower corner of the two boxes' intersection (a cell both boxes cover).
// The cell size follows the boxes themselves (a high percentile of their extents), so one huge
// or very fast object does not coarsen the grid for all the others: boxes covering more than
// kMaxCellsPerBox cells are kept in a short list that every query tests directly.
//
// Why a hash grid: measured against sweep-and-prune and a dense grid in bench/ (see the README's
// "Performance" section); in short, sweep-and-prune degrades on dense 2D piles (every disk
// overlaps a whole column of the pile in x), and a dense grid needs the scene's bounding box,
// which one stray particle can make arbitrarily large.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fosssim {

/// A closed axis-aligned box [x0, x1] x [y0, y1].
struct Box {
  double x0, y0, x1, y1;
};

inline bool overlap(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

class BoxGrid {
 public:
  /// A box covering more cells than this is not hashed but tested by every query.
  static constexpr long kMaxCellsPerBox = 64;
  /// A query covering more cells than this tests every registered box instead.
  static constexpr long kMaxCellsPerQuery = 256;

  /// Indexes boxes[0, count). The array must outlive the grid's use and keep these boxes until
  /// the next build (callers that change a box later skip its stale entries themselves).
  /// Boxes must not contain NaN (callers fall back to all pairs for non-finite states).
  void build(const Box* boxes, int count);

  /// Calls visit(k) exactly once for every indexed k whose box overlaps b.
  template <class Visit>
  void forEachOverlap(const Box& b, Visit&& visit) const;

  int size() const { return count_; }
  /// Bytes held (capacity), for the benchmark's memory figures.
  size_t memoryBytes() const;

 private:
  int cellX(double x) const { return cellOf((x - originX_) * inverseCell_); }
  int cellY(double y) const { return cellOf((y - originY_) * inverseCell_); }
  /// Monotone in v (so a box's cells are an index range), clamped so the cast is defined.
  static int cellOf(double v) {
    constexpr double kLimit = 1 << 30;
    v = v < -kLimit ? -kLimit : (v > kLimit ? kLimit : v);
    const int c = static_cast<int>(v);
    return c - (static_cast<double>(c) > v);  // floor
  }
  uint32_t bucket(int cx, int cy) const {
    const uint32_t h = static_cast<uint32_t>(cx) * 0x9E3779B1u ^ static_cast<uint32_t>(cy) * 0x85EBCA77u;
    return (h ^ (h >> 15)) & mask_;
  }
  long cellsCovered(const Box& b) const {
    return (static_cast<long>(cellX(b.x1)) - cellX(b.x0) + 1) * (static_cast<long>(cellY(b.y1)) - cellY(b.y0) + 1);
  }

  const Box* boxes_ = nullptr;
  int count_ = 0;
  double originX_ = 0, originY_ = 0, inverseCell_ = 1;
  uint32_t mask_ = 0;
  std::vector<int> start_;    ///< per bucket, the first entry; one more at the end
  std::vector<int> entries_;  ///< box indices, ascending within a bucket
  std::vector<int> large_;    ///< boxes covering more than kMaxCellsPerBox cells
  std::vector<double> extents_;  ///< scratch for the cell size
};

template <class Visit>
void BoxGrid::forEachOverlap(const Box& b, Visit&& visit) const {
  for (int k : large_)
    if (overlap(b, boxes_[k])) visit(k);
  const int x0 = cellX(b.x0), x1 = cellX(b.x1), y0 = cellY(b.y0), y1 = cellY(b.y1);
  if ((static_cast<long>(x1) - x0 + 1) * (static_cast<long>(y1) - y0 + 1) > kMaxCellsPerQuery) {
    // A huge query box: testing every box is cheaper than visiting its cells. Large boxes were
    // reported above; the others are recognised by their cell count.
    for (int k = 0; k < count_; ++k)
      if (overlap(b, boxes_[k]) && cellsCovered(boxes_[k]) <= kMaxCellsPerBox) visit(k);
    return;
  }
  // One cell: every overlapping box covers it, so it is met once (its second entry in the same
  // bucket, from another cell hashing there, is adjacent and skipped).
  const bool oneCell = x0 == x1 && y0 == y1;
  for (int cy = y0; cy <= y1; ++cy) {
    for (int cx = x0; cx <= x1; ++cx) {
      const uint32_t h = bucket(cx, cy);
      int previous = -1;
      for (int p = start_[h], end = start_[h + 1]; p < end; ++p) {
        const int k = entries_[p];
        if (k == previous) continue;
        previous = k;
        const Box& o = boxes_[k];
        if (!overlap(b, o)) continue;
        if (!oneCell && (cellX(b.x0 > o.x0 ? b.x0 : o.x0) != cx || cellY(b.y0 > o.y0 ? b.y0 : o.y0) != cy))
          continue;  // reported from the cell of the intersection's lower corner
        visit(k);
      }
    }
  }
}

}  // namespace fosssim
