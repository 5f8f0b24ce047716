// Small 2D closest-point helpers shared by CCD, the collision handlers, verification and the
// penalty force (the only copy: degenerate segments are guarded here once). Header-only and
// inline: they sit in per-pair inner loops.
#pragma once

#include <Eigen/Core>

namespace fosssim::math {

using Vec2 = Eigen::Vector2d;

/// Parameter alpha of the point a + alpha*(b - a) of the LINE through a and b closest to x:
/// alpha = ((x - a).(b - a)) / |b - a|^2. A degenerate segment (a == b) has every alpha
/// equally close; 0 is returned so callers get the endpoint a rather than a NaN.
inline double segmentParameterUnclamped(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double ee = e.squaredNorm();
  return ee > 0.0 ? (x - a).dot(e) / ee : 0.0;
}

/// The same, clamped to [0, 1]: the closest point of the SEGMENT.
inline double segmentParameterClamped(const Vec2& x, const Vec2& a, const Vec2& b) {
  const double alpha = segmentParameterUnclamped(x, a, b);
  return alpha < 0.0 ? 0.0 : (alpha > 1.0 ? 1.0 : alpha);
}

/// a + alpha*(b - a).
inline Vec2 pointOnSegment(const Vec2& a, const Vec2& b, double alpha) { return a + alpha * (b - a); }

/// Vector from x to the closest point of segment ab; *alpha (optional) receives the clamped
/// parameter. The particle-edge n of the penalty force, the simple handler, the failsafe's
/// contacts and the overlap depths.
inline Vec2 segmentContactVector(const Vec2& x, const Vec2& a, const Vec2& b, double* alpha = nullptr) {
  const double s = segmentParameterClamped(x, a, b);
  if (alpha != nullptr) *alpha = s;
  return pointOnSegment(a, b, s) - x;
}

/// Vector from x to the half-plane boundary through p with (unnormalised) normal m, along m:
/// ((p - x).m / m.m) m. Written with the raw m on purpose: it equals ((p - x).m^)m^ with
/// m^ = m/|m| but needs no square root, and it is the reference's PH contact vector of the
/// penalty force and of CCD.
inline Vec2 halfPlaneContactVector(const Vec2& x, const Vec2& p, const Vec2& m) {
  return ((p - x).dot(m) / m.squaredNorm()) * m;
}

/// The same vector computed through the unit normal, ((p - x).m^) m^ with m^ = m.normalized():
/// the reference's simple (discrete) handler computes it this way, and the last bits differ
/// from halfPlaneContactVector's, so --compat's simple-handler trajectories need this form.
inline Vec2 halfPlaneContactVectorUnit(const Vec2& x, const Vec2& p, const Vec2& m) {
  const Vec2 nhat = m.normalized();
  return (p - x).dot(nhat) * nhat;
}

}  // namespace fosssim::math
