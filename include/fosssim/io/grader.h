// Grading a trajectory file against the simulator (-i), with the reference's semantics: every step
// restarts from the file's state, is simulated, and is compared with the file's next record; a
// mid-step record (continuous-time, hybrid) is compared too and then replaces the handler's own
// state, so an early difference does not spread through the step.
//
// One rule the reference does not have: record 0 must be the scene's initial state. The reference
// copies every record into the scene without looking at record 0, so a file of zeros passed for
// the billiards example (balls at rest at the origin, with no force on them, stay there), and
// another scene's file with as many particles was graded as if it were this scene's.
#pragma once

#include "fosssim/core/simulator.h"
#include "fosssim/io/trajectory.h"

#include <ostream>
#include <string>
#include <vector>

namespace fosssim {

/// The tolerances of the reference's grader.
struct GradeTolerances {
  double residualSum = 1e-6;   ///< accumulated per-particle position (and velocity) residuals
  double residualMax = 1e-10;  ///< largest single per-particle residual (record 0 is held to it too)
  double normal = 1e-9;        ///< impulse contact vectors, per component
  double polynomial = 1e-10;   ///< coefficients after L1 normalisation, per coefficient
};

struct GradeOptions {
  GradeTolerances tolerances;
  int maxFindings = 20;             ///< findings kept (and printed) in full; the rest are counted
  bool stopAtFirstFinding = false;  ///< enough to know whether a file passes (the mode hint's grade)
};

/// One difference between a simulated record and the file's.
struct GradeFinding {
  enum Category { Positions = 0, Velocities, Impulses, Polynomials };
  Category category = Positions;
  long step = 0;          ///< the step whose record differs (the first step is 1)
  long record = 0;        ///< the record's index in the file (record 0 is the initial state)
  bool midStep = false;   ///< the record from inside collision handling, not the end of the step
  std::string who;        ///< the particle or pair, e.g. "particle 3", "particle 2 and edge 0"; may be empty
  std::string what;       ///< the difference, e.g. "differs by 2.5e-06 (the file's (1, 2), simulated (1, 2.0000025))"
};

struct GradeReport {
  long stepsGraded = 0;
  long numSteps = 0;  ///< the scene's
  double positionSum = 0, positionMax = 0, velocitySum = 0, velocityMax = 0;
  long impulsesMissed = 0, impulsesSuperfluous = 0, impulsesWrongNormal = 0;
  long polynomialMismatches = 0;
  long findingCount = 0;                 ///< every finding
  long categoryFindings[4] = {0, 0, 0, 0};
  long stepsDiverged = 0;                ///< steps with at least one finding
  std::vector<GradeFinding> findings;    ///< the first ones, in file order (at least the first is kept)
  std::string structuralError;  ///< the file does not fit the scene (record 0 included), or the simulation failed
  bool unreadable = false;      ///< the file could not be opened (structuralError says why); nothing was read
  RecordLayout layout;          ///< what the records hold
  /// Set by gradeFile: the other mode (--compat or not) passes the file, or the file fails as one
  /// written with -o --compact (no polynomial log) would, and reads as one.
  std::string hint;
  bool passed(const GradeTolerances& tol) const;
};

/// Grades `path` for `scene` from `initial`, writing nothing.
GradeReport gradeRecords(const Scene& scene, const State& initial, Simulator& simulator, const std::string& path,
                         const GradeOptions& options = {});

/// Writes a grade: a failed one leads with where the run first diverged (step, time, record,
/// category, particle or pair) or why the file does not fit, then the hint, then the first
/// findings; every grade then gives one line per category and ends with the reference's
/// "Overall success: Passed." or "Overall success: Failed.". Writes nothing for an unreadable
/// file: the caller reports report.structuralError as its error.
void printGrade(const GradeReport& report, const Scene& scene, std::ostream& out, const GradeOptions& options = {});

/// gradeRecords, then printGrade.
GradeReport gradeTrajectory(const Scene& scene, const State& initial, Simulator& simulator,
                            const std::string& path, std::ostream& out, const GradeTolerances& tol = {},
                            int maxFindings = 20);

/// What -i does: gradeTrajectory with `simulator` (made with `made`), and when a file whose
/// records hold polynomials (continuous-time, hybrid: the only handlers the modes differ in) fails
/// on what it holds, grades it again in the other mode (--compat or not) and, if that passes,
/// says so in report.hint ahead of the findings; a file that does not fit and reads as one written
/// with -o --compact gets that hint instead.
GradeReport gradeFile(const Scene& scene, const State& initial, Simulator& simulator, const SimulatorOptions& made,
                      const std::string& path, std::ostream& out, const GradeOptions& options = {});

/// The reference's polynomial equality: equal length and, after dividing each by its L1 norm,
/// coefficients within `tol` (so a positive scale is allowed, a negation is not).
bool samePolynomial(const double* a, int na, const double* b, int nb, double tol);

/// Which pair's polynomial number `k` of a record's log of `logSize` polynomials is, e.g. "the
/// approach polynomial of particle 2 and edge 0"; "" when the log is not a whole number of
/// detection passes over this scene's pairs (spec, section 4: per pass every pair in the
/// reference's order, 2 polynomials per particle-particle and particle-half-plane pair, 4 per
/// particle-edge pair).
std::string polynomialOwner(const Scene& scene, long k, long logSize);

}  // namespace fosssim
