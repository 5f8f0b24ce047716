// The broad-phase designs measured before choosing one (README, "Performance"): each finds, for
// every particle i, the particles j > i whose swept boxes overlap i's, in ascending order (what
// the detection needs, in the reference's pair order). Box sets come from steps of the benchmark
// scenes; every method must find the same pairs (checked).
//   grid     the chosen one (src/core/collision/box_grid.h): a uniform grid filing each box in
//            the cell of its lower corner, cells contiguous by a counting sort
//   hash     a spatial hash filing each box in every cell it covers, one query per row with a
//            dedupe rule (the first implementation)
//   sap      sweep and prune: boxes sorted by their lower x, each swept against the following
//            ones while they can overlap in x; the pairs are then sorted into row order
#pragma once

#include <string>
#include <vector>

namespace fosssim::bench {

struct BroadPhaseTiming {
  std::string scene;
  int n = 0;
  std::string method;
  double buildMs = 0;  ///< building the index (sorting for sap)
  double queryMs = 0;  ///< producing the ordered candidates of every row
  long pairs = 0;
};

/// Times the three methods on box sets of the given scenes and sizes (best of `repeats`).
std::vector<BroadPhaseTiming> compareBroadPhases(const std::vector<std::string>& scenes, const std::vector<int>& sizes,
                                                 int repeats);

}  // namespace fosssim::bench
