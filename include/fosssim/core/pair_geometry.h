// Closest-point geometry shared by the penalty force and the discrete (simple) collision handler.
#pragma once

#include "fosssim/core/types.h"

namespace fosssim {

/// Parameter alpha of the point of the line a + alpha (b - a) closest to p (unclamped).
inline double segmentParameter(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  return (p - a).dot(e) / e.squaredNorm();
}

/// Vector from p to its projection on the boundary of the half-plane through `point` with
/// (unnormalised) `normal`: ((point - p) . nhat) nhat.
inline Vec2 halfPlaneContact(const Vec2& p, const Vec2& point, const Vec2& normal) {
  const Vec2 nhat = normal.normalized();
  return (point - p).dot(nhat) * nhat;
}

}  // namespace fosssim
