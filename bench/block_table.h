// The per-block report both benchmarks print (fosssim-bench and fosssim-box2d-pile), in one format
// so that their tables line up: wall time per step of each block of 100 steps, and what the scene
// was doing at the time (particles in failsafe zones, particles at rest, Box2D's bodies awake,
// disks touching). An average over a run hides a cost that creeps as a pile forms, and a pile
// that costs nothing once it rests; the blocks show both, and the touching pairs tell a cost that
// grows with the scene's contacts (any engine's) from one that grows with the method.
#pragma once

#include "bench_scenes.h"

#include <cstdio>
#include <string>

namespace fosssim::bench {

constexpr long kBlockSteps = 100;  ///< steps per reported block
constexpr int kMaxBlocks = 100;    ///< blocks kept per run (fixed size: fosssim-bench's figures cross a pipe)

/// One block of a run. A figure an engine does not have is negative and printed as "-".
struct Block {
  long first = 0, last = 0;   ///< steps, counted from 1
  double msPerStep = 0;       ///< wall time of the block's steps per step
  double failsafeMs = -1;     ///< FOSSSim: of which the failsafe, per step
  double inZones = -1;        ///< FOSSSim: particles in failsafe zones at the ends of steps, mean share
  double atRest = 0;          ///< share of the movable particles at rest after the block's last step (atRestShare)
  double awake = -1;          ///< share of the particles (bodies) awake after the block's last step
  long touching = -1;         ///< pairs of disks touching after the block's last step (touchingPairs)
};

/// The speed below which a particle counts as at rest: a thousandth of its radius per step (0.01 m/s
/// for the benchmark's r = 0.05 m and dt = 0.005 s, which is also Box2D's sleep tolerance,
/// b2_linearSleepTolerance). It is relative to the scene, not an absolute speed; under gravity a
/// particle in free fall passes through it only at the top of a bounce.
double restSpeed(double radius, double dt);

/// The share of the scene's movable particles whose speed in `v` (2 entries per particle) is below
/// restSpeed. Not timed by the benchmarks (computed between blocks).
double atRestShare(const Scene& scene, const VecX& v);

/// Disks closer than this fraction of their radius sum beyond touching count as touching. The
/// engines rest differently: FOSSSim's contacts end at a gap of a few ulps, Box2D's overlap by up
/// to its linear slop (0.005 m, a tenth of the benchmark's radius); both are within it, while a
/// disk falling towards another is not until it is about to land.
constexpr double kTouchingGap = 0.01;

/// The pairs of distinct particles i < j of `x` (2 entries per particle) whose centres are at most
/// (r_i + r_j)(1 + kTouchingGap) apart: the scene's contacts, measured the same way for every
/// engine from positions alone. Non-finite positions, and those more than 10^15 cells of
/// 2 (1 + kTouchingGap) max r from the origin (no benchmark scene's), touch nothing. Not timed by
/// the benchmarks.
long touchingPairs(const Scene& scene, const VecX& x);

/// What names a run in the tables.
struct RunLabel {
  std::string engine;  ///< "FOSSSim", "FOSSSim --compat", "Box2D 2.4.1"
  std::string scene;
  int particles = 0;
  unsigned seed = 0;
  double restSpeed = 0;  ///< of the scene's first particle (the benchmark's scenes have one radius)
};

/// The label of `s` run by `engine`.
RunLabel runLabel(const std::string& engine, const BenchScene& s, unsigned seed);

/// The block table: a title line naming the run, a header, one row per block.
void printBlocks(const RunLabel& run, const Block* blocks, int count);

/// The same rows as CSV, appended to `path` (the header first when the file is new or empty), so
/// that several runs and both engines gather in one file. False (errno set) when it cannot be written.
bool appendBlocksCsv(const std::string& path, const RunLabel& run, const Block* blocks, int count);

}  // namespace fosssim::bench
