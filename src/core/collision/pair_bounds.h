// Internal header: the boxes the broad phase compares, and why comparing them is exact.
//
// The broad phase may skip a pair only when the narrow phase would certainly report nothing for
// it, rounding and the CCD's cutoffs included. Every box is therefore grown by a margin on top of
// the object's radius. Two kinds of narrow phase need two kinds of margin (Margins):
//
// The course's narrow phase (Margins::Course, CollisionSearch's): m = kRelativeMargin (S + r) +
// kAbsoluteMargin, where S bounds the magnitude of every coordinate involved in the step (start
// and end positions, half-plane points) and r is the object's radius. Two boxes that do not
// overlap are apart along some axis by more than r1 + r2 + m1 + m2. Why that suffices, per pair:
//
//  * particle-edge (swept): the narrow phase (math::detectPE without a log) first rejects pairs
//    whose swept boxes are apart by more than rv + re + kSweptBoxMargin * scale, scale <= 4 S +
//    rv + re; m1 + m2 >= 2 kRelativeMargin (S + ...) exceeds that by 4 kSweptBoxMargin S, far
//    more than the rounding of the box bounds (a few ulps of S). So the narrow phase's own first
//    test rejects every pair the broad phase skips.
//  * particle-particle (swept): the centres stay farther apart than rs + M (rs = r1 + r2,
//    M = m1 + m2) all step long, so the position quadratic rs^2 - |x21(t)|^2 <= -M^2 on [0, 1].
//    Its computed coefficients differ from the exact ones by rounding, at most c eps (S^2 + rs^2)
//    for a small c, and by the cutoff, which drops at most two leading coefficients below
//    1e-12 (a change of at most 2e-12 on [0, 1]). M^2 >= (2 kRelativeMargin (S + rs/2))^2 +
//    4 kAbsoluteMargin^2 exceeds both by orders of magnitude, so the quadratic the solver sees is
//    negative on [0, 1] by far more than its evaluation error: no positive time, no collision.
//  * particle-half-plane (swept): the same for r^2|m|^2 - s(t)^2 with the signed distance
//    s(t) = (x(t) - p).m linear in t; the broad phase skips the pair when |s| stays above
//    (r + M)|m| with M = m + kCutoffReach / |m| (the cutoff's 2e-12 in units of |m|^2).
//
// The default mode's exact queries (math::exactPP, exactPE, exactPH) and the static pairs (penalty
// force, simple handler) (Margins::Relative, PairCandidates' default): m = kRelativeMargin (E + r)
// + kCoordinateRounding S, where E is the object's own extent over the step (for a particle
// |dx| + |dy| of its motion; for an edge the width plus the height of its swept box, which bounds
// its length and its endpoints' motions). Why no absolute part and no kRelativeMargin S:
//
//  * The exact queries work on the pair's differences only (x2 - x1, the displacements, the edge
//    vector, each computed from the stored positions with a relative error of eps), scale them by
//    a power of two, and judge cutoffs relative to each polynomial's largest coefficient (4 eps).
//    What they can report beyond reach is therefore rounding relative to the pair's own
//    magnitudes, not to where the pair sits. A pair that could come within reach has those
//    magnitudes bounded by its two boxes: |x2 - x1| by the motions and sizes (a pair farther
//    apart than its motions can close is farther than reach by about its own distance, which
//    relative rounding cannot bridge), the displacements by E1 + E2, an edge vector by E. So
//    M = m1 + m2 >= kRelativeMargin (E1 + E2 + r1 + r2) bounds a few eps of every magnitude
//    involved by a factor of some 10^9, as (8e-6 S)^2 bounded a few eps S^2 above. Where the
//    distance enters squared (PE's interior, R^2 |e|^2 - (w x e)^2), the pair's largest magnitude
//    L is at most about 4 (E1 + E2 + r1 + r2), and M^2 >= (1e-6 L)^2 stays far above a few eps
//    L^2 likewise.
//  * Where the pair sits enters only as rounding of the positions themselves: a position at an
//    instant of the step (x + T d) or a box bound is off by a few ulps of S, which
//    kCoordinateRounding S exceeds by thousands.
//  * Static pairs compare |n| < reach at the positions x: |n| is off by a few ulps of itself
//    (at most about 3 S near reach) and the box bounds by a few ulps of S.
//  * The zones (ContactZones::near) and sleepers' wakes (EventHandler::stepBoxesMeet) test boxes
//    grown by the radii times 1 + kTouchingSlack (1e-6): the radius part kRelativeMargin r (4e-6)
//    contains them, so what they find is among the candidates.
//
// With S in the relative margin, as the course's boxes have it, a scene's cost depended on where
// it sits: 200 disks of `rain` moved 10^5 m from the origin had boxes 0.4 m wider than their
// 0.05 m radius, and 42 times the candidate pairs. With an absolute part, it depended on the
// scene's units: a scene drawn in micrometres had every box 4e-6 m wider than the scene.
//
// Non-finite states make no bounds at all: the callers then check every pair (as the reference).
// Boxes may be grown further (PairCandidates files them with some slack): larger boxes only add
// candidates. tests/core/broad_phase_grazing_test.cpp builds grazing pairs for both kinds of
// narrow phase, near the origin and far from it: the course's cutoff admits some beyond reach,
// which boxes without margins miss; the exact queries report pairs within a hair of reach.
#pragma once

#include "box_grid.h"

#include "fosssim/core/scene.h"
#include "fosssim/math/ccd.h"

#include <cmath>

