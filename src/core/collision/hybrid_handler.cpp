// The "hybrid" handler (Bridson, Fedkiw and Anderson's strategy, as the course simplifies it):
//   1. up to maxiters passes of continuous-time detection over the step, each applying the impulses
//      of all the pass's collisions computed from the same end positions; a pass that finds
//      nothing ends this phase with success (maxiters <= 0: no pass at all, no success);
//   2. the mid-step record;
//   3. if the passes did not succeed, the failsafe: rigid impact zones grown until no new
//      collision joins them (impact_zones.h).
// Its impulse list stays empty (as in the reference); its polynomial log holds every query.
#include "collision_handlers.h"
#include "impulse_response.h"

namespace fosssim {

Status HybridHandler::handle(const Scene& scene, const State& start, State& state, StepContext& ctx) {
  detector_.setStats(ctx.stats);
  zones_.reset(scene.numParticles());
  const bool resolved = impulsePasses(scene, start, state, ctx);
  if (ctx.observer) ctx.observer->midStep(*ctx.log, state);
  if (!resolved) {
    const StepTimer timer(ctx.timing, ctx.stats->failsafe);
    failsafe(scene, start, state, ctx);
    ctx.stats->failsafeUsed = true;
    zones_.sizes(ctx.stats->zones, ctx.stats->largestZone);
  }
  return Status::ok();
}

bool HybridHandler::impulsePasses(const Scene& scene, const State& start, State& state, StepContext& ctx) {
  for (int pass = 0; pass < maxIterations_; ++pass) {
    collisions_.clear();
    {
      const StepTimer timer(ctx.timing, ctx.stats->narrowPhase);
      detector_.forEachCollision(scene, start.x, state.x, &ctx.log->polynomials,
                                 [&](const Collision& c) { collisions_.push_back(c); });
    }
    ++ctx.stats->impulsePasses;
    ctx.stats->collisions += static_cast<long>(collisions_.size());
    if (collisions_.empty()) return true;
    const StepTimer timer(ctx.timing, ctx.stats->response);
    changes_.clear();
    for (const Collision& c : collisions_)
      changes_.push_back(collisionResponse(scene, c, cor_, start.x, state.x, ctx.dt));
    for (const VelocityChange& change : changes_) applyWithDisplacement(change, ctx.dt, state.x, state.v);
  }
  return false;
}

void HybridHandler::failsafe(const Scene& scene, const State& start, State& state, StepContext& ctx) {
  predicted_ = state.x;
  PolynomialLog* log = &ctx.log->polynomials;
  auto grow = [&](const VecX& end) {
    bool changed = false;
    detector_.forEachCollision(scene, start.x, end, log,
                               [&](const Collision& c) { changed = zones_.add(scene, c) || changed; });
    return changed;
  };
  grow(predicted_);
  // Move the zones, look again, until no new collision joins a zone. The reference checks at
  // least once, even when the first detection found nothing (its log shows the second query).
  // Zones only grow, so this ends after at most N + (number of zones marked immovable) rounds.
  do {
    // Each round fits the rigid motions to the positions the previous round left (zones that did
    // not change are refitted to their own rigid motion): the reference's sequencing, which
    // replaying its trajectories reproduces bit for bit, unlike fitting every round to the
    // integrator's prediction.
    predicted_ = state.x;
    zones_.moveRigidly(scene, start.x, predicted_, state.x);
  } while (grow(state.x));
  for (int p : zones_.members()) at(state.v, p) = divide(at(state.x, p) - at(start.x, p), ctx.dt);
}

}  // namespace fosssim
