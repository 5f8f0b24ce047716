// Internal header: the explicit integrators (built through integratorTable()).
#pragma once

#include "fosssim/core/integrator.h"

namespace fosssim {

/// F/m at (x, v) with fixed particles' rows zeroed; kept as a member to reuse its storage.
struct ExplicitForces {
  VecX acceleration;  ///< 2N
  void compute(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context);
};

class ExplicitEuler final : public Integrator {
 public:
  using Integrator::step;
  Status step(const Scene& scene, State& state, double dt, ForceContext& forces) override;

 private:
  ExplicitForces forces_;  ///< the step's F/m (2N), its storage reused
};

class SymplecticEuler final : public Integrator {
 public:
  using Integrator::step;
  Status step(const Scene& scene, State& state, double dt, ForceContext& forces) override;

 private:
  ExplicitForces forces_;  ///< the step's F/m (2N), its storage reused
};

}  // namespace fosssim
