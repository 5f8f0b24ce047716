#include "box_grid.h"

#include "parallel_rows.h"

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

/// Ordinary boxes are at most this fraction of the cell size wide (and tall): their exact
/// extent then stays below the cell size whatever the rounding of the bounds.
constexpr double kExtentSlack = 0.999;

/// When outliers make the corners' bounding box too large, the grid covers this central range
/// of the corners' coordinates (per axis, from both ends) and files the rest at the border.
constexpr double kTrimmedFraction = 0.01;

/// Extents sampled for the median that sets the cell size.
constexpr size_t kMedianSample = 1024;

double extent(const Box& b) { return std::max(b.x1 - b.x0, b.y1 - b.y0); }

}  // namespace

// Every head_ entry is -1 again (only the touched ones were set), so head_ can simply grow to
// the next build's cell count.
void BoxGrid::forgetInserted() {
  for (int c : touched_) head_[c] = -1;
  touched_.clear();
  dynamic_.clear();
  dynamicLarge_.clear();
  live_.clear();
}

void BoxGrid::insert(int id, const Box& b) {
  if (live_.empty()) live_.assign(static_cast<size_t>(std::max(count_, id + 1)), -1);  // first since the build
  if (id >= static_cast<int>(live_.size())) live_.resize(static_cast<size_t>(id) + 1, -1);
  const size_t cells = static_cast<size_t>(columns_) * rows_;
  if (head_.size() < cells) head_.resize(cells, -1);
  const int k = static_cast<int>(dynamic_.size());
  dynamic_.push_back(Inserted{b, id, -1});
  live_[id] = k;
  if (!(b.x1 - b.x0 <= kExtentSlack * cell_ && b.y1 - b.y0 <= kExtentSlack * cell_)) {
    dynamicLarge_.push_back(k);
    return;
  }
  const int c = row(b.y0) * columns_ + column(b.x0);
  if (head_[c] < 0) touched_.push_back(c);
  dynamic_[k].next = head_[c];
  head_[c] = k;
}

double BoxGrid::chooseCell(const Box* boxes, int count) {
  // The largest extent among the boxes no larger than kLargeFactor medians. The median is that
  // of an evenly spaced sample (the grid affects speed only, never results).
  auto extentOf = [&](int k) { return extent(boxes[k]); };
  scratch_.clear();
  const int stride = std::max(1, count / static_cast<int>(kMedianSample));
  for (int k = 0; k < count; k += stride)
    if (std::isfinite(extentOf(k))) scratch_.push_back(extentOf(k));
  if (scratch_.empty())  // the sample is all infinite: the median of every finite box
    for (int k = 0; k < count; ++k)
      if (std::isfinite(extentOf(k))) scratch_.push_back(extentOf(k));
  if (scratch_.empty()) return 1.0;  // every box is infinite: all go to the large list
  auto middle = scratch_.begin() + static_cast<long>(scratch_.size() / 2);
  std::nth_element(scratch_.begin(), middle, scratch_.end());
  const double limit = kLargeFactor * *middle;
  double largest = 0;
  for (int k = 0; k < count; ++k) {
    const double e = extentOf(k);
    if (e <= limit && e > largest) largest = e;
  }
  return largest > 0 ? largest / kExtentSlack : 1.0;
}

