#include "box_grid.h"

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

void BoxGrid::clear() {
  count_ = 0;
  start_.assign(2, 0);
  columns_ = rows_ = 1;
  boxes_.clear();
  ids_.clear();
  largeBoxes_.clear();
  largeIds_.clear();
}

double BoxGrid::chooseCell(const Box* boxes, int count, const int* ids) {
  // The largest extent among the boxes no larger than kLargeFactor medians.
  scratch_.clear();
  for (int k = 0; k < count; ++k) {
    const double e = extent(boxes[ids ? ids[k] : k]);
    if (std::isfinite(e)) scratch_.push_back(e);
  }
  if (scratch_.empty()) return 1.0;  // every box is infinite: all go to the large list
  // The median of an evenly spaced sample (the grid affects speed only, never results).
  const size_t stride = std::max<size_t>(1, scratch_.size() / kMedianSample);
  size_t sampled = 0;
  for (size_t k = 0; k < scratch_.size(); k += stride) std::swap(scratch_[sampled++], scratch_[k]);
  auto middle = scratch_.begin() + static_cast<long>(sampled / 2);
  std::nth_element(scratch_.begin(), middle, scratch_.begin() + static_cast<long>(sampled));
  const double limit = kLargeFactor * *middle;
  double largest = 0;
  for (double e : scratch_)
    if (e <= limit && e > largest) largest = e;
  return largest > 0 ? largest / kExtentSlack : 1.0;
}

void BoxGrid::build(const Box* boxes, int count, const int* ids, double imposedCell) {
  clear();
  count_ = count;
  auto idOf = [&](int k) { return ids ? ids[k] : k; };
  double cell = imposedCell > 0 ? imposedCell : chooseCell(boxes, count, ids);
  // Which boxes are ordinary, and the bounding box of their lower corners.
  home_.resize(count);
  double minX = 0, minY = 0, maxX = 0, maxY = 0;
  int ordinary = 0;
  for (int k = 0; k < count; ++k) {
    const Box& b = boxes[idOf(k)];
    const bool large = !(b.x1 - b.x0 <= kExtentSlack * cell && b.y1 - b.y0 <= kExtentSlack * cell);
    home_[k] = large ? -1 : 0;
    if (large) {
      largeBoxes_.push_back(b);
      largeIds_.push_back(idOf(k));
      continue;
    }
    minX = ordinary ? std::min(minX, b.x0) : b.x0;
    maxX = ordinary ? std::max(maxX, b.x0) : b.x0;
    minY = ordinary ? std::min(minY, b.y0) : b.y0;
    maxY = ordinary ? std::max(maxY, b.y0) : b.y0;
    ++ordinary;
  }
  if (ordinary == 0) return;
  const double maxCells = kCellsPerBox * ordinary + 64;
  auto cellsFor = [&](double c) { return (std::floor((maxX - minX) / c) + 1) * (std::floor((maxY - minY) / c) + 1); };
  if (cellsFor(cell) > maxCells) {
    // A few far-away corners must not stretch the grid: keep the central range of each axis.
    // Percentiles of an evenly spaced sample of the corners (again: speed only, never results).
    const int stride = std::max(1, count / static_cast<int>(kMedianSample));
    auto trim = [&](bool yAxis, double& lo, double& hi) {
      scratch_.clear();
      for (int k = 0; k < count; k += stride)
        if (home_[k] >= 0) scratch_.push_back(yAxis ? boxes[idOf(k)].y0 : boxes[idOf(k)].x0);
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

  // Counting sort by home cell; entries of a cell keep ascending box order.
  const size_t cells = static_cast<size_t>(columns_) * rows_;
  start_.assign(cells + 1, 0);
  for (int k = 0; k < count; ++k) {
    if (home_[k] < 0) continue;
    const Box& b = boxes[idOf(k)];
    home_[k] = row(b.y0) * columns_ + column(b.x0);
    ++start_[home_[k] + 1];
  }
  for (size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
  boxes_.resize(ordinary);
  ids_.resize(ordinary);
  for (int k = 0; k < count; ++k) {  // start_[c] runs ahead as the cursor of cell c ...
    if (home_[k] < 0) continue;
    const int e = start_[home_[k]]++;
    boxes_[e] = boxes[idOf(k)];
    ids_[e] = idOf(k);
  }
  for (size_t c = cells; c > 0; --c) start_[c] = start_[c - 1];  // ... and is moved back
  start_[0] = 0;
}

size_t BoxGrid::memoryBytes() const {
  return start_.capacity() * sizeof(int) + boxes_.capacity() * sizeof(Box) + ids_.capacity() * sizeof(int) +
         largeBoxes_.capacity() * sizeof(Box) + largeIds_.capacity() * sizeof(int) + home_.capacity() * sizeof(int) +
         scratch_.capacity() * sizeof(double);
}

}  // namespace fosssim
