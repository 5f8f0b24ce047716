// What every collision handler shares: the mid-step seam and the default verification.
#include "fosssim/core/collision_handler.h"

namespace fosssim {

bool showMidStep(StepContext& ctx, State& state) {
  if (!ctx.observer) return false;
  const State* replacement = ctx.observer->midStep(*ctx.log, state);
  if (!replacement || replacement == &state) return false;
  // Whether the positions changed, compared exactly: the hybrid failsafe may build on its last
  // detection pass only when it goes on from the positions that pass saw.
  const bool moved = replacement->x != state.x;
  state.x = replacement->x;
  state.v = replacement->v;
  return moved;
}

std::vector<Violation> CollisionHandler::unresolved(const Scene& scene, const VecX& start, const VecX& end,
                                                    size_t limit) const {
  return unresolvedCollisions(scene, start, end, ZoneOf{}, limit);  // straight paths, no zones
}

}  // namespace fosssim
