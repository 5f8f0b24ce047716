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
};

/// Implicit Euler's Newton iteration stops when the update's Euclidean norm falls below this
/// (the reference's criterion)...
constexpr double kNewtonTolerance = 1e-9;
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
