// The failsafe's inelastic projection (Harmon, Vouga, Tamstorf, Grinspun 2008): for an impact
// zone (bodies joined by contacts the time-ordered response could not resolve) with predicted
// velocities v~ and diagonal mass matrix M, find
//
//     v* = argmin 1/2 (v - v~)^T M (v - v~)   subject to   G v >= 0,
//
// one row of G per contact (see ConstraintRow; the formulation is the contact-physics design
// notes' section "The failsafe: inelastic projection"). Bodies with
// inverse mass 0 (fixed particles, or a half-plane folded into a row) have no degrees of freedom
// and keep their velocity.
//
// Leaf math: bodies are indices, rows are plain coefficient vectors; the caller (the collision
// handler in fosssim_core) builds the rows from its scene.
//
// Promises (each one a test in tests/math/zone_projection_test.cpp):
//  * the result is the unique minimiser (KKT: G v* >= 0, impulses >= 0, complementarity), up to
//    the stated relative tolerance, compared against an independent active-set enumeration;
//  * kinetic energy never grows when the immovable bodies are at rest -- at EVERY sweep, so
//    even a result reported as not converged is safe to use (see zone_projection.cpp);
//  * v* - v~ = M^-1 G^T lambda: motion orthogonal to a body's contact normals (tangential
//    sliding) is kept, and free bodies' momentum is kept;
//  * scale-free: scaling all velocities, all masses or all coefficients gives the same sweep
//    count and the correspondingly scaled result (up to rounding).
//
// Limitation (PGS's, stated so callers plan for it): jammed zones whose normals are nearly
// dependent -- a disk driven into a narrow V, an over-constrained pile with v* = 0 -- contract
// slowly (a V of half-angle a by about cos^2(2a) per sweep) and can spend the sweep budget; about
// 2% of random over-constrained test zones do. The result then has converged = false and the
// residual reached; its velocities are still feasible-leaning and never add energy, but contacts
// may still approach: the caller's fallback (the rigid zone) takes over.
#pragma once

#include <vector>

#include "fosssim/math/geometry.h"

namespace fosssim::math {

/// One non-penetration constraint: sum_k coef[k] . v[body[k]] >= bias (a row of G), 1 to 3 bodies.
/// particle-particle (i, j), n from i to j:   {i: -n, j: n}
/// particle-edge (p; a, b; alpha):             {p: n, a: -(1 - alpha) n, b: -alpha n}
/// particle-half-plane (p; n):                 {p: n}
/// A body may appear twice in one row (its coefficients then add).
/// bias <= 0 (a speed): how fast the row may close. 0 for a contact; a pair still apart by a gap
/// may close it by the end of the step, -gap / (time left), and no faster (a speculative row).
/// The set of allowed velocities still contains v = 0, so a projection onto it never adds
/// kinetic energy (it is non-expansive about 0, as the projection onto the cone bias = 0 is).
struct ConstraintRow {
  int count = 0;
  int body[3] = {0, 0, 0};
  Vec2 coef[3] = {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  double bias = 0.0;
};

/// Relative stopping tolerance (see ProjectionSettings::tolerance). 1e-10 leaves six orders of
/// magnitude above the rounding of w_k (~1e-16 relative) and is far below anything visible in a
/// trajectory; PGS reaches it in tens of sweeps on typical zones.
inline constexpr double kProjectionTolerance = 1e-10;

/// Sweep budget. PGS contracts like Gauss-Seidel on the zone's contact graph: a chain of n equal
/// contacts (the worst common case: a column of disks, a rack) needs about 2.3 n^2 sweeps to
/// gain 10 digits, so 10000 sweeps cover chains of ~65 contacts. Larger stuck zones are the
/// rigid-zone fallback's job; the budget bounds the cost at 10000 * rows row updates.
inline constexpr int kProjectionMaxSweeps = 10000;

struct ProjectionSettings {
  /// Stop when, for every row k with A_kk > 0,
  ///     |min(A_kk lambda_k, w_k)| <= tolerance * |G_k| * V
  /// and, for every row with A_kk == 0 (all its bodies immovable), max(0, -w_k) <= the same,
  /// where w_k = G_k v is the row's current velocity, |G_k| = sqrt(sum |coef|^2) over the row's
  /// entries, and V = max |v~_b| over the bodies the rows reference. See zone_projection.cpp for
  /// why this measures both violation and complementarity and why it is scale-free.
  double tolerance = kProjectionTolerance;
  int maxSweeps = kProjectionMaxSweeps;
};

struct ProjectionResult {
  int sweeps = 0;          ///< Gauss-Seidel sweeps done (each visits every row once)
  double residual = 0;     ///< the max over rows of the measure above divided by |G_k| V, at v*
  bool converged = false;  ///< residual <= tolerance (false also on non-finite input)
};

/// Finds v* = argmin 1/2 (v - v~)^T M (v - v~) subject to G v >= 0, bodies with inverse mass 0
/// keep their velocity. inverseMass[b] >= 0 for bodies 0..B-1; v holds v~ on entry (B entries) and
/// v* on exit. Bodies no row references are untouched.
class ZoneProjector {  // owns scratch so repeated solves do not allocate
 public:
  ProjectionResult project(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                           std::vector<Vec2>& v, const ProjectionSettings& settings = {});

  /// The impulses lambda (one per row, >= 0) of the last project(): v* = v~ + M^-1 G^T lambda.
  const std::vector<double>& lastImpulses() const { return lambda_; }

 private:
  std::vector<double> lambda_;    // per row: the multiplier
  std::vector<double> diag_;      // per row: A_kk = G_k M^-1 G_k^T (0: row skipped)
  std::vector<double> rowScale_;  // per row: |G_k| V, the denominator of the residual (0: trivial row)
};

/// Rows and bodies (movable or not) that projectByEnumeration takes: its arrays are sized at
/// compile time, and 2^rows active sets are as many as it can afford.
constexpr int kMaxEnumerationRows = 20;
constexpr int kMaxEnumerationBodies = 32;

/// Reference solver for tests: enumerates active sets (feasible for up to ~14 rows), exact KKT;
/// returns false if none found (or for more than kMaxEnumerationRows rows or kMaxEnumerationBodies
/// bodies).
bool projectByEnumeration(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                          std::vector<Vec2>& v);
/// The same with a row counted as satisfied at w_k >= -relTol |G_k| V (V: the largest speed of
/// the rows' bodies), writing each row's multiplier to `impulses`: the reference the tests hold
/// the exact solves (projectByActiveSet, ContactProjector::solveAlone) to.
bool projectByEnumeration(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                          std::vector<Vec2>& v, double relTol, std::vector<double>& impulses);

}  // namespace fosssim::math
