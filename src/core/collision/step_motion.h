// Internal header: the motion of every particle within one step, as the time-ordered handler
// changes it (the default mode's contacts; see event_handler.h).
//
// Time is the step's fraction t in [0, 1]. Each particle moves on straight pieces: from its
// last change at time t0 it is at  x(t) = from + (t - t0) * rate,  where `rate` is its
// displacement per whole step (h times its velocity over the piece). A contact changes the rate
// of its particles at the contact time and starts a new piece there; nothing else moves them.
// Because contacts are handled in time order, at the current event time T every particle's
// motion over [T, 1] is a single straight piece: any pair can be tested over [T, 1] with the
// ordinary continuous-time query.
//
// The end of the step is  end = from + (1 - t0) * rate, kept up to date so that the broad phase
// (boxes from `from` to `end`) always covers what is left of each particle's motion. Each change
// is also recorded as a break (time, position) so that the whole step can be checked afterwards
// piece by piece (piecewise_verify.cpp).
#pragma once

#include "parallel_rows.h"

#include "fosssim/core/types.h"


#include <cstdint>
#include <vector>

namespace fosssim {

/// Where particle p's path bends: at step fraction t it is at x.
struct MotionBreak {
  int particle = 0;
  double t = 0;
  Vec2 x = Vec2::Zero();
};

class StepMotion {
 public:
  /// Every particle on one piece from start (t = 0) to end (t = 1); by ranges of particles on
  /// `threads` (plain copies and differences: the same for any count).
  void begin(const VecX& start, const VecX& end, int threads = 1) {
    const int n = static_cast<int>(start.size() / 2);
    copyByParticles(start, from_, threads);
    copyByParticles(end, end_, threads);
    rate_.resize(start.size());
    forRowRanges(n, threads, [&](int, int first, int last) {
      rate_.segment(2L * first, 2L * (last - first)) =
          end.segment(2L * first, 2L * (last - first)) - start.segment(2L * first, 2L * (last - first));
    });
    t0_.assign(static_cast<size_t>(n), 0.0);
    if (version_.size() != t0_.size()) version_.assign(t0_.size(), 0);
    breaks_.clear();
  }

  Vec2 at(int p, double t) const { return fosssim::at(from_, p) + (t - t0_[p]) * fosssim::at(rate_, p); }
  /// Displacement per whole step on the current piece.
  Vec2 rate(int p) const { return fosssim::at(rate_, p); }
  double pieceStart(int p) const { return t0_[p]; }
  uint32_t version(int p) const { return version_[p]; }

  /// Changes particle p's rate from time t on (t >= its piece start): a new piece begins there.
  void setRate(int p, double t, const Vec2& rate) {
    const Vec2 x = at(p, t);
    fosssim::at(from_, p) = x;
    t0_[p] = t;
    fosssim::at(rate_, p) = rate;
    fosssim::at(end_, p) = x + (1.0 - t) * rate;
    ++version_[p];
    breaks_.push_back(MotionBreak{p, t, x});
  }

  /// Start of each particle's current piece and the end of the step (2N each): the vectors the
  /// broad phase boxes (they change in place).
  const VecX& from() const { return from_; }
  const VecX& end() const { return end_; }
  const std::vector<MotionBreak>& breaks() const { return breaks_; }

 private:
  VecX from_;   ///< 2N: position at the start of the current piece
  VecX end_;    ///< 2N: position at t = 1
  VecX rate_;   ///< 2N: displacement per whole step on the current piece
  std::vector<double> t0_;          ///< N: start time of the current piece
  std::vector<uint32_t> version_;   ///< N: bumped at every change (stale events are dropped)
  std::vector<MotionBreak> breaks_; ///< every change of the step, in time order
};

}  // namespace fosssim
