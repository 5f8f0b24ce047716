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
    if (z < 0) return false;
    switch (c.kind) {
      case PairKind::ParticleParticle: return zoneOf(c.j) == z;
      case PairKind::ParticleEdge:
        return zoneOf(scene.edges[c.j].i) == z && zoneOf(scene.edges[c.j].j) == z;
      case PairKind::ParticleHalfPlane: return false;
    }
    return false;
  };
  for (const Collision& c : collisions)
    if ((limit == 0 || found.size() < limit) && !sameZone(c)) found.push_back(Violation{c.kind, c.i, c.j, c.tau});
  return found;
}

std::vector<Violation> CollisionHandler::unresolved(const Scene& scene, const VecX& start, const VecX& end,
                                                    size_t limit) const {
  return unresolvedCollisions(scene, start, end, [this](int p) { return zoneOf(p); }, limit);
}

}  // namespace fosssim
