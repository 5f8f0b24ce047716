#include "fosssim/render/path_trails.h"

#include <algorithm>
#include <cmath>

namespace fosssim::render {

Trail::Trail(int particle, std::size_t capacity, Rgb color)
    : particle_(particle), color_(color), points_(std::max<std::size_t>(capacity, 1)) {}

void Trail::push(const Vec2& p) {
  if (count_ < points_.size()) {
    points_[(head_ + count_++) % points_.size()] = p;
  } else {  // full: overwrite the oldest
    points_[head_] = p;
    head_ = (head_ + 1) % points_.size();
  }
}

PathTrails::PathTrails(const std::vector<ParticlePath>& paths, double dt) {
  trails_.reserve(paths.size());
  for (const ParticlePath& p : paths) {
    // ceil(duration/dt) positions, as the reference keeps; bounded so that a silly duration in a
    // scene file cannot ask for gigabytes.
    const double n = dt > 0 ? std::ceil(p.duration / dt) : 1.0;
    const std::size_t capacity = n >= 1 ? static_cast<std::size_t>(std::min(n, 1.0e7)) : 1;
    trails_.emplace_back(p.particle, capacity, p.color);
  }
}

void PathTrails::record(const State& state) {
  for (Trail& t : trails_)
    if (t.particle() >= 0 && t.particle() < state.numParticles()) t.push(at(state.x, t.particle()));
}

void PathTrails::clear() {
  for (Trail& t : trails_) t.clear();
}

}  // namespace fosssim::render
