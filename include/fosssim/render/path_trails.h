// Particle paths (<particlepath>): each a trail of a particle's most recent positions.
#pragma once

#include "fosssim/core/state.h"
#include "fosssim/io/scene_file.h"

#include <vector>

namespace fosssim::render {

/// A fixed-capacity ring buffer of positions: recording is O(1) and never allocates, which matters
/// for long runs where a trail of ceil(duration/dt) points is appended to after every step.
class Trail {
 public:
  Trail(int particle, std::size_t capacity, Rgb color);
  void push(const Vec2& p);
  void clear() { count_ = 0; }
  std::size_t size() const { return count_; }
  std::size_t capacity() const { return points_.size(); }
  /// The k-th oldest point still kept (0 <= k < size()).
  const Vec2& operator[](std::size_t k) const { return points_[(head_ + k) % points_.size()]; }
  int particle() const { return particle_; }
  const Rgb& color() const { return color_; }

 private:
  int particle_;
  Rgb color_;
  std::vector<Vec2> points_;
  std::size_t head_ = 0;   ///< index of the oldest point
  std::size_t count_ = 0;
};

/// All the paths of a scene.
class PathTrails {
 public:
  PathTrails() = default;
  /// One trail per path, keeping the last ceil(duration / dt) positions (at least one).
  PathTrails(const std::vector<ParticlePath>& paths, double dt);
  /// Appends every path's particle position in `state` (call with the initial state and after
  /// every step). Paths naming a particle the state does not have are ignored.
  void record(const State& state);
  void clear();
  const std::vector<Trail>& trails() const { return trails_; }

 private:
  std::vector<Trail> trails_;
};

}  // namespace fosssim::render
