#include "fosssim/render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fosssim::render {

Camera fitParticles(const State& state, int width, int height) {
  double minX = std::numeric_limits<double>::infinity(), maxX = -minX, minY = minX, maxY = -minX;
  for (int i = 0; i < state.numParticles(); ++i) {
    const Vec2 p = at(state.x, i);
    if (!p.allFinite()) continue;  // a blown-up particle must not take the camera with it
    minX = std::min(minX, p.x());
    maxX = std::max(maxX, p.x());
    minY = std::min(minY, p.y());
    maxY = std::max(maxY, p.y());
  }
  Camera c;
  if (!(minX <= maxX)) return c;  // no (finite) particles: the unit view around the origin
  c.cx = 0.5 * (minX + maxX);
  c.cy = 0.5 * (minY + maxY);
  double rx = maxX - c.cx, ry = maxY - c.cy;
  if (rx == 0) rx = 1;
  if (ry == 0) ry = 1;
  const double ratio = static_cast<double>(height) / static_cast<double>(width);
  c.size = 1.2 * std::max(ratio * rx, ry);
  return c;
}

Camera initialCamera(const Appearance& look, const State& state, int width, int height) {
  if (look.viewport) return Camera{look.viewport->cx, look.viewport->cy, look.viewport->size};
  return fitParticles(state, width, height);
}

}  // namespace fosssim::render
