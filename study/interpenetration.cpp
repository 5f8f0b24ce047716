#include "interpenetration.h"

#include <algorithm>

namespace fosssim::study {
namespace {

constexpr double kTouch = 1e-9;

void consider(double distance, double reach, Overlap& out) {
  const double depth = reach - distance;
  if (depth <= kTouch * reach) return;
  ++out.pairs;
  out.deepest = std::max(out.deepest, depth);
}

}  // namespace

Overlap measureOverlap(const Scene& scene, const VecX& x) {
  Overlap out;
  const int n = scene.numParticles();
  for (int i = 0; i < n; ++i) {
    const Vec2 xi = at(x, i);
    for (int j = i + 1; j < n; ++j) {
      if (scene.isFixed(i) && scene.isFixed(j)) continue;
      consider((at(x, j) - xi).norm(), scene.radius[i] + scene.radius[j], out);
    }
    for (const Edge& e : scene.edges) {
      if (e.i == i || e.j == i) continue;
      if (scene.isFixed(i) && scene.isFixed(e.i) && scene.isFixed(e.j)) continue;
      const Vec2 a = at(x, e.i), b = at(x, e.j), d = b - a;
      const double len2 = d.squaredNorm();
      const double alpha = len2 > 0 ? std::clamp((xi - a).dot(d) / len2, 0.0, 1.0) : 0.0;
      consider((a + alpha * d - xi).norm(), scene.radius[i] + e.radius, out);
    }
    if (scene.isFixed(i)) continue;
    for (const HalfPlane& h : scene.halfplanes) {
      // Signed distance of the centre from the boundary, positive on the free side.
      const double signedDistance = (xi - h.point).dot(h.normal) / h.normal.norm();
      consider(signedDistance, scene.radius[i], out);
    }
  }
  return out;
}

}  // namespace fosssim::study
