// Internal header: the broad phase's index, a uniform grid of axis-aligned boxes.
//
// The cell size h is the largest extent of the ordinary boxes (those at most kLargeFactor times
// the median extent); each ordinary box is filed once, in the cell of its lower-left corner
// ("home cell"), by a counting sort, so cells are contiguous runs of one array and the cells of a
// grid row are contiguous too. A box b can only meet ordinary boxes whose home cell lies in
// [cell(b.x0 - h), cell(b.x1)] x [cell(b.y0 - h), cell(b.y1)]: one contiguous run per grid row,
// no box reported twice. The few larger boxes are kept in a list every query tests.
//
// The grid covers the home corners' bounding box (trimmed to a central percentile range when a
// few outliers would make it huge); corners outside are filed in the border cells, which keeps
// every query exact (clamping is monotone) at the price of fuller border cells. The cell count
// stays below about kCellsPerBox times the number of boxes (cells grow when the boxes are
// spread thin), so memory is linear in the boxes.
//
// Boxes that change after the build (a particle whose path a response bent) are re-filed with
// insert(): their home cells get a short list each, on top of the sorted entries, and the old
// entry is skipped from then on. An insertion costs O(1) and queries stay local, so a step's
// thousands of refreshed boxes need no rebuild until they are a good share of all (the owner
// decides when: inserted()).
//
// Why this and not the alternatives: bench/broad_phase_alternatives.cpp measures it against a
// spatial hash filing each box in every cell it covers and against sweep-and-prune (README,
// "Performance").
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
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
  /// Boxes wider or taller than this many median extents are not filed in cells.
  static constexpr double kLargeFactor = 4.0;
  /// At most about this many cells per box.
  static constexpr double kCellsPerBox = 2.0;

  /// Indexes the boxes boxes[0, count) (box id k is boxes[k]). Boxes are copied; they must not
  /// contain NaN (callers check every pair for non-finite states). `threads`: the filing's (the
  /// same grid for any count).
  void build(const Box* boxes, int count, int threads = 1);

  /// Files box `id` anew with box b (id as indexed by the build; its earlier box, sorted or
  /// inserted, no longer counts). b must not contain NaN.
  void insert(int id, const Box& b);
  /// Boxes inserted since the build (re-filed ones count again).
  int inserted() const { return static_cast<int>(dynamic_.size()); }

  /// Calls visit(id) exactly once for every indexed box that overlaps b (its latest box).
  template <class Visit>
  void forEachOverlap(const Box& query, Visit&& visit) const {
    forEachOverlapFrom(query, std::numeric_limits<int>::min(), visit);
  }
  /// The same for the boxes with id >= firstId only. The id is tested before the box: a row's
  /// query (the particles after i) then skips about half the boxes without reading them.
  template <class Visit>
  void forEachOverlapFrom(const Box& query, int firstId, Visit&& visit) const;

  int size() const { return count_; }
  /// Bytes held (capacity), for the benchmark's memory figures.
  size_t memoryBytes() const;

 private:
  double chooseCell(const Box* boxes, int count);
  void forgetInserted();
  int column(double x) const { return clamp((x - originX_) * inverseCell_, columns_); }
  int row(double y) const { return clamp((y - originY_) * inverseCell_, rows_); }
  /// floor(v) clamped to [0, n - 1]; monotone in v, so ranges of coordinates map to ranges.
  static int clamp(double v, int n) {
    if (!(v >= 0)) return 0;
    if (v >= n - 1) return n - 1;
    return static_cast<int>(v);
  }

  int count_ = 0;  ///< boxes indexed by the build: ids 0..count_-1
  /// The lower-left corner of cell (0, 0), the cell size h and 1/h.
  double originX_ = 0, originY_ = 0, cell_ = 1, inverseCell_ = 1;
  int columns_ = 1, rows_ = 1;  ///< the grid in cells: columns_ x rows_, numbered row by row
  std::vector<int> start_;     ///< per cell (row-major), its first entry; one more at the end
  std::vector<Box> boxes_;     ///< entries' boxes, cell by cell
  std::vector<int> ids_;       ///< entries' ids, parallel to boxes_
  std::vector<Box> largeBoxes_;  ///< the boxes too large for the cells, by ascending id
  std::vector<int> largeIds_;    ///< their ids, parallel to largeBoxes_
  /// A box inserted after the build, in its home cell's list (or the large ones').
  struct Inserted {
    Box box;   ///< the box it files
    int id;    ///< the box's id, as indexed by the build
    int next;  ///< the next entry of the same list, -1 at its end
  };
  std::vector<Inserted> dynamic_;  ///< the entries inserted since the build, in insertion order
  std::vector<int> head_;          ///< per cell: its first inserted entry, -1 if none (empty: none yet)
  std::vector<int> dynamicLarge_;  ///< inserted entries too large for the cells
  std::vector<int> live_;          ///< per id: its inserted entry, -1 while its sorted entry holds
  std::vector<int> touched_;       ///< cells whose head_ is set
  std::vector<int> home_;      ///< scratch: each box's cell, or -1 for a large one
  std::vector<int> cursor_;    ///< scratch: per cell, where its next entry goes
  std::vector<int> bandStart_; ///< scratch: per band of cells (one per thread), its first entry
  std::vector<double> scratch_;  ///< scratch: the sampled extents (chooseCell) or corner coordinates (the trim)
};

template <class Visit>
void BoxGrid::forEachOverlapFrom(const Box& query, int firstId, Visit&& visit) const {
  // The query and the arrays in locals: visit() writes memory (a caller's vector) that the
  // compiler must otherwise assume aliases them, and would reload them for every entry.
  const Box b = query;
  const Box* boxes = boxes_.data();
  const int* ids = ids_.data();
  const int* live = live_.data();
  // With insertions, a sorted entry counts only while its id has not been re-filed; an inserted
  // one only while it is its id's latest.
  const bool refiled = !dynamic_.empty();
  for (size_t k = 0; k < largeIds_.size(); ++k)
    if (largeIds_[k] >= firstId && overlap(b, largeBoxes_[k]) && (!refiled || live[largeIds_[k]] < 0))
      visit(largeIds_[k]);
  const int x0 = column(b.x0 - cell_), x1 = column(b.x1), y0 = row(b.y0 - cell_), y1 = row(b.y1);
  if (!boxes_.empty()) {
    const int* start = start_.data();
    const int columns = columns_;
    for (int y = y0; y <= y1; ++y) {
      const int* first = start + static_cast<size_t>(y) * columns;
      for (int e = first[x0], end = first[x1 + 1]; e < end; ++e)
        if (ids[e] >= firstId && overlap(b, boxes[e]) && (!refiled || live[ids[e]] < 0)) visit(ids[e]);
    }
  }
  if (!refiled) return;
  const Inserted* dynamic = dynamic_.data();
  auto visitLive = [&](int k) {
    if (dynamic[k].id >= firstId && live[dynamic[k].id] == k && overlap(b, dynamic[k].box)) visit(dynamic[k].id);
  };
  for (int k : dynamicLarge_) visitLive(k);
  const int* head = head_.data();
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      for (int k = head[static_cast<size_t>(y) * columns_ + x]; k >= 0; k = dynamic[k].next) visitLive(k);
}

}  // namespace fosssim
