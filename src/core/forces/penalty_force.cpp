// The collision penalty force. For a pair at distance vector n (from the particle to the closest
// point of the other object), with reach R = r_sum + thickness and |n| < R:
//   E = k/2 (|n| - R)^2,  dE/dx_particle = -k (|n| - R) n/|n|
// and the other object takes the opposite gradient: the other particle whole, an edge's endpoints
// weighted (1 - alpha) and alpha at the closest point's parameter alpha (held fixed, as in the
// reference), a half-plane nothing. An exact overlap (|n| = 0) has no direction and gets no force.
#include "fosssim/core/forces.h"

#include "fosssim/core/pair_geometry.h"

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

/// Calls visit(i, other, n, reach, weights...) for every pair in the reference's order that lies
/// within reach; `Visit` gets the pair kind so energy and gradient share one traversal.
template <class Visit>
void forEachPenaltyPair(const Scene& scene, const VecX& x, double thickness, Visit&& visit) {
  const int n = scene.numParticles();
  for (int i = 0; i < n; ++i) {
    const Vec2 xi = at(x, i);
    for (int j = i + 1; j < n; ++j) {
      const Vec2 d = at(x, j) - xi;
      const double reach = scene.radius[i] + scene.radius[j] + thickness;
      if (d.squaredNorm() < reach * reach) visit(i, d, reach, j, -1, 0.0);
    }
    for (const Edge& e : scene.edges) {
      if (e.i == i || e.j == i) continue;
      const double alpha = std::clamp(segmentParameter(xi, at(x, e.i), at(x, e.j)), 0.0, 1.0);
      const Vec2 d = at(x, e.i) + alpha * (at(x, e.j) - at(x, e.i)) - xi;
      const double reach = scene.radius[i] + e.radius + thickness;
      if (d.squaredNorm() < reach * reach) visit(i, d, reach, e.i, e.j, alpha);
    }
    for (const HalfPlane& h : scene.halfplanes) {
      const Vec2 d = halfPlaneContact(xi, h.point, h.normal);
      const double reach = scene.radius[i] + thickness;
      if (d.squaredNorm() < reach * reach) visit(i, d, reach, -1, -1, 0.0);
    }
  }
}

}  // namespace

double PenaltyForce::energy(const Scene& scene, const VecX& x, const VecX&) const {
  double e = 0;
  forEachPenaltyPair(scene, x, thickness_, [&](int, const Vec2& d, double reach, int, int, double) {
    const double gap = d.norm() - reach;
    e += 0.5 * k_ * gap * gap;
  });
  return e;
}

void PenaltyForce::addGradient(const Scene& scene, const VecX& x, const VecX&, VecX& gradE) const {
  forEachPenaltyPair(scene, x, thickness_,
                     [&](int i, const Vec2& d, double reach, int a, int b, double alpha) {
                       const double len = d.norm();
                       if (len == 0.0) return;
                       const Vec2 g = k_ * (len - reach) / len * d;  // dE/d(other point)
                       at(gradE, i) -= g;
                       if (b >= 0) {  // edge a-b
                         at(gradE, a) += (1.0 - alpha) * g;
                         at(gradE, b) += alpha * g;
                       } else if (a >= 0) {  // particle a
                         at(gradE, a) += g;
                       }
                     });
}

}  // namespace fosssim
