// The energy error the study charts is the largest over the run (and its RMS), not the end
// point's: symplectic Euler's energy error oscillates, so the end point can be small by chance.
// These tests check the orders the study claims against their derivations.
#include "experiments.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

const Problem& problem(const std::string& name) {
  static const std::vector<Problem> problems = integratorProblems(false);
  for (const Problem& p : problems)
    if (p.name == name) return p;
  ADD_FAILURE() << "no problem " << name;
  return problems.front();
}

Method symplecticEuler() { return Method{"symplectic-euler", "symplectic-euler", CollisionChoice{}}; }

// On u'' = -w^2 u symplectic Euler (v' = v - h w^2 u, u' = u + h v') keeps
// Q = v^2 + w^2 u^2 - h w^2 u v exactly. From rest at u0, Q = w^2 u0^2 = 2 E0, and on that ellipse
// the energy E = (v^2 + w^2 u^2)/2 = (Q + h w^2 u v)/2 ranges over E0 [1/(1 + s/2), 1/(1 - s/2)]
// with s = w h: the largest relative error over the run is (s/2)/(1 - s/2), first order in h, and
// it does not grow with time.
TEST(StudyEnergyOrder, SymplecticEulerOnASpringHasTheModifiedEnergysBound) {
  const Problem& spring = problem("spring");
  const double w = std::sqrt(10.0);
  for (double dt : {0.01, 0.001}) {
    const AccuracyCell c = measureAccuracy(spring, symplecticEuler(), dt, StudyOptions{}, false);
    ASSERT_TRUE(c.run.ok()) << c.run.message;
    const double s = w * dt, bound = (s / 2) / (1 - s / 2);
    EXPECT_LE(c.metrics.energyMax, bound * (1 + 1e-9)) << dt;
    EXPECT_GT(c.metrics.energyMax, bound * (1 - 1e-3)) << dt;  // 5 periods come close to the extreme
    EXPECT_LT(c.metrics.energyRms, c.metrics.energyMax) << dt;
  }
}

// On the orbit the same holds by backward error analysis: symplectic Euler conserves a modified
// energy H + h H1 + O(h^2) exactly, so |H - H0| is bounded by C h over the whole run: halving dt
// halves the largest error (first order, not second). The end point's error does not follow.
TEST(StudyEnergyOrder, SymplecticEulerOnTheOrbitIsFirstOrderInTheLargestError) {
  const Problem& orbit = problem("orbit");
  double previous = 0;
  for (double dt : {0.002, 0.001, 0.0005}) {
    const AccuracyCell c = measureAccuracy(orbit, symplecticEuler(), dt, StudyOptions{}, false);
    ASSERT_TRUE(c.run.ok()) << c.run.message;
    EXPECT_LE(c.metrics.energy, c.metrics.energyMax);
    if (previous > 0) {
      EXPECT_NEAR(std::log2(previous / c.metrics.energyMax), 1.0, 0.1) << dt;
    }
    previous = c.metrics.energyMax;
  }
}

// Implicit Euler's Newton iteration fails on the orbit at dt = 0.05 after the orbit has already
// fallen inside the true periapsis a (1 - e): the closest approach is recorded for failed runs too.
TEST(StudyEnergyOrder, ImplicitEulersOrbitCollapsesBeforeNewtonFails) {
  const Problem& orbit = problem("orbit");
  const AccuracyCell c = measureAccuracy(orbit, Method{"implicit-euler", "implicit-euler", CollisionChoice{}}, 0.05,
                                         StudyOptions{}, false);
  ASSERT_EQ(c.run.outcome, Outcome::SolverFailure) << c.run.message;
  EXPECT_LT(c.metrics.minSeparation, orbit.exactMinSeparation);
  // The periapsis from vis-viva: a = 0.770, e = 0.41 (closed_forms_test checks KeplerOrbit).
  EXPECT_NEAR(orbit.exactMinSeparation, 0.770 * (1 - 0.41), 0.01);
}

// Explicit Euler on the undamped spring at dt = 0.1 grows so much that the bob passes through the
// anchor (the spring's law -k (|x| - l0) x/|x| is not linear there).
TEST(StudyEnergyOrder, ExplicitEulersSpringPassesThroughTheAnchor) {
  const AccuracyCell c = measureAccuracy(
      problem("spring"), Method{"explicit-euler", "explicit-euler", CollisionChoice{}}, 0.1, StudyOptions{}, false);
  ASSERT_TRUE(c.run.ok()) << c.run.message;
  EXPECT_LT(c.metrics.minSeparation, 0);
}

}  // namespace
}  // namespace fosssim::study
