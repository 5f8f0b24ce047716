// Internal header: continuous-time detection of one pair, or of every pair in the reference's
// order, over a step from start positions qs to end positions qe (straight-line motion), on the
// math library's CCD queries. Shared by the continuous-time and hybrid handlers and --verify.
#pragma once

#include "fosssim/core/collision_log.h"
#include "fosssim/core/scene.h"
#include "fosssim/core/step_stats.h"
#include "fosssim/math/ccd.h"

namespace fosssim {

class ContinuousDetector {
 public:
  explicit ContinuousDetector(const math::DetectionRules& rules) : rules_(rules) {}

  /// Where forEachCollision counts its queries (may be null).
  void setStats(StepStats* stats) { stats_ = stats; }

  /// Each returns true and fills `hit` when the pair collides during the step; when `log` is
  /// non-null (and enabled) the pair's polynomials are appended to it in the reference's order.
  bool particleParticle(const Scene& scene, const VecX& qs, const VecX& qe, int i, int j, Collision& hit,
                        PolynomialLog* log) const;
  bool particleEdge(const Scene& scene, const VecX& qs, const VecX& qe, int i, int edge, Collision& hit,
                    PolynomialLog* log) const;
  bool particleHalfPlane(const Scene& scene, const VecX& qs, const VecX& qe, int i, int plane, Collision& hit,
                         PolynomialLog* log) const;

  /// Visits every pair in the reference's order (for each particle i: particles j > i, edges not
  /// incident to i, half-planes) and calls onHit(const Collision&) for each collision. `qe` is read
  /// as the traversal goes, so onHit may change it (the continuous-time handler does).
  template <class OnHit>
  void forEachCollision(const Scene& scene, const VecX& qs, const VecX& qe, PolynomialLog* log, OnHit&& onHit) const {
    Collision hit;
    const int n = scene.numParticles();
    const int edges = static_cast<int>(scene.edges.size()), planes = static_cast<int>(scene.halfplanes.size());
    if (stats_) {
      const long incident = 2L * edges;  // particle-edge pairs skipped: the particle is an endpoint
      stats_->queries[0] += static_cast<long>(n) * (n - 1) / 2;
      stats_->queries[1] += static_cast<long>(n) * edges - incident;
      stats_->queries[2] += static_cast<long>(n) * planes;
      stats_->candidatePairs += static_cast<long>(n) * (n - 1) / 2 + static_cast<long>(n) * edges - incident +
                                static_cast<long>(n) * planes;
    }
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j)
        if (particleParticle(scene, qs, qe, i, j, hit, log)) onHit(hit);
      for (int e = 0; e < edges; ++e)
        if (scene.edges[e].i != i && scene.edges[e].j != i && particleEdge(scene, qs, qe, i, e, hit, log)) onHit(hit);
      for (int h = 0; h < planes; ++h)
        if (particleHalfPlane(scene, qs, qe, i, h, hit, log)) onHit(hit);
    }
  }

 private:
  math::DetectionRules rules_;  ///< the PE quintic and interval rule: FOSSSim's own, or the reference's (--compat)
  StepStats* stats_ = nullptr;  ///< where forEachCollision counts its queries, or null (setStats)
};

}  // namespace fosssim
