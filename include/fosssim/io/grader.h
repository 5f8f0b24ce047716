// Grading a trajectory file against the simulator (-i), with the reference's semantics: every step
// restarts from the file's state, is simulated, and is compared with the file's next record; a
// mid-step record (continuous-time, hybrid) is compared too and then replaces the handler's own
// state, so an early difference does not spread through the step.
#pragma once

#include "fosssim/core/simulator.h"
#include "fosssim/io/trajectory.h"

#include <ostream>
#include <string>

namespace fosssim {

/// The tolerances of the reference's grader.
struct GradeTolerances {
  double residualSum = 1e-6;   ///< accumulated per-particle position (and velocity) residuals
  double residualMax = 1e-10;  ///< largest single per-particle residual
  double normal = 1e-9;        ///< impulse contact vectors, per component
  double polynomial = 1e-10;   ///< coefficients after L1 normalisation, per coefficient
};

struct GradeReport {
  long stepsGraded = 0;
  double positionSum = 0, positionMax = 0, velocitySum = 0, velocityMax = 0;
  long impulsesMissed = 0, impulsesSuperfluous = 0, impulsesWrongNormal = 0;
  long polynomialMismatches = 0;
  std::string structuralError;  ///< the file does not fit the scene, or the simulation failed
  bool passed(const GradeTolerances& tol) const;
};

/// Grades `path` for `scene` from `initial`, writing findings (at most `maxFindings` lines) and the
/// closing summary ("Overall success: Passed." or "Failed.") to `out`.
GradeReport gradeTrajectory(const Scene& scene, const State& initial, Simulator& simulator,
                            const std::string& path, std::ostream& out, const GradeTolerances& tol = {},
                            int maxFindings = 20);

/// The reference's polynomial equality: equal length and, after dividing each by its L1 norm,
/// coefficients within `tol` (so a positive scale is allowed, a negation is not).
bool samePolynomial(const double* a, int na, const double* b, int nb, double tol);

}  // namespace fosssim
