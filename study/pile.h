// A dense pile: disks dropped in a grid into a box of three half-planes (floor and two walls),
// under gravity, settling into contact with many neighbours at once. The hybrid handler's hard
// case: impulses that resolve one contact create others, until the failsafe takes over.
#pragma once

#include "scene_builder.h"

namespace fosssim::study {

/// `columns` x `rows` disks of radius 0.1 with 0.02 gaps, in a box 0.22 * columns + 0.1 wide, with
/// small deterministic sideways velocities; 1.5 s at dt.
SceneBuilder pileScene(const Method& method, double dt, int columns = 8, int rows = 5);

}  // namespace fosssim::study
