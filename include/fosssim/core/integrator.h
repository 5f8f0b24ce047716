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
};

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
