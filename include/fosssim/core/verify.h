// Checking a step after the fact (--verify, tests): a fresh continuous-time detection over the
// step must find no collision, except between particles that one rigid impact zone moved
// together (their relative motion is rigid, so a pair overlapping inside a zone stays so).
#pragma once

#include "fosssim/core/collision_log.h"
#include "fosssim/core/scene.h"

#include <functional>
#include <vector>

namespace fosssim {

/// A pair that still collides somewhere during a step: kind, i, j and tau (first contact as a
/// fraction of the step) of the same record detection uses.
using Violation = Collision;

/// The rigid impact zone of a particle after the last step, or -1 (see Simulator::zoneOf).
using ZoneOf = std::function<int(int particle)>;

/// Every pair of `scene` that collides while moving in straight lines from `start` to `end`
/// (exact quintic), in the reference's pair order, skipping pairs whose particles all share one
/// rigid zone. `limit` caps the list (0 = no cap).
std::vector<Violation> unresolvedCollisions(const Scene& scene, const VecX& start, const VecX& end,
                                            const ZoneOf& zoneOf, size_t limit = 0);

}  // namespace fosssim
