#pragma once
// Measures of a zone's constraint rows that the projection's solvers share (zone_projection.cpp's
// Gauss-Seidel and enumeration, active_set_projection.cpp's exact solve): a row's velocity and
// norm, and the zone's speed scale their tolerances are relative to. Internal to fosssim_math:
// not installed.

#include <algorithm>
#include <cmath>
#include <vector>

#include "fosssim/math/zone_projection.h"

namespace fosssim::math::measure {

/// G_k v - b_k: the row's velocity past its bias (>= 0 when the contact does not close faster
/// than its row allows); v indexed by body.
inline double rowVelocity(const ConstraintRow& row, const Vec2* v) {
  double w = 0.0;
  for (int j = 0; j < row.count; ++j) w += row.coef[j].dot(v[row.body[j]]);
  return w - row.bias;  // exact for bias 0: the rows of contacts read as they always did
}
inline double rowVelocity(const ConstraintRow& row, const std::vector<Vec2>& v) { return rowVelocity(row, v.data()); }

/// |G_k| = sqrt(sum of |coef|^2) over the row's entries.
inline double rowNorm(const ConstraintRow& row) {
  double n2 = 0.0;
  for (int j = 0; j < row.count; ++j) n2 += row.coef[j].squaredNorm();
  return std::sqrt(n2);
}

/// The zone's velocity scale V: the largest speed among the bodies the rows reference.
inline double zoneSpeed(const std::vector<ConstraintRow>& rows, const std::vector<Vec2>& v) {
  double speed = 0.0;
  for (const ConstraintRow& row : rows)
    for (int j = 0; j < row.count; ++j) speed = std::max(speed, v[row.body[j]].norm());
  return speed;
}

}  // namespace fosssim::math::measure
