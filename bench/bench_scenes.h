// Scalable benchmark scenes, built in memory (for the benchmark) or written as scene files (for
// the command line, via fosssim-scenegen). Every scene uses hybrid handling unless asked
// otherwise; sizes are particle counts.
//   rain     disks r = 0.05 on a jittered 2.5r grid, at rest, falling into a V of two half-planes and
//            forming a dense pile
//   gas      disks with random velocities in a closed box, no gravity, elastic (a sparse gas:
//            10% of the area covered)
//   chains   chains of 10 particles joined by capsule edges and damped springs, falling in rows
//            onto a floor between two walls (3 impulse passes: see bench_scenes.cpp)
//   bullets  fast small disks (40-60 m/s, a sparse field) shot at a fixed chain of thin edges,
//            a ceiling above and walls at the sides: every bullet crosses 20-30 radii per step
// The dense-pile family (pileKinds(): scenes that cannot flatter a method), 1,000 steps,
// every start jittered from the seed:
//   pile-low-cor0, pile-low-cor0.5    disks r = 0.05 on a 2.5r grid jittered by 0.4 of the gap,
//                                      poured at rest into a V from just above it (rain's start)
//   pile-high-cor0, pile-high-cor0.5  the same block lifted by its own height: it lands at speed
//   pile-rest                          disks stacked almost settled (small gaps) in a flat-bottomed
//                                      box, hexagonally, COR 0: it settles by a few hundredths of a
//                                      radius per row and stays (what a resting pile costs; at
//                                      N = 2,500, 95% at rest after 200 steps in the default mode)
#pragma once

#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"
#include "fosssim/io/scene_file.h"

#include <string>
#include <vector>

namespace fosssim::bench {

struct BenchScene {
  std::string name;
  Scene scene;
  State state;
  std::string description;
  double gravity = 0;  ///< the SimpleGravityForce's y component (0: none), for engines that take it as a setting
};

/// The scene kinds, in the order the benchmark shows them.
const std::vector<std::string>& sceneKinds();

/// The dense-pile family, in the order the benchmark shows them (not in sceneKinds(): the
/// benchmark's default table stays what it was; scripts/bench --piles runs these).
const std::vector<std::string>& pileKinds();

/// sceneKinds() then pileKinds(): every name makeScene knows.
std::vector<std::string> allKinds();

/// The collision types a scene can be made with (the keywords of the collision table).
std::vector<std::string> collisionTypes();

/// Builds `kind` with about n particles (exactly n for rain, gas and the piles). `collision` is the
/// <collision type>; the seed fixes the random velocities and jitter. Unknown kind: false.
bool makeScene(const std::string& kind, int n, const std::string& collision, unsigned seed, BenchScene& out);

/// The scene as a scene file (fosssim-scenegen writes it with sceneToXml): the same scene the
/// benchmark steps, its description, and a <viewport> that frames it.
SceneFile toSceneFile(BenchScene s);

}  // namespace fosssim::bench
