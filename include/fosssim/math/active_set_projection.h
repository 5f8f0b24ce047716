// The failsafe's projection of a few bodies, exactly: Goldfarb and Idnani's dual active-set
// method (1983, "A numerically stable dual method for solving strictly convex quadratic
// programs") for
//
//     v* = argmin 1/2 (v - v~)^T M (v - v~)   subject to   G v >= 0,
//
// the problem ZoneProjector solves by Gauss-Seidel (zone_projection.h has the rows and the
// promises). Gauss-Seidel stalls where bodies of very different masses are squeezed together or
// where rows are nearly dependent; an active-set method does not, and takes a number of steps
// that grows with the rows, where the enumeration of active sets (projectByEnumeration) takes
// 2^rows. ContactProjector solves its small clusters with it (solveCluster).
//
// Promises (tests/math/active_set_projection_test.cpp): the same v* as the enumeration where
// that finds one; KKT (G v* >= -slack, lambda >= 0, complementarity, v* = v~ + M^-1 G^T lambda)
// on clusters too large to enumerate; false, never a wrong answer, when no v satisfies the rows
// (a body squeezed between two obstacles that close on it) or the limits below are passed.
#pragma once

#include <vector>

#include "fosssim/math/zone_projection.h"

namespace fosssim::math {

/// Movable bodies and rows projectByActiveSet takes: its matrices are sized at compile time, so a
/// solve allocates nothing. Bodies of inverse mass 0 (obstacles a row names) count in
/// kMaxActiveSetBodies, not in kMaxActiveSetMovable.
constexpr int kMaxActiveSetMovable = 16;
constexpr int kMaxActiveSetBodies = 96;
constexpr int kMaxActiveSetRows = 64;

/// A row whose normal (in the mass-weighted coordinates M^1/2 v) lies within this fraction of its
/// length of the span of the active rows' normals is taken as dependent on them: a step along
/// what is left of it would be lost to rounding (nearly parallel walls of a wedge).
constexpr double kActiveSetDependence = 1e-10;

/// Rows violated by more than this (relative as the caller's slack, relTol below) join the
/// active set, whatever the slack the caller accepts: a row left closing by up to the slack
/// comes back to the failsafe as a contact that still closes (a pile of masses 10^6 apart ended
/// a step overlapping a wall so, at a slack of 1e-9), and the active set's rows end tight to
/// rounding. A row that cannot join (dependent on tight rows) and is within the slack is left.
constexpr double kActiveSetJoin = 1e-13;

/// Writes v* into v and each row's multiplier into `impulses` (v* = v~ + M^-1 G^T impulses) and
/// returns true when it finds v* with every row satisfied to G_k v* >= -relTol |G_k| V (V: the
/// largest speed of the rows' bodies, as projectByEnumeration's slack). Returns false, v and the
/// impulses untouched, when the rows cannot all be satisfied, when rounding leaves a row
/// violated beyond the slack, or when the problem passes the limits above.
bool projectByActiveSet(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                        std::vector<Vec2>& v, double relTol, std::vector<double>& impulses);

}  // namespace fosssim::math
