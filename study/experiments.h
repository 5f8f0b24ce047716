// The study's experiments, each writing one CSV file into the output directory:
//   accuracy.csv    error and cost of every method over a sweep of dt, per accuracy problem
//   problems.csv    each accuracy problem's set-up and exact answers, for the report's table
//   audit_series.csv
//                   energy, momentum and angular momentum against time, per integrator problem and method
//   stability.csv   the largest stable dt of every integrator against spring stiffness
//   damped_stability.csv
//                   the largest stable dt of every integrator on a damped spring, against damping
//   newton_failure.csv, newton_iterations.csv
//                   implicit Euler's Newton: where it fails on orbits, its iterations per step
//                   against dt and stiffness
//   robustness.csv  outcome of a fast disk against a thin edge, per collision method, speed and dt
//   robustness_shots.csv
//                   random shots at edge faces, ends, joints and slots, judged by energy, both modes
//   hybrid.csv      the hybrid handler's failsafe use, zone sizes and cost against maxiters
//   profile.csv     per scene: the parts of the simulator it uses and what each costs per step
//   contacts_series.csv, contacts_summary.csv
//                   multi-contact problems, default mode next to --compat: energy, momentum,
//                   angular momentum, zones and escapes over time, and each problem's outcome
#pragma once

#include "problems.h"

#include "fosssim/core/status.h"

#include <ostream>
#include <string>

namespace fosssim::study {

struct StudyOptions {
  std::string outDir = ".";
  bool quick = false;          ///< a tiny matrix (tests, smoke runs): same code, fewer cells
  std::ostream* log = nullptr; ///< progress lines, may be null
  double timingBudget = 0.3;   ///< seconds of repeated runs per timed cell (minimum taken)
  int timingRepeats = 7;
};

/// One cell of the accuracy matrix.
struct AccuracyCell {
  RunResult run;
  Metrics metrics;
  double wallSeconds = kNotApplicable;  ///< timeRun's minimum; NaN if not timed or unstable
  TimingSpread timing{kNotApplicable, kNotApplicable, kNotApplicable, 0};  ///< all the repeats
};
AccuracyCell measureAccuracy(const Problem& problem, const Method& method, double dt, const StudyOptions& options,
                             bool timed);

Status runAccuracy(const StudyOptions& options);
/// problems.csv: every problem's Problem::setup (set-up and exact answers); runAccuracy calls it.
Status writeProblemSetups(const std::vector<Problem>& problems, const StudyOptions& options);
/// audit_series.csv (audit.cpp): energy, momentum and angular momentum over time; runAccuracy calls it.
Status runAudit(const StudyOptions& options);
Status runStability(const StudyOptions& options);
/// damped_stability.csv (damped_stability.h); runStability calls it.
Status runDampedStability(const StudyOptions& options);
/// newton_failure.csv (newton_failure.cpp): where implicit Euler's Newton fails on orbits; runStability calls it.
Status runNewtonFailure(const StudyOptions& options);
/// newton_iterations.csv (newton_iterations.cpp): implicit Euler's Newton iterations per step on a
/// particle between two stiff springs against k and dt, with a linear control; runStability calls it.
Status runNewtonIterations(const StudyOptions& options);
/// One run of that experiment: its springs of stiffness k and rest length 1 (or 0: the linear
/// control) with implicit Euler at step dt. RunResult::newtonIterations holds the iterations.
RunResult runTwoSprings(double k, double restLength, double dt);
Status runRobustness(const StudyOptions& options);
/// robustness_shots.csv (shots.h); runRobustness calls it.
Status runShots(const StudyOptions& options);
Status runHybridCost(const StudyOptions& options);
Status runProfile(const StudyOptions& options);
Status runContacts(const StudyOptions& options);

}  // namespace fosssim::study
