// Time integrators: advance positions and velocities by one step of the scene's forces, before
// collisions are handled. Fixed particles never move: their force is zeroed (explicit methods) or
// their rows are the identity with a zero right-hand side (implicit solves).
#pragma once

#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"
#include "fosssim/core/status.h"

#include <memory>
#include <vector>

namespace fosssim {

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// Advances state.x and state.v by dt (not state.time: the step does that). `forces`: the
  /// caller's context for evaluating the scene's forces (a Simulator passes its own).
  virtual Status step(const Scene& scene, State& state, double dt, ForceContext& forces) = 0;
  /// The same with a fresh default context (tools and tests that step an integrator alone).
  Status step(const Scene& scene, State& state, double dt) {
    ForceContext forces;
    return step(scene, state, dt, forces);
  }
  /// Newton iterations the last step took (failed steps included): implicit Euler's count, 1 for
  /// linearized implicit Euler (one Newton step by definition), 0 for methods that solve nothing.
  /// Simulator::step copies it into StepStats::newtonIterations.
  virtual int newtonIterations() const { return 0; }
  /// Whether the method solves as the reference does (--compat: its absolute tolerances and its
  /// systems' form, the course's iterates bit for bit) or in the scene's own units (tolerances
  /// relative to the scene's scales, systems whose every entry has the units of its row: the
  /// default mode, which the Simulator sets). Methods that solve nothing ignore it.
  virtual void setCourseForm(bool /*course*/) {}
};

/// Implicit Euler's Newton iteration stops, under --compat, when the update's Euclidean norm falls
/// below this (the reference's criterion, in the scene's units)...
constexpr double kNewtonTolerance = 1e-9;
/// ...and in the default mode when it falls to this fraction of the velocity scale: units-free.
/// The absolute 1e-9 m/s stopped a spring pendulum scaled by 10^6 (its updates stalled at
/// 2.4e-9 m/s, rounding for velocities of 10^6 m/s: "did not converge"), and accepted a first
/// update as the answer at the 10^-6 scale.
constexpr double kNewtonRelativeTolerance = 1e-9;
/// The velocity scale is the norm of the step's new velocities (every particle's), but at least
/// this fraction of the positions' norm over the step. A particle resting where its forces
/// balance has no velocity to measure against, and Newton's updates stall at the rounding of its
/// forces, at most about eps |x| / h; this floor puts the tolerance some 45 times above that.
constexpr double kNewtonRestingFraction = 1e-5;
/// ...and a step that has not converged after this many iterations fails with a message instead
/// of looping forever (the reference had no limit).
constexpr int kMaxNewtonIterations = 100;

/// One row of the integrator table: the XML keyword and how to build the integrator.
struct IntegratorEntry {
  const char* keyword;
  std::unique_ptr<Integrator> (*make)();
  const char* summary;  ///< one line for -h and docs
  bool implicit;        ///< solves a linear system (uses force Jacobians)
};

/// Every integrator keyword of the scene format (aliases included), in the order shown to users.
const std::vector<IntegratorEntry>& integratorTable();

/// The entry for `keyword`, or nullptr.
const IntegratorEntry* findIntegrator(const std::string& keyword);

}  // namespace fosssim
