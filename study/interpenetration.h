// Interpenetration at a step's end: which pairs overlap and how deep. Measured by the study
// itself from positions and radii (not by the handlers), so every collision method is judged by
// the same ruler, including penalty, which has no handler at all.
#pragma once

#include "fosssim/core/scene.h"

namespace fosssim::study {

struct Overlap {
  int pairs = 0;         ///< overlapping pairs (particle-particle, -edge, -half-plane)
  double deepest = 0;    ///< largest r_sum - distance over them (0 if none), in scene length units
};

/// Overlaps at positions x. Pairs of two fixed particles, and a particle against an edge it is an
/// end of, are skipped (nothing could separate them); an overlap shallower than 1e-9 of the radii
/// sum is a touch, not an overlap (rounding of exact contact).
Overlap measureOverlap(const Scene& scene, const VecX& x);

/// Running totals over the step ends of a run.
struct OverlapTally {
  long stepsWithOverlap = 0;
  long pairSteps = 0;      ///< sum over step ends of overlapping pairs
  double deepest = 0;
  void add(const Overlap& o) {
    if (o.pairs > 0) ++stepsWithOverlap;
    pairSteps += o.pairs;
    if (o.deepest > deepest) deepest = o.deepest;
  }
};

}  // namespace fosssim::study
