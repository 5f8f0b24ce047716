// Explicit Euler and symplectic (forward-backward) Euler.
//   explicit:   x' = x + h v,        v' = v + h F(x, v)/m
//   symplectic: v' = v + h F(x, v)/m, x' = x + h v'
// The force on fixed particles is zeroed, so they keep v = 0 (as in the reference).
#include "explicit_integrators.h"

#include "core/collision/parallel_rows.h"

namespace fosssim {

// Element by element, on ranges of particles with the context's threads (each value is computed
// alone, so any thread count gives the same bits).
void ExplicitForces::compute(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context) {
  acceleration.setZero(x.size());
  accumulateGradient(scene, x, v, acceleration, context);
  forRowRanges(scene.numParticles(), context.threads(), [&](int, int first, int end) {
    for (int i = first; i < end; ++i)
      at(acceleration, i) =
          scene.isFixed(i) ? Vec2(Vec2::Zero()) : Vec2(-at(acceleration, i).cwiseQuotient(at(scene.mass, i)));
  });
}

Status ExplicitEuler::step(const Scene& scene, State& state, double dt, ForceContext& forces) {
  forces_.compute(scene, state.x, state.v, forces);
  forRowRanges(scene.numParticles(), forces.threads(), [&](int, int first, int end) {
    const long from = 2L * first, count = 2L * (end - first);
    state.x.segment(from, count) += dt * state.v.segment(from, count);
    state.v.segment(from, count) += dt * forces_.acceleration.segment(from, count);
  });
  return Status::ok();
}

Status SymplecticEuler::step(const Scene& scene, State& state, double dt, ForceContext& forces) {
  forces_.compute(scene, state.x, state.v, forces);
  forRowRanges(scene.numParticles(), forces.threads(), [&](int, int first, int end) {
    const long from = 2L * first, count = 2L * (end - first);
    state.v.segment(from, count) += dt * forces_.acceleration.segment(from, count);
    state.x.segment(from, count) += dt * state.v.segment(from, count);
  });
  return Status::ok();
}

}  // namespace fosssim
