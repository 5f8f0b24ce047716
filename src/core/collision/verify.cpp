#include "fosssim/core/verify.h"

#include "collision_search.h"

namespace fosssim {

std::vector<Violation> unresolvedCollisions(const Scene& scene, const VecX& start, const VecX& end,
                                            const ZoneOf& zoneOf, size_t limit) {
  std::vector<Violation> found;
  // A fresh detection with the broad phase (the same collisions as checking every pair).
  CollisionSearch search(math::DetectionRules{});
  StepStats stats;
  StepContext ctx;
  ctx.stats = &stats;
  std::vector<Collision> collisions;
  search.detectAll(scene, start, end, ctx, collisions);
  auto sameZone = [&](const Collision& c) {
    const int z = zoneOf ? zoneOf(c.i) : -1;
    const PairParticles pair = pairParticles(scene, c.kind, c.i, c.j);
    if (z < 0 || pair.count == 1) return false;  // a half-plane is in no zone
    for (int k = 1; k < pair.count; ++k)
      if (zoneOf(pair.p[k]) != z) return false;
    return true;
  };
  for (const Collision& c : collisions)
    if ((limit == 0 || found.size() < limit) && !sameZone(c)) found.push_back(c);
  return found;
}

}  // namespace fosssim