void BoxGrid::build(const Box* boxes, int count, int threads) {
  // boxes_ and ids_ keep their storage: they are refilled below.
  count_ = count;
  start_.assign(2, 0);
  columns_ = rows_ = 1;
  largeBoxes_.clear();
  largeIds_.clear();
  forgetInserted();
  double cell = chooseCell(boxes, count);
  cell_ = cell;
  inverseCell_ = 1.0 / cell;
  // Which boxes are ordinary, and the bounding box of their lower corners.
  // By ranges of boxes (min and max do not depend on the order they are taken in); the large
  // boxes, few, are then listed in order.
  home_.resize(count);
  struct Corners {
    double minX = 0, minY = 0, maxX = 0, maxY = 0;
    int ordinary = 0, large = 0;
  };
  std::vector<Corners> ranges(static_cast<size_t>(rowRangesFor(count, threads)));
  forRowRanges(count, threads, [&](int range, int first, int end) {
    Corners c;
    for (int k = first; k < end; ++k) {
      const Box& b = boxes[k];
      const bool large = !(b.x1 - b.x0 <= kExtentSlack * cell && b.y1 - b.y0 <= kExtentSlack * cell);
      home_[k] = large ? -1 : 0;
      if (large) {
        ++c.large;
        continue;
      }
      c.minX = c.ordinary ? std::min(c.minX, b.x0) : b.x0;
      c.maxX = c.ordinary ? std::max(c.maxX, b.x0) : b.x0;
      c.minY = c.ordinary ? std::min(c.minY, b.y0) : b.y0;
      c.maxY = c.ordinary ? std::max(c.maxY, b.y0) : b.y0;
      ++c.ordinary;
    }
    ranges[range] = c;
  });
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  int ordinary = 0, large = 0;
  for (const Corners& c : ranges) {
    large += c.large;
    if (c.ordinary == 0) continue;
    minX = ordinary ? std::min(minX, c.minX) : c.minX;
    maxX = ordinary ? std::max(maxX, c.maxX) : c.maxX;
    minY = ordinary ? std::min(minY, c.minY) : c.minY;
    maxY = ordinary ? std::max(maxY, c.maxY) : c.maxY;
    ordinary += c.ordinary;
  }
  for (int k = 0; large > 0 && k < count; ++k)
    if (home_[k] < 0) largeBoxes_.push_back(boxes[k]), largeIds_.push_back(k);
  if (ordinary == 0) {
    boxes_.clear();
    ids_.clear();
    return;
  }
  const double maxCells = kCellsPerBox * ordinary + 64;
  auto cellsFor = [&](double c) { return (std::floor((maxX - minX) / c) + 1) * (std::floor((maxY - minY) / c) + 1); };
  if (cellsFor(cell) > maxCells) {
    // A few far-away corners must not stretch the grid: keep the central range of each axis.
    // Percentiles of an evenly spaced sample of the corners (again: speed only, never results).
    const int stride = std::max(1, count / static_cast<int>(kMedianSample));
    auto trim = [&](bool yAxis, double& lo, double& hi) {
      scratch_.clear();
      for (int k = 0; k < count; k += stride)
        if (home_[k] >= 0) scratch_.push_back(yAxis ? boxes[k].y0 : boxes[k].x0);
      if (scratch_.empty()) return;
      const long skip = static_cast<long>(kTrimmedFraction * static_cast<double>(scratch_.size()));
      std::nth_element(scratch_.begin(), scratch_.begin() + skip, scratch_.end());
      lo = scratch_[skip];
      std::nth_element(scratch_.begin(), scratch_.end() - 1 - skip, scratch_.end());
      hi = scratch_[scratch_.size() - 1 - skip];
    };
    trim(false, minX, maxX);
    trim(true, minY, maxY);
    // Boxes spread thin: larger cells (still exact, just fuller).
    const double cells = cellsFor(cell);
    if (cells > maxCells) cell *= std::sqrt(cells / maxCells) * 1.0001;
  }
  cell_ = cell;
  inverseCell_ = 1.0 / cell;
  originX_ = minX;
  originY_ = minY;
  columns_ = static_cast<int>(std::min(std::floor((maxX - minX) * inverseCell_) + 1, maxCells));
  rows_ = static_cast<int>(std::min(std::floor((maxY - minY) * inverseCell_) + 1, maxCells / columns_ + 1));

  // Counting sort by home cell; entries of a cell keep ascending box order. With threads, each
  // takes a band of cells (contiguous in the arrays) and files every box whose home lies in it,
  // in ascending box order: the arrays come out the same for any thread count.
  const size_t cells = static_cast<size_t>(columns_) * rows_;
  start_.assign(cells + 1, 0);
  cursor_.resize(cells);
  forRowRanges(count, threads, [&](int, int first, int end) {
    for (int k = first; k < end; ++k)
      if (home_[k] >= 0) home_[k] = row(boxes[k].y0) * columns_ + column(boxes[k].x0);
  });
  const int bands = rowRangesFor(count, threads);
  auto band = [&](int t) { return cells * static_cast<size_t>(t) / static_cast<size_t>(bands); };
  auto inBand = [&](int k, size_t lo, size_t hi) {
    return home_[k] >= 0 && static_cast<size_t>(home_[k]) >= lo && static_cast<size_t>(home_[k]) < hi;
  };
  // Each band's counts (start_[c + 1] for its cells c), summed within the band: start_[lo] is
  // the previous band's to write, so the band's own sums start from 0 there.
  bandStart_.assign(static_cast<size_t>(bands) + 1, 0);
  forRowRanges(count, threads, [&](int t, int, int) {
    const size_t lo = band(t), hi = band(t + 1);
    for (int k = 0; k < count; ++k)
      if (inBand(k, lo, hi)) ++start_[home_[k] + 1];
    for (size_t c = lo + 1; c < hi; ++c) start_[c + 1] += start_[c];
    bandStart_[t + 1] = hi > lo ? start_[hi] : 0;
  });
  for (int t = 0; t < bands; ++t) bandStart_[t + 1] += bandStart_[t];
  boxes_.resize(ordinary);
  ids_.resize(ordinary);
  forRowRanges(count, threads, [&](int t, int, int) {
    const size_t lo = band(t), hi = band(t + 1);
    for (size_t c = lo + 1; c <= hi; ++c) start_[c] += bandStart_[t];
    if (hi == lo) return;
    cursor_[lo] = bandStart_[t];  // start_[lo]: the band before writes it
    for (size_t c = lo + 1; c < hi; ++c) cursor_[c] = start_[c];
    for (int k = 0; k < count; ++k) {
      if (!inBand(k, lo, hi)) continue;
      const int e = cursor_[home_[k]]++;
      boxes_[e] = boxes[k];
      ids_[e] = k;
    }
  });
}

size_t BoxGrid::memoryBytes() const {
  return start_.capacity() * sizeof(int) + boxes_.capacity() * sizeof(Box) + ids_.capacity() * sizeof(int) +
         largeBoxes_.capacity() * sizeof(Box) + largeIds_.capacity() * sizeof(int) + home_.capacity() * sizeof(int) +
         scratch_.capacity() * sizeof(double) + (cursor_.capacity() + bandStart_.capacity()) * sizeof(int) +
         dynamic_.capacity() * sizeof(Inserted) +
         (head_.capacity() + dynamicLarge_.capacity() + live_.capacity() + touched_.capacity()) * sizeof(int);
}

}  // namespace fosssim
