// The window's pacing of its steps: the scene's <maxsimfreq> steps per wall second, without
// falling into catching up for ever when the steps are slower than that, and the steps per
// second it shows, measured every half second. Apart from the window (glut_window.cpp) so that it
// is tested without a display: times are arguments, not read from the clock.
#pragma once

#include <chrono>

namespace fosssim::render {

class StepPacer {
 public:
  using Clock = std::chrono::steady_clock;

  /// stepsPerSecond: <maxsimfreq> (any positive value, 1e30 included); pacing starts at `now`.
  StepPacer(double stepsPerSecond, Clock::time_point now);

  /// Pacing starts again from `now` (a pause ends, the run restarts): no steps are due for the
  /// time before.
  void restart(Clock::time_point now);
  /// The steps due at `now` (since the pacing's start, less those taken), at most `left` (the
  /// run's steps still to take). Behind by more than a quarter of a second's steps, the pacing
  /// starts again from `now`: a scene whose steps are slower than the rate is not chased.
  long due(Clock::time_point now, long left);
  /// `steps` of the due steps were taken.
  void took(long steps) { anchorSteps_ += steps; }

  /// Measures the steps per second from the run's count of steps taken, at most every
  /// kRateSeconds; true when the rate shown changes (by more than half a step per second).
  bool measure(Clock::time_point now, long stepsTaken);
  double rate() const { return rate_; }

  static constexpr double kRateSeconds = 0.5;
  /// Behind by more than this share of a second's steps, pacing starts again.
  static constexpr double kCatchUpSeconds = 0.25;

 private:
  double stepsPerSecond_;
  Clock::time_point anchor_;  ///< steps are due since here ...
  long anchorSteps_ = 0;      ///< ... less these, taken since
  Clock::time_point rateTime_;
  long rateSteps_ = 0;
  double rate_ = 0;
};

}  // namespace fosssim::render