namespace fosssim {

/// Relative part of the margin (see above): four times the narrow phase's swept-box margin.
constexpr double kRelativeMargin = 4 * math::kSweptBoxMargin;
/// The default mode's allowance for rounding of the coordinates themselves, as a fraction of their
/// largest magnitude S (about 4,500 ulps of S; see above).
constexpr double kCoordinateRounding = 1e-12;
/// Absolute part of the margin: covers the CCD's absolute leading-coefficient cutoff (squared
/// lengths below 1e-12) in the particle-particle position quadratic with a factor 8 to spare.
constexpr double kAbsoluteMargin = 4e-6;
static_assert(4 * kAbsoluteMargin * kAbsoluteMargin >= 16 * 2 * math::kNegligibleLeadingCoefficient,
              "the absolute margin must dominate the CCD cutoff");
/// Half-plane extra reach times |m|: the same cutoff in the unnormalised normal's units.
constexpr double kCutoffReach = 1e-5;
static_assert(kCutoffReach * kCutoffReach >= 16 * 2 * math::kNegligibleLeadingCoefficient,
              "the half-plane reach must dominate the CCD cutoff");

/// Largest |coordinate| of the positions a and b (2N each, b may equal a) and of the scene's
/// half-plane points; infinity when some coordinate is not finite. `threads`: ranges of particles.
double coordinateScale(const Scene& scene, const VecX& a, const VecX& b, int threads = 1);

/// Whether boxes carry the absolute margins (see above): the course's narrow phase needs them
/// (its cutoff is absolute), the exact and static ones do not, and would pay for them in a scene
/// of small units.
enum class Margins { Course, Relative };

/// The margin of an object of radius `radius` and extent `extent` over the step (see above), with
/// S = `scale`.
inline double margin(double scale, double radius, double extent, Margins margins) {
  if (margins == Margins::Course) return kRelativeMargin * (scale + radius) + kAbsoluteMargin;
  return kRelativeMargin * (extent + radius) + kCoordinateRounding * scale;
}

/// Particle p's extent over the step from qs to qe: |dx| + |dy| of its motion.
inline double particleExtent(const VecX& qs, const VecX& qe, int p) {
  return std::fabs(qe[2 * p] - qs[2 * p]) + std::fabs(qe[2 * p + 1] - qs[2 * p + 1]);
}

/// The box of particle p's centre moving from qs to qe, grown by `grow` on every side.
inline Box sweptPointBox(const VecX& qs, const VecX& qe, int p, double grow) {
  const double xs = qs[2 * p], ys = qs[2 * p + 1], xe = qe[2 * p], ye = qe[2 * p + 1];
  return Box{(xs < xe ? xs : xe) - grow, (ys < ye ? ys : ye) - grow, (xs > xe ? xs : xe) + grow,
             (ys > ye ? ys : ye) + grow};
}

/// Particle p moving from qs to qe, as a disk of its radius plus `extra`.
inline Box particleBox(const Scene& scene, const VecX& qs, const VecX& qe, int p, double scale, double extra,
                       Margins margins) {
  const double r = scene.radius[p];
  return sweptPointBox(qs, qe, p, r + extra + margin(scale, r, particleExtent(qs, qe, p), margins));
}

/// The box of edge e's segment with both endpoints moving from qs to qe, grown by `grow`.
inline Box sweptEdgeBox(const Scene& scene, const VecX& qs, const VecX& qe, int e, double grow) {
  const Edge& edge = scene.edges[e];
  const double xs[4] = {qs[2 * edge.i], qs[2 * edge.j], qe[2 * edge.i], qe[2 * edge.j]};
  const double ys[4] = {qs[2 * edge.i + 1], qs[2 * edge.j + 1], qe[2 * edge.i + 1], qe[2 * edge.j + 1]};
  Box b{xs[0], ys[0], xs[0], ys[0]};
  for (int k = 1; k < 4; ++k) {
    b.x0 = xs[k] < b.x0 ? xs[k] : b.x0;
    b.x1 = xs[k] > b.x1 ? xs[k] : b.x1;
    b.y0 = ys[k] < b.y0 ? ys[k] : b.y0;
    b.y1 = ys[k] > b.y1 ? ys[k] : b.y1;
  }
  return Box{b.x0 - grow, b.y0 - grow, b.x1 + grow, b.y1 + grow};
}

/// Edge e with both endpoints moving from qs to qe, as a capsule of its radius plus `extra`.
inline Box edgeBox(const Scene& scene, const VecX& qs, const VecX& qe, int e, double scale, double extra,
                    Margins margins) {
  const double r = scene.edges[e].radius;
  const Box bare = sweptEdgeBox(scene, qs, qe, e, 0.0);
  const double grow = r + extra + margin(scale, r, (bare.x1 - bare.x0) + (bare.y1 - bare.y0), margins);
  return Box{bare.x0 - grow, bare.y0 - grow, bare.x1 + grow, bare.y1 + grow};
}

/// False when particle p, moving from qs to qe, certainly stays farther than its radius plus
/// `extra` from half-plane h's boundary line (on either side) during the whole step.
inline bool nearHalfPlane(const Scene& scene, const VecX& qs, const VecX& qe, int p, int h, double scale,
                          double extra, Margins margins) {
  const HalfPlane& plane = scene.halfplanes[h];
  const double r = scene.radius[p];
  const double normal = plane.normal.norm();
  const double s0 = (at(qs, p) - plane.point).dot(plane.normal);
  const double s1 = (at(qe, p) - plane.point).dot(plane.normal);
  const double grow = r + extra + 2 * margin(scale, r, particleExtent(qs, qe, p), margins);
  const double reach = grow * normal + (margins == Margins::Course ? kCutoffReach : 0.0);
  return !((s0 > reach && s1 > reach) || (s0 < -reach && s1 < -reach));
}

}  // namespace fosssim
