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
};

}  // namespace fosssim
