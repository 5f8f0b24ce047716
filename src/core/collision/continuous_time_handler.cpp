// The "continuous-time" handler: every pair, in the reference's order, is tested for a collision
// anywhere along its straight-line motion during the step; each collision's impulse is applied at
// once, so later pairs see the changed motion (and the broad phase follows it, see
// CollisionSearch::sweep). One pass, no failsafe: what a response creates may remain (the hybrid
// handler exists for that).
#include "collision_handlers.h"
#include "impulse_response.h"

namespace fosssim {

Status ContinuousTimeHandler::handle(const Scene& scene, const State& start, State& state, StepContext& ctx) {
  // Responses are interleaved with the queries; CollisionSearch::sweep counts them as narrow phase.
  search_.sweep(scene, start.x, state.x, ctx, [&](const Collision& c) {
    ++ctx.stats->collisions;
    ctx.log->impulses.push_back(Impulse{c.kind, c.i, c.j, c.n, c.tau});
    applyWithDisplacement(collisionResponse(scene, c, cor_, start.x, state.x, ctx.dt), ctx.dt, state.x, state.v);
  });
  showMidStep(ctx, state);
  return Status::ok();
}

}  // namespace fosssim
