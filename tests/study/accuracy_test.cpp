// The accuracy measurement on the smallest case whose error is known exactly: explicit Euler on
// a projectile lags the parabola by g h T / 2, so halving dt halves the error (first order).
#include "experiments.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

const Problem& projectile() {
  static const std::vector<Problem> problems = integratorProblems(false);
  return problems.front();
}

Method explicitEuler() { return Method{"explicit-euler", "explicit-euler", CollisionChoice{}}; }

TEST(StudyAccuracy, ExplicitEulerOnAProjectileHasFirstOrderError) {
  ASSERT_EQ(projectile().name, "projectile");
  const StudyOptions options;
  std::vector<double> errors;
  for (double dt : {0.02, 0.01, 0.005, 0.0025}) {
    const AccuracyCell c = measureAccuracy(projectile(), explicitEuler(), dt, options, false);
    ASSERT_TRUE(c.run.ok()) << c.run.message;
    // The error constant, from x_n = x0 + n h v0 + g h^2 n (n - 1)/2 at t = n h = 2 s.
    EXPECT_NEAR(c.metrics.error, 9.81 * dt * 2.0 / 2, 1e-9) << dt;
    errors.push_back(c.metrics.error);
  }
  for (size_t k = 1; k < errors.size(); ++k) EXPECT_NEAR(std::log2(errors[k - 1] / errors[k]), 1.0, 1e-6);
}

// Velocities under a constant force are exact for every integrator; only positions lag or lead.
TEST(StudyAccuracy, ProjectileVelocitiesAreExactForEveryIntegrator) {
  for (const Method& m : integratorMethods()) {
    const AccuracyCell c = measureAccuracy(projectile(), m, 0.01, StudyOptions{}, false);
    ASSERT_TRUE(c.run.ok()) << m.label;
    EXPECT_LT(c.metrics.velocity, 1e-12) << m.label;
    EXPECT_NEAR(c.metrics.position, 9.81 * 0.01, 1e-9) << m.label;
  }
}

// A timed cell reports a positive wall time; an untimed one none.
TEST(StudyAccuracy, TimingIsReportedOnlyWhenAskedFor) {
  const AccuracyCell timed = measureAccuracy(projectile(), explicitEuler(), 0.01, StudyOptions{}, true);
  EXPECT_GT(timed.wallSeconds, 0);
  const AccuracyCell untimed = measureAccuracy(projectile(), explicitEuler(), 0.01, StudyOptions{}, false);
  EXPECT_TRUE(std::isnan(untimed.wallSeconds));
}

}  // namespace
}  // namespace fosssim::study
