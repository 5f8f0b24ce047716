// Per-step diagnostics: what the state is (energies, momenta) and what the step did and cost
// (contacts, failsafe zones, time by phase), as one row of numbers under named columns. The same
// table feeds `FOSSSim --stats` (CSV) and the Python module's arrays, so both use these names.
#pragma once

#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"
#include "fosssim/core/step_stats.h"

#include <string>
#include <vector>

namespace fosssim {

struct CollisionLog;

/// One step's diagnostics. Energies and momenta are of the state at the end of the step (of the
/// initial state for step 0); counts and costs are the step's own (0 for step 0).
struct StepDiagnostics {
  long step = 0;
  double time = 0;
  double kinetic = 0;                 ///< 1/2 v^T M v
  std::vector<double> potential;      ///< per force of the scene, in its order (0 for drag and vortex)
  double momentumX = 0, momentumY = 0;  ///< sum of m v over free particles
  double angularMomentum = 0;         ///< sum of m (x cross v) over free particles, about the origin
  long contacts = 0;                  ///< impulses applied in the step (simple, continuous-time, hybrid)
  int failsafeZones = 0;              ///< impact zones of the failsafe at the end of the step
  int zoneParticles = 0;              ///< particles in those zones
  int rigidZones = 0;                 ///< zones moved rigidly (or stopped)
  StepStats cost;                     ///< the step's counters and phase times (times need Simulator::setTiming)

  double potentialTotal() const;
};

/// The state's part: step, time, energies, momenta. Leaves counts and costs alone.
void measureState(const Scene& scene, const State& state, StepDiagnostics& out);

/// A whole step's diagnostics: measureState, then the counts and costs from the step's log and
/// statistics (Simulator::log() and Simulator::stats() after Simulator::step).
void measureStep(const Scene& scene, const State& state, const CollisionLog& log, const StepStats& stats,
                 StepDiagnostics& out);

/// Column names, in row order: step, time, kinetic, potential, energy, one potential_<k>_<force>
/// per force, momentum_x, momentum_y, angular_momentum, contacts, failsafe_zones,
/// zone_particles, rigid_zones, candidate_pairs, newton_iterations, asleep, then the phase costs in seconds
/// cost_integrate, cost_broad_phase, cost_narrow_phase, cost_response, cost_failsafe, cost_total.
std::vector<std::string> diagnosticColumns(const Scene& scene);

/// The row of `d` under diagnosticColumns(scene) (cleared and refilled).
void diagnosticRow(const StepDiagnostics& d, std::vector<double>& row);

}  // namespace fosssim
