// Internal header: continuous-time detection of a whole step, the way the handlers need it, with
// the broad phase (pair_candidates.h) in front of the narrow phase (ContinuousDetector).
//
// Three forms, each giving exactly what checking every pair in the reference's order gives:
//   detectAll      every collision of the motion qs -> qe, in pair order;
//   detectChanged  the same after qe changed at a few particles since a previous detection: only
//                  pairs involving those particles are queried again, the others' collisions are
//                  carried over (a query is a function of its pair's positions alone);
//   sweep          the continuous-time handler's sequential pass: a response changes qe at once,
//                  and every later pair, the current particle's own included, sees the change.
// With a polynomial log (trajectory files, grading) every pair is queried in the reference's
// order whatever the broad phase says, since the reference's log holds every pair's
// polynomials. The same happens when all pairs are forced (HandlerOptions::allPairs) and when the
// state is not finite. One exception to "exactly": under --compat (IntervalRule::Reference) the
// reference's sign test at r -+ 1 cancels catastrophically for roots beyond ~1e8 steps and can
// report a far, slow pair at t = 0, as the reference does; the broad phase rules such pairs out.
// Runs that write or grade trajectories log polynomials, so they query every pair and match the
// reference there too. detectAll spreads its rows over threads (HandlerOptions::threads) and
// joins their collisions in row order (parallel_rows.h): the same result for any thread count.
#pragma once

#include "continuous_detection.h"
#include "pair_candidates.h"

#include "fosssim/core/collision_handler.h"

#include <chrono>
#include <functional>
#include <vector>

namespace fosssim {

class CollisionSearch {
 public:
  /// Candidates collected at a time before the narrow phase runs on them.
  static constexpr size_t kKeysPerBlock = 1 << 14;

  explicit CollisionSearch(const math::DetectionRules& rules, bool allPairs = false, int threads = 1)
      : detector_(rules), forceAll_(allPairs), threads_(threads) {
    candidates_.setMargins(Margins::Course);  // the course's narrow phase: its cut-off is absolute
  }

  /// Every collision of qs -> qe in pair order into `out`.
  void detectAll(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx, std::vector<Collision>& out);

  /// Every collision of qs -> qe into `out`, given that `previous` holds those of the last
  /// detectAll/detectChanged of this object on the same qs and qe vectors and that qe changed
  /// since then only at the particles in `changed` (duplicates allowed).
  void detectChanged(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx,
                     const std::vector<Collision>& previous, const std::vector<int>& changed,
                     std::vector<Collision>& out);

  /// Visits every pair in the reference's order and calls onHit for each collision. onHit may
  /// change qe, but only at the particles of the pair it is given.
  void sweep(const Scene& scene, const VecX& qs, VecX& qe, StepContext& ctx,
             const std::function<void(const Collision&)>& onHit);

  /// Bytes held by the broad phase and scratch lists (capacity), for the benchmark.
  size_t memoryBytes() const;
  /// Candidates per block (tests use small blocks to cross block boundaries often).
  void setBlockSize(size_t keys) { blockSize_ = keys > 0 ? keys : 1; }

 private:
  bool logging(const StepContext& ctx) const { return ctx.log && ctx.log->polynomials.enabled(); }
  /// Builds the broad phase; false when every pair must be checked (forced, logging, not finite).
  bool prepare(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx);
  /// Replaces `keys` with the candidate keys of the rows from `first` on (before `end`), in
  /// order, stopping after the row that brings them past a block's worth; returns the next row.
  int collectRows(int first, int end, std::vector<uint64_t>& keys, std::vector<int>& row) const;
  /// The narrow-phase query of one candidate.
  bool query(const Scene& scene, const VecX& qs, const VecX& qe, uint64_t key, Collision& hit, StepStats& stats) const;
  void referenceSweep(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx,
                      const std::function<void(const Collision&)>& onHit);

  ContinuousDetector detector_;    ///< the narrow phase: one pair's continuous-time query
  bool forceAll_;  ///< query every pair in the reference's order, without the broad phase (HandlerOptions::allPairs)
  int threads_;                    ///< threads for detectAll's rows and the broad phase's build
  size_t blockSize_ = kKeysPerBlock;  ///< candidates collected at a time before the narrow phase (setBlockSize)
  PairCandidates candidates_;      ///< the broad phase, built by prepare()
  const VecX* builtQs_ = nullptr;  ///< the vectors the broad phase was built on
  const VecX* builtQe_ = nullptr;  ///< ... its end positions (both null when not built)
  /// Candidate keys of the current block (detectChanged: the changed particles' pairs, sorted), and
  /// sweep's min-heap of later pairs of the particles a response moved.
  std::vector<uint64_t> keys_, extra_;
  std::vector<int> row_;       ///< scratch for forEachInRow (one row's candidates)
  std::vector<char> mark_;     ///< N: detectChanged's mark of the changed particles (all 0 between calls)
  struct alignas(64) Worker {  ///< one range of rows of a parallel detectAll (a cache line of its own)
    std::vector<uint64_t> keys;  ///< its current block of candidate keys
    std::vector<int> row;        ///< scratch for forEachInRow
    std::vector<Collision> out;  ///< its rows' collisions, in pair order
    StepStats stats;             ///< its counts and phase times (joinRangeStats adds them up)
  };
  std::vector<Worker> workers_;  ///< one per row range of the last parallel detectAll (grown, never shrunk)
};

/// Adds the counts of a detection's row ranges (range k's in stats(k)) to `total`; with timing,
/// the wall time since `start` is shared out between the broad and the narrow phase in the
/// proportion of the ranges' own times (with threads, their sum exceeds the wall time).
template <class RangeStats>
void joinRangeStats(int ranges, RangeStats&& stats, std::chrono::steady_clock::time_point start, bool timing,
                    StepStats& total) {
  double broad = 0, narrow = 0;
  for (int k = 0; k < ranges; ++k) {
    const StepStats& range = stats(k);
    total.candidatePairs += range.candidatePairs;
    for (int kind = 0; kind < 3; ++kind) total.queries[kind] += range.queries[kind];
    broad += range.broadPhase;
    narrow += range.narrowPhase;
  }
  if (!timing || broad + narrow <= 0) return;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  total.broadPhase += wall * broad / (broad + narrow);
  total.narrowPhase += wall * narrow / (broad + narrow);
}

inline uint64_t pairKey(const Collision& c) { return pairKey(c.i, c.kind, c.j); }

}  // namespace fosssim
