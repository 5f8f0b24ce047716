// What *changes* during a run.
#pragma once

#include "fosssim/core/types.h"

namespace fosssim {

struct State {
  VecX x;           ///< 2N positions: particle i at rows 2i, 2i+1
  VecX v;           ///< 2N velocities, same layout
  double time = 0;  ///< simulated time at this state
  long step = 0;    ///< number of steps taken to reach this state

  int numParticles() const { return static_cast<int>(x.size() / 2); }
  /// Appends a particle's position and velocity (its constant properties go to the Scene:
  /// addParticle); returns its index. One resize each: for building scenes, not in a step.
  int addParticle(const Vec2& position, const Vec2& velocity) {
    const Eigen::Index n = x.size();
    x.conservativeResize(n + 2);
    v.conservativeResize(n + 2);
    x.segment<2>(n) = position;
    v.segment<2>(n) = velocity;
    return static_cast<int>(n / 2);
  }
};

}  // namespace fosssim
