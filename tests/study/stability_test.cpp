// Unstable runs are reported as unstable, with the reason, and the stability search finds the
// limits that theory gives for a single spring.
#include "stability.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

// Symplectic Euler on an undamped spring is stable exactly for omega h < 2.
TEST(StudyStability, SymplecticEulerPastOmegaHTwoIsReportedAsUnstable) {
  const double k = 100, omega = 10;
  const RunResult unstable = probeStability(1, k, "symplectic-euler", 2.2 / omega);
  EXPECT_FALSE(unstable.ok());
  EXPECT_EQ(unstable.outcome, Outcome::EnergyBlowUp) << unstable.message;
  EXPECT_NE(unstable.message.find("energy"), std::string::npos);
  const RunResult stable = probeStability(1, k, "symplectic-euler", 1.8 / omega);
  EXPECT_TRUE(stable.ok()) << stable.message;
}

// Without the energy watch the same run overflows; the simulator's error names the step and the
// particle, and the study records it as a non-finite state rather than stopping.
TEST(StudyStability, OverflowIsReportedAsNonFinite) {
  SceneFile file;
  ASSERT_TRUE(springRow(1, 1e6, "explicit-euler", 0.1).build("row.xml", file).isOk());
  RunOptions options;
  options.checkEnergy = false;
  options.steps = 100000;
  const RunResult r = runScene(file, options);
  EXPECT_EQ(r.outcome, Outcome::NonFinite);
  EXPECT_NE(r.message.find("particle 1"), std::string::npos) << r.message;
  EXPECT_LT(r.steps, 1000);
}

TEST(StudyStability, SearchFindsTheTheoreticalLimits) {
  const double k = 10, omega = std::sqrt(k);
  const StabilityLimit symplectic = findStabilityLimit(1, k, "symplectic-euler", 1e-2, 1e3);
  EXPECT_FALSE(symplectic.capped);
  EXPECT_NEAR(symplectic.largestStable * omega, 2.0, 0.02);
  // Explicit Euler's energy grows by 1 + (omega h)^2 every step: the limit is where that reaches
  // 1e6 within the horizon (10 periods, at least 200 steps).
  const StabilityLimit explicitEuler = findStabilityLimit(1, k, "explicit-euler", 1e-2, 1e3);
  const double s = explicitEuler.largestStable * omega;
  const double steps = static_cast<double>(stabilityHorizon(omega, explicitEuler.largestStable));
  EXPECT_NEAR(steps * std::log1p(s * s), std::log(1e6), 0.1);
  const StabilityLimit implicitEuler = findStabilityLimit(1, k, "implicit-euler", 1e-2, 1e3);
  EXPECT_TRUE(implicitEuler.capped);
}

TEST(StudyStability, HighestFrequencyOfARowMatchesItsStiffnessMatrix) {
  EXPECT_NEAR(highestFrequency(1, 4.0), 2.0, 1e-12);
  // Two bobs: K = k [[2, -1], [-1, 1]], eigenvalues k (3 +- sqrt 5)/2.
  EXPECT_NEAR(highestFrequency(2, 1.0), std::sqrt((3 + std::sqrt(5.0)) / 2), 1e-12);
}

}  // namespace
}  // namespace fosssim::study
