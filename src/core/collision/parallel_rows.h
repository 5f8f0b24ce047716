// Internal header: rows of the pair order split across threads, deterministically.
//
// The broad and narrow phases work row by row (particle i's pairs), and a row's result depends on
// nothing but the positions. So [0, n) is cut into contiguous ranges, one per thread, each
// range's results are collected on its own, and the caller joins them in range order: the joined
// result is the row-ordered one, whatever the thread count, the cut or the scheduling. OpenMP
// runs the ranges (without it, or for small n, one range on the calling thread).
#pragma once

#include "fosssim/core/types.h"

#include <algorithm>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace fosssim {

/// Fewer rows than this per thread are not worth waking a thread for.
constexpr int kMinRowsPerThread = 2048;

/// How many ranges forRowRanges will use at most for n rows and `threads` requested.
inline int rowRangesFor(int n, int threads) {
#ifdef _OPENMP
  return std::max(1, std::min(threads, n / kMinRowsPerThread));
#else
  (void)n, (void)threads;
  return 1;
#endif
}

/// Calls body(range, first, end) for contiguous ranges [first, end) covering [0, n), range <
/// rowRangesFor(n, threads), all at once on as many threads.
template <class Body>
void forRowRanges(int n, int threads, Body&& body) {
  const int ranges = rowRangesFor(n, threads);
  if (ranges <= 1) {
    body(0, 0, n);
    return;
  }
#ifdef _OPENMP
#pragma omp parallel num_threads(ranges)
  {
    const long k = omp_get_thread_num(), count = omp_get_num_threads();
    body(static_cast<int>(k), static_cast<int>(n * k / count), static_cast<int>(n * (k + 1) / count));
  }
#endif
}

/// to = from, for a vector of two entries per particle (positions, velocities, 2N), by ranges of
/// particles on `threads` (large copies are a per-step cost of their own).
inline void copyByParticles(const VecX& from, VecX& to, int threads) {
  to.resize(from.size());
  forRowRanges(static_cast<int>(from.size() / 2), threads, [&](int, int first, int end) {
    to.segment(2L * first, 2L * (end - first)) = from.segment(2L * first, 2L * (end - first));
  });
  if (from.size() % 2 != 0) to[from.size() - 1] = from[from.size() - 1];
}

}  // namespace fosssim
