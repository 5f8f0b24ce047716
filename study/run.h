// Running one scene for the study: step it to the end (or until it fails), watching for blow-up,
// counting collisions, failsafe use and interpenetration, and timing it robustly. A run that
// fails is a result ("unstable"), never a crash: the study is about where methods break.
#pragma once

#include "interpenetration.h"

#include "fosssim/core/simulator.h"
#include "fosssim/io/scene_file.h"

#include <functional>
#include <string>

namespace fosssim::study {

enum class Outcome {
  Ok,
  NonFinite,      ///< Simulator::step reported a non-finite position or velocity
  EnergyBlowUp,   ///< mechanical energy moved by more than RunOptions::energyGrowthLimit times its scale
  SolverFailure,  ///< an implicit solve failed (singular system, Newton did not converge)
  Error,          ///< anything else Simulator::create or step reported
};

/// "ok", "non-finite", "energy-blow-up", "solver-failure", "error".
const char* outcomeName(Outcome outcome);

struct RunOptions {
  /// A run whose |E - E0| exceeds this times max(|E0|, kinetic0, |potential0|) is stopped and
  /// called a blow-up: by then the numbers mean nothing, long before they overflow.
  double energyGrowthLimit = 1e6;
  bool checkEnergy = true;
  bool measureOverlap = true;
  /// Simulator::setTiming(true): per-phase timings in RunResult::phases (costs a clock read per
  /// phase, so plain wall times come from timeRun instead).
  bool phaseTimings = false;
  /// Steps to take; < 0 means the scene's own ceil(duration / dt).
  long steps = -1;
  /// The course's formulation (--compat) instead of the default mode.
  bool compat = false;
};

struct RunResult {
  Outcome outcome = Outcome::Ok;
  std::string message;      ///< the failure, with step and particle when the simulator names them
  long steps = 0;           ///< steps completed
  double stepSeconds = 0;   ///< wall time spent inside Simulator::step (clock read around each step)
  long collisions = 0;      ///< collisions handled: logged impulses, or the handler's own count
  long failsafeSteps = 0;   ///< hybrid: steps whose impulse passes did not resolve every collision
  long failsafeParticles = 0;     ///< hybrid: particles the failsafe moved, summed over steps
  int mostFailsafeParticles = 0;  ///< hybrid: most particles the failsafe moved in one step
  long impulsePasses = 0;   ///< hybrid: detection passes, summed over steps
  long zoneSum = 0;         ///< hybrid: impact zones, summed over failsafe steps
  int largestZone = 0;      ///< hybrid: particles in the largest impact zone of the run
  long newtonIterations = 0;     ///< the integrator's Newton iterations, summed over completed steps
  int mostNewtonIterations = 0;  ///< the most in one step, the failed step included
  StepStats phases;         ///< per-phase timings and counters summed over steps
  OverlapTally overlap;
  double energy0 = 0, energyEnd = 0;
  State final;

  bool ok() const { return outcome == Outcome::Ok; }
};

/// Called after every successful step with the new state.
using StepVisitor = std::function<void(const Scene&, const State&)>;

/// The simulator options of every study run: the energy watch off (the study has its own blow-up
/// mark), and the course's formulation (--compat) only when asked for, to compare against it.
SimulatorOptions studySimulatorOptions(bool compat = false);

/// Total mechanical energy: kinetic plus the potential of the forces that have one.
double mechanicalEnergy(const Scene& scene, const State& state);

RunResult runScene(const SceneFile& file, const RunOptions& options, const StepVisitor& visit = {});

/// Wall time of a whole run of `file` with nothing measured, as the minimum over repeated runs:
/// the minimum is the run least disturbed by other work on a shared machine. Repeats until
/// `budgetSeconds` are spent or `maxRepeats` runs are done (at least one run). A failing run
/// returns NaN.
double timeRun(const SceneFile& file, long steps, int maxRepeats, double budgetSeconds);

/// timeRun's repeats, all of them: the least, the median and the greatest wall time (NaN if a run
/// failed), so that charts can show how much the times on a shared machine spread.
struct TimingSpread {
  double min = 0, median = 0, max = 0;
  int repeats = 0;
};
TimingSpread timeRunSpread(const SceneFile& file, long steps, int maxRepeats, double budgetSeconds);

}  // namespace fosssim::study
