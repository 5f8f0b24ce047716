// Internal header: what the penalty force keeps from one evaluation to the next (its near-pair
// search and lists). It lives in a ForceContext (force.h), owned by the caller (each Simulator
// owns one), never in the force: a scene and its forces are shared, read-only, by every
// simulator that runs it.
#pragma once

#include "core/collision/pair_candidates.h"

#include <vector>

namespace fosssim {

/// One pair within reach: n from particle i to the other object, the gap |n| - r1 - r2 - h < 0,
/// and who takes the opposite gradient (particle a; or edge a-b at alpha; or nobody, a = -1).
struct PenaltyPair {
  int i;
  Vec2 n;
  double length, gap;
  int a, b;
  double alpha;
};

struct PenaltyScratch {
  PairCandidates candidates;
  std::vector<std::vector<int>> rows;            ///< per range of rows: candidate scratch
  std::vector<std::vector<PenaltyPair>> found;   ///< per range of rows, with threads
  std::vector<char> skipRows;                    ///< N: rows of resting particles left unread
  std::vector<std::vector<int>> border;          ///< per range: resting particles met by moving ones
};

}  // namespace fosssim
