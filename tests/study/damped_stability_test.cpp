// The damped spring's stability limits: the closed forms (damped_stability.h) checked against
// the eigenvalues of each method's one-step map, and the study's measured limits (the simulator
// stepping the spring) checked against the closed forms within one step of the sweep's grid.
#include "damped_stability.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

/// Largest eigenvalue modulus of one step of `integrator` on u'' = -w^2 u - 2 g u', written out
/// from the method's update rule (not from the closed form's algebra).
double spectralRadius(const std::string& integrator, double w, double g, double h) {
  Eigen::Matrix2d a;
  if (integrator == "explicit-euler") {
    // u' = u + h v; v' = v + h (-w^2 u - 2 g v)
    a << 1, h, -w * w * h, 1 - 2 * g * h;
  } else {
    // v' = v + h (-w^2 u - 2 g v); u' = u + h v'
    const double vu = -w * w * h, vv = 1 - 2 * g * h;
    a << 1 + h * vu, h * vv, vu, vv;
  }
  return a.eigenvalues().cwiseAbs().maxCoeff();
}

TEST(StudyDampedStability, ClosedFormsAreWhereTheSpectralRadiusCrossesOne) {
  const double w = 10;
  for (const char* integrator : {"explicit-euler", "symplectic-euler"}) {
    for (double zeta : {0.02, 0.3, 1.0, 1.5, 5.0}) {
      const double g = zeta * w;
      const double h = dampedStabilityLimit(integrator, w, g);
      ASSERT_TRUE(std::isfinite(h)) << integrator << " zeta " << zeta;
      EXPECT_LT(spectralRadius(integrator, w, g, 0.999 * h), 1.0) << integrator << " zeta " << zeta;
      EXPECT_GT(spectralRadius(integrator, w, g, 1.001 * h), 1.0) << integrator << " zeta " << zeta;
      // Stable all the way down: the stable set is the interval (0, h).
      for (double f : {0.01, 0.1, 0.5, 0.9}) EXPECT_LT(spectralRadius(integrator, w, g, f * h), 1.0);
    }
  }
  // The familiar special cases: b / k for explicit Euler, 2 / w for symplectic Euler undamped.
  EXPECT_NEAR(dampedStabilityLimit("explicit-euler", w, 1.0), 2.0 / 100, 1e-15);
  EXPECT_NEAR(dampedStabilityLimit("symplectic-euler", w, 0.0), 0.2, 1e-15);
  EXPECT_TRUE(std::isnan(dampedStabilityLimit("explicit-euler", w, 0.0)));
  EXPECT_TRUE(std::isnan(dampedStabilityLimit("implicit-euler", w, 1.0)));
}

TEST(StudyDampedStability, ProbeTellsGrowthFromDecay) {
  const double w = 10, g = 1;  // explicit Euler's limit: 2 g / w^2 = 0.02
  EXPECT_TRUE(probeDamped("explicit-euler", w, g, 0.019, 20000).stable);
  const DampedProbe grows = probeDamped("explicit-euler", w, g, 0.021, 20000);
  EXPECT_FALSE(grows.stable);
  EXPECT_GT(grows.growth, 0);
}

// The measured limit (largest stable grid step) lies within one grid step of the closed form.
TEST(StudyDampedStability, MeasuredLimitsMatchTheClosedForms) {
  const double w = 10;
  for (const char* integrator : {"explicit-euler", "symplectic-euler"}) {
    for (double zeta : {0.1, 1.0, 3.0}) {
      const double g = zeta * w;
      const DampedLimit limit = findDampedLimit(integrator, w, g, 20000);
      const double exact = dampedStabilityLimit(integrator, w, g);
      ASSERT_GE(limit.index, 0) << integrator << " zeta " << zeta;
      ASSERT_FALSE(limit.capped);
      const double step = limit.smallestUnstable() - limit.largestStable();
      EXPECT_LE(std::abs(limit.largestStable() - exact), step) << integrator << " zeta " << zeta;
    }
  }
}

TEST(StudyDampedStability, UndampedAndImplicitLimits) {
  const double w = 10;
  const DampedLimit explicitEuler = findDampedLimit("explicit-euler", w, 0.0, 20000);
  EXPECT_EQ(explicitEuler.index, -1);  // grew even at w h = 0.01
  // Undamped, symplectic Euler is neutrally stable up to w h = 2: bounded, so stable.
  const DampedLimit symplectic = findDampedLimit("symplectic-euler", w, 0.0, 20000);
  EXPECT_LE(std::abs(symplectic.largestStable() - 2 / w), symplectic.smallestUnstable() - symplectic.largestStable());
  const DampedLimit implicitEuler = findDampedLimit("implicit-euler", w, 0.0, 2000);
  EXPECT_TRUE(implicitEuler.capped);  // held at w h = 100
}

}  // namespace
}  // namespace fosssim::study
