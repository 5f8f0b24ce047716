// The study's Newton-iteration runs against what Newton's method must do: the linear control
// (rest length 0: F = -k (x - a) per spring) is solved by the first update, so no step takes more
// than 2 (the second update is round-off) and, while the particle still moves by more than the
// tolerance, every step takes exactly 2; the springs of rest length 1 are nonlinear and take more,
// more at the larger step.
#include "experiments.h"

#include <gtest/gtest.h>

namespace fosssim::study {
namespace {

double meanIterations(const RunResult& r) { return static_cast<double>(r.newtonIterations) / r.steps; }

TEST(StudyNewtonIterations, LinearControlTakesAtMostTwoPerStep) {
  for (double k : {1e1, 1e5})
    for (double dt : {1e-3, 1e-1}) {
      const RunResult r = runTwoSprings(k, 0.0, dt);
      ASSERT_TRUE(r.ok()) << r.message;
      ASSERT_GT(r.steps, 0);
      EXPECT_EQ(r.mostNewtonIterations, 2) << "k " << k << " dt " << dt;
      EXPECT_LE(r.newtonIterations, 2 * r.steps) << "k " << k << " dt " << dt;
    }
  // Soft springs, small step: omega dt = 0.0045, the motion lasts the whole run.
  const RunResult moving = runTwoSprings(1e1, 0.0, 1e-3);
  EXPECT_EQ(moving.newtonIterations, 2 * moving.steps);
}

TEST(StudyNewtonIterations, NonlinearSpringsTakeMoreAtLargerSteps) {
  const RunResult fine = runTwoSprings(1e4, 1.0, 1e-4);
  const RunResult coarse = runTwoSprings(1e4, 1.0, 1e-2);
  ASSERT_TRUE(fine.ok()) << fine.message;
  ASSERT_TRUE(coarse.ok()) << coarse.message;
  EXPECT_GT(coarse.mostNewtonIterations, 2);
  EXPECT_GT(meanIterations(coarse), meanIterations(fine));
  EXPECT_GE(meanIterations(fine), 2.0);  // the particle moves: one update, then one below the tolerance
}

}  // namespace
}  // namespace fosssim::study
