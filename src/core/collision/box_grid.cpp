#include "box_grid.h"

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

/// The cell size is this percentile of the boxes' extents: most boxes cover at most 2 x 2
/// cells, and a few large or fast ones neither coarsen the grid nor (up to kMaxCellsPerBox
/// cells) leave it.
constexpr double kCellPercentile = 0.9;

/// Buckets per registered cell entry (at least): keeps hash collisions rare.
constexpr int kBucketsPerEntry = 2;

}  // namespace

void BoxGrid::build(const Box* boxes, int count) {
  boxes_ = boxes;
  count_ = count;
  large_.clear();

  // Cell size and origin from the finite boxes (boxes with infinite bounds come from infinite
  // margins and go to the large list).
  extents_.clear();
  double minX = 0, minY = 0;
  bool first = true;
  for (int k = 0; k < count; ++k) {
    const Box& b = boxes[k];
    const double extent = std::max(b.x1 - b.x0, b.y1 - b.y0);
    if (!std::isfinite(extent)) continue;
    extents_.push_back(extent);
    minX = first ? b.x0 : std::min(minX, b.x0);
    minY = first ? b.y0 : std::min(minY, b.y0);
    first = false;
  }
  double cell = 1.0;
  if (!extents_.empty()) {
    const auto nth = extents_.begin() + static_cast<long>(kCellPercentile * (extents_.size() - 1));
    std::nth_element(extents_.begin(), nth, extents_.end());
    if (*nth > 0 && std::isfinite(*nth)) cell = *nth;
  }
  originX_ = minX;
  originY_ = minY;
  inverseCell_ = 1.0 / cell;

  // Count the entries, size the table, count per bucket, fill (ascending box index per bucket).
  long entries = 0;
  for (int k = 0; k < count; ++k) {
    const long cells = cellsCovered(boxes[k]);
    if (cells > kMaxCellsPerBox) large_.push_back(k);
    else entries += cells;
  }
  uint32_t buckets = 16;
  while (buckets < kBucketsPerEntry * entries && buckets < (1u << 30)) buckets <<= 1;
  mask_ = buckets - 1;
  start_.assign(buckets + 1, 0);
  entries_.resize(static_cast<size_t>(entries));
  auto forEachCell = [&](const Box& b, auto&& f) {
    const int x0 = cellX(b.x0), x1 = cellX(b.x1), y0 = cellY(b.y0), y1 = cellY(b.y1);
    for (int cy = y0; cy <= y1; ++cy)
      for (int cx = x0; cx <= x1; ++cx) f(bucket(cx, cy));
  };
  size_t nextLarge = 0;
  for (int k = 0; k < count; ++k) {
    if (nextLarge < large_.size() && large_[nextLarge] == k) {
      ++nextLarge;
      continue;
    }
    forEachCell(boxes[k], [&](uint32_t h) { ++start_[h + 1]; });
  }
  for (uint32_t h = 0; h < buckets; ++h) start_[h + 1] += start_[h];
  // Fill using start_[h] as the cursor, then shift back: start_[h] ends at the old start_[h+1].
  nextLarge = 0;
  for (int k = 0; k < count; ++k) {
    if (nextLarge < large_.size() && large_[nextLarge] == k) {
      ++nextLarge;
      continue;
    }
    forEachCell(boxes[k], [&](uint32_t h) { entries_[start_[h]++] = k; });
  }
  for (uint32_t h = buckets; h > 0; --h) start_[h] = start_[h - 1];
  start_[0] = 0;
}

size_t BoxGrid::memoryBytes() const {
  return start_.capacity() * sizeof(int) + entries_.capacity() * sizeof(int) + large_.capacity() * sizeof(int) +
         extents_.capacity() * sizeof(double);
}

}  // namespace fosssim
