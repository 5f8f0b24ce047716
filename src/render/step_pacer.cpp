#include "step_pacer.h"

#include <cmath>

namespace fosssim::render {
namespace {

double seconds(StepPacer::Clock::duration d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

StepPacer::StepPacer(double stepsPerSecond, Clock::time_point now)
    : stepsPerSecond_(stepsPerSecond), anchor_(now), rateTime_(now) {}

void StepPacer::restart(Clock::time_point now) {
  anchor_ = now;
  anchorSteps_ = 0;
}

long StepPacer::due(Clock::time_point now, long left) {
  const double due = seconds(now - anchor_) * stepsPerSecond_ - static_cast<double>(anchorSteps_);
  if (due > stepsPerSecond_ * kCatchUpSeconds) restart(now);
  // Compared in double: at <maxsimfreq max="1e30"/> `due` is beyond any long, and converting it
  // is undefined (it came out negative, and the window never stepped). The steps left bound it.
  return due >= static_cast<double>(left) ? left : due > 0 ? static_cast<long>(due) : 0L;
}

bool StepPacer::measure(Clock::time_point now, long stepsTaken) {
  const double dt = seconds(now - rateTime_);
  if (dt < kRateSeconds) return false;
  const double rate = static_cast<double>(stepsTaken - rateSteps_) / dt;
  rateTime_ = now;
  rateSteps_ = stepsTaken;
  if (!(std::abs(rate - rate_) > 0.5)) return false;
  rate_ = rate;
  return true;
}

}  // namespace fosssim::render
