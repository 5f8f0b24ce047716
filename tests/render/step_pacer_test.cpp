// The window's pacing (src/render/step_pacer.h), on a clock the test sets: steps due at the
// scene's rate, the run's steps left as a bound (also at a rate beyond any long), no chasing of a
// scene whose steps are slower than the rate, and the rate shown, measured every half second.
#include "../../src/render/step_pacer.h"

#include <gtest/gtest.h>

namespace fosssim::render {
namespace {

using Clock = StepPacer::Clock;

Clock::time_point at(double seconds) {
  return Clock::time_point(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds)));
}

TEST(StepPacer, StepsAreDueAtTheRateLessThoseTaken) {
  StepPacer pacer(100.0, at(0));
  EXPECT_EQ(pacer.due(at(0.0), 1000), 0);
  EXPECT_EQ(pacer.due(at(0.1), 1000), 10);  // 100 steps/s for 0.1 s
  pacer.took(10);
  EXPECT_EQ(pacer.due(at(0.15), 1000), 5);
  pacer.took(4);  // one fell behind: still due
  EXPECT_EQ(pacer.due(at(0.2), 1000), 6);
}

TEST(StepPacer, TheStepsLeftBoundWhatIsDueAtAnyRate) {
  StepPacer slow(100.0, at(0));
  EXPECT_EQ(slow.due(at(0.1), 3), 3);
  // 1e30 steps a second: due is beyond any long, and converting it was undefined (it came out
  // negative, and the window never stepped).
  StepPacer fast(1e30, at(0));
  EXPECT_EQ(fast.due(at(0.01), 250), 250);
}

TEST(StepPacer, AScenePacedSlowerThanItsRateIsNotChased) {
  StepPacer pacer(100.0, at(0));
  // Nothing taken for a second: 100 steps due, more than a quarter second's 25, so the pacing
  // starts again from now (the 100 are still handed out this once)...
  EXPECT_EQ(pacer.due(at(1.0), 1000), 100);
  pacer.took(3);  // ... of which the slow steps took 3 within the tick
  // ... and 50 ms later 5 steps are due since the new start, less those 3: not the 97 left behind.
  EXPECT_EQ(pacer.due(at(1.05), 1000), 2);
}

TEST(StepPacer, ARestartDropsTheStepsDueBeforeIt) {
  StepPacer pacer(100.0, at(0));
  pacer.restart(at(0.2));  // a pause ended
  EXPECT_EQ(pacer.due(at(0.25), 1000), 5);
}

TEST(StepPacer, TheRateIsMeasuredEveryHalfSecond) {
  StepPacer pacer(100.0, at(0));
  EXPECT_FALSE(pacer.measure(at(0.4), 40));  // too soon
  EXPECT_TRUE(pacer.measure(at(0.5), 50));
  EXPECT_DOUBLE_EQ(pacer.rate(), 100.0);
  EXPECT_FALSE(pacer.measure(at(1.0), 100));  // the same rate: nothing to show anew
  EXPECT_TRUE(pacer.measure(at(1.5), 125));
  EXPECT_DOUBLE_EQ(pacer.rate(), 50.0);
}

}  // namespace
}  // namespace fosssim::render
