#pragma once
// ContactProjector's two innermost updates, shared by the translation units that make updates
// (contact_projector.cpp's Gauss-Seidel solve, contact_projector_alone.cpp's exact one) and forced
// inline where the compiler's own choice was measured to cost (GCC and Clang). Internal to
// fosssim_math: not installed.

#include "fosssim/math/contact_projector.h"

#if defined(__GNUC__)
#define FOSSSIM_ALWAYS_INLINE __attribute__((always_inline))
#else
#define FOSSSIM_ALWAYS_INLINE
#endif

namespace fosssim::math {

// Sets row k's multiplier to `lambda`: its movable bodies' velocities change by
// w_b coef_b (lambda - old), and their other rows are queued (row k itself is satisfied by a
// Gauss-Seidel update; a warm start has it queued by addRow). Inlined into solve's loop, which
// calls it for every update (GCC otherwise kept the call: rain and chains at N = 1,000-2,500
// took 3-5% longer per step, fastest of 18 runs each).
FOSSSIM_ALWAYS_INLINE inline void ContactProjector::apply(int k, double lambda) {
  touch(k);
  Row& row = row_[k];
  const double delta = lambda - row.lambda;
  row.lambda = lambda;
  for (int m = 0; m < row.r.count; ++m) {
    const int s = row.r.body[m];
    if (inverseMass_[s] == 0.0) continue;
    markChanged(s);
    velocity_[s] += inverseMass_[s] * delta * row.r.coef[m];
  }
  for (int m = 0; m < row.r.count; ++m)
    if (inverseMass_[row.r.body[m]] != 0.0) queueRowsOf(row.r.body[m], k);
}

// Without a branch per row: whether a row is queued already is a coin toss in a pile. The slot
// past the queue's end is written either way and kept only when the row is new to the queue
// (the order is queue()'s).
FOSSSIM_ALWAYS_INLINE inline void ContactProjector::queueRowsOf(int slot, int except) {
  const Body& body = body_[slot];
  makeRoom(static_cast<size_t>(body.rowCount));
  int* work = work_.data();
  char* queued = queued_.data();
  size_t tail = tail_;
  body.forEachRow([&](int k) {
    const bool add = (k != except) & (queued[k] == 0);
    work[tail] = k;
    queued[k] = static_cast<char>(queued[k] | add);
    tail += add;
  });
  tail_ = tail;
}

}  // namespace fosssim::math
