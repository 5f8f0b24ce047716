// Explicit Euler and symplectic (forward-backward) Euler.
//   explicit:   x' = x + h v,        v' = v + h F(x, v)/m
//   symplectic: v' = v + h F(x, v)/m, x' = x + h v'
// The force on fixed particles is zeroed, so they keep v = 0 (as in the reference).
#include "explicit_integrators.h"

namespace fosssim {

void ExplicitForces::compute(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context) {
  acceleration.setZero(x.size());
  accumulateGradient(scene, x, v, acceleration, context);
  acceleration = -acceleration.cwiseQuotient(scene.mass);
  for (int i = 0; i < scene.numParticles(); ++i)
    if (scene.isFixed(i)) at(acceleration, i).setZero();
}

Status ExplicitEuler::step(const Scene& scene, State& state, double dt, ForceContext& forces) {
  forces_.compute(scene, state.x, state.v, forces);
  state.x += dt * state.v;
  state.v += dt * forces_.acceleration;
  return Status::ok();
}

Status SymplecticEuler::step(const Scene& scene, State& state, double dt, ForceContext& forces) {
  forces_.compute(scene, state.x, state.v, forces);
  state.v += dt * forces_.acceleration;
  state.x += dt * state.v;
  return Status::ok();
}

}  // namespace fosssim
