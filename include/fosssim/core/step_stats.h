// What one step cost and did: phase timings and counters, for the benchmarks, the study and
// users asking where the time goes. Filled by Simulator::step when statistics are enabled.
#pragma once

namespace fosssim {

struct StepStats {
  // --- wall time per phase, seconds -------------------------------------------------------------
  double integrate = 0;    ///< forces, Jacobians and the integrator's solve
  double broadPhase = 0;   ///< finding candidate pairs
  double narrowPhase = 0;  ///< continuous-time (or discrete) queries on candidate pairs
  double response = 0;     ///< computing and applying impulses
  double failsafe = 0;     ///< rigid impact zones, including their detection passes
  double total = 0;        ///< the whole step

  // --- counters -------------------------------------------------------------------------------
  long candidatePairs = 0;   ///< pairs handed to the narrow phase (all kinds, all passes)
  long queries[3] = {0, 0, 0};  ///< narrow-phase queries by PairKind (particle-particle, -edge, -half-plane)
  long collisions = 0;       ///< collisions found by the impulse phase (all passes)
  int newtonIterations = 0;  ///< Newton iterations of the integrator's solve (Integrator::newtonIterations)
  int impulsePasses = 0;     ///< hybrid: detection passes of the impulse phase
  bool failsafeUsed = false; ///< hybrid: the rigid impact-zone failsafe ran
  int failsafeRounds = 0;    ///< hybrid: rigid moves of the failsafe (each followed by a detection)
  int zones = 0;             ///< hybrid: impact zones at the end of the failsafe
  int largestZone = 0;       ///< hybrid: particles in the largest zone
  int zoneParticles = 0;     ///< particles in failsafe zones at the end of the step
  int asleep = 0;            ///< default mode: particles asleep at the end of the step (resting, not moved)
  int woken = 0;             ///< default mode: sleepers woken in the step (by a contact or a moving neighbour)
  int rigidZones = 0;  ///< zones that moved rigidly (or stopped): all of --compat's, the default mode's last resort
  int jammedParticles = 0;   ///< default mode: particles a jam against an obstacle stopped for the rest of the step
  int heldParticles =
      0;  ///< default mode: particles held at rest by a budget-ended solve (stopped for the rest of the step)
  long zoneUpdates = 0;      ///< default mode: Gauss-Seidel updates of the failsafe's projection (the zones' solves)
  /// default mode: zone solves and rigid moves at which the rows' changes since the last one, warm
  /// starts included, were scaled back for adding kinetic energy (ContactProjector::capEnergy)
  int energyCaps = 0;

  void clear() { *this = StepStats{}; }
};

}  // namespace fosssim

#include <chrono>

namespace fosssim {

/// Adds the lifetime of the timer to `into` when enabled (RAII; costs nothing when disabled).
class StepTimer {
 public:
  StepTimer(bool enabled, double& into) : into_(enabled ? &into : nullptr) {
    if (into_) begin_ = std::chrono::steady_clock::now();
  }
  ~StepTimer() {
    if (into_) *into_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin_).count();
  }
  StepTimer(const StepTimer&) = delete;
  StepTimer& operator=(const StepTimer&) = delete;

 private:
  double* into_;                                 ///< where the elapsed seconds are added; null when disabled
  std::chrono::steady_clock::time_point begin_;  ///< when the timer started (set only when enabled)
};

}  // namespace fosssim
