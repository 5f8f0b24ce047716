// The "simple" handler: discrete detection at the end of the step. In the reference's pair order,
// a pair collides when it overlaps and approaches; its response changes velocities at once (later
// pairs see it) and leaves positions alone. Impulses are recorded with tau 0. The broad phase
// (pair_candidates.h) skips pairs that provably do not overlap.
#include "collision_handlers.h"
#include "impulse_response.h"

#include "fosssim/math/geometry.h"

#include <algorithm>

namespace fosssim {
namespace {

void apply(const VelocityChange& change, VecX& v) {
  for (int k = 0; k < change.count; ++k) at(v, change.particle[k]) += change.dv[k];
}

}  // namespace

Status SimpleHandler::handle(const Scene& scene, const State&, State& state, StepContext& ctx) {
  const VecX& x = state.x;
  VecX& v = state.v;
  const double cor = cor_;
  auto record = [&](PairKind kind, int i, int j, const Vec2& n) {
    ctx.log->impulses.push_back(Impulse{kind, i, j, n, 0.0});
  };
  // Positions do not change here (responses change velocities only), so the pairs that overlap
  // at the end of the step are known before the first response: candidates first, then the
  // tests in the reference's order.
  {
    const StepTimer timer(ctx.timing, ctx.stats->broadPhase);
    candidates_.build(scene, x, x);
    if (allPairs_) candidates_.forceAllPairs();
    keys_.clear();
    for (int i = 0; i < scene.numParticles(); ++i)
      candidates_.forEachInRow(i, row_, [&](PairKind kind, int other) { keys_.push_back(pairKey(i, kind, other)); });
  }
  const StepTimer timer(ctx.timing, ctx.stats->narrowPhase);  // responses are interleaved: counted here too
  ctx.stats->candidatePairs += static_cast<long>(keys_.size());
  for (uint64_t key : keys_) {
    const int i = keyParticle(key), other = keyOther(key);
    const Vec2 xi = at(x, i);
    ++ctx.stats->queries[static_cast<int>(keyKind(key))];
    switch (keyKind(key)) {
      case PairKind::ParticleParticle: {
        const int j = other;
        const Vec2 n = at(x, j) - xi;
        const double reach = scene.radius[i] + scene.radius[j];
        if (n.squaredNorm() < reach * reach && (at(v, i) - at(v, j)).dot(n) > 0.0) {
          record(PairKind::ParticleParticle, i, j, n);
          apply(particleParticleResponse(scene, i, j, n, cor, at(v, i), at(v, j)), v);
        }
        break;
      }
      case PairKind::ParticleEdge: {
        const int e = other;
        const Edge& edge = scene.edges[e];
        const Vec2 x2 = at(x, edge.i), x3 = at(x, edge.j);
        double alpha = 0;
        const Vec2 n = math::segmentContactVector(xi, x2, x3, &alpha);
        const double reach = scene.radius[i] + edge.radius;
        const Vec2 v2 = at(v, edge.i), v3 = at(v, edge.j);
        if (n.squaredNorm() < reach * reach && (at(v, i) - v2 - alpha * (v3 - v2)).dot(n) > 0.0) {
          record(PairKind::ParticleEdge, i, e, n);
          apply(particleEdgeResponse(scene, i, edge, alpha, n, cor, at(v, i), v2, v3), v);
        }
        break;
      }
      case PairKind::ParticleHalfPlane: {
        const int h = other;
        const HalfPlane& plane = scene.halfplanes[h];
        const Vec2 n = math::halfPlaneContactVectorUnit(xi, plane.point, plane.normal);
        const double r = scene.radius[i];
        if (n.squaredNorm() < r * r && at(v, i).dot(n) > 0.0) {
          record(PairKind::ParticleHalfPlane, i, h, n);
          apply(particleHalfPlaneResponse(scene, i, n, cor, at(v, i)), v);
        }
        break;
      }
    }
  }
  return Status::ok();
}

}  // namespace fosssim
