// The failsafe's inelastic projection: projected Gauss-Seidel (PGS) on the dual LCP, in velocity
// form, and the active-set enumeration the tests compare it with.
//
// Derivation. The primal problem min 1/2 |v - v~|_M^2 s.t. G v >= 0 is strictly convex in the
// movable bodies' velocities, so v* is unique. Its Lagrangian stationarity gives
// M (v - v~) = G^T lambda, i.e. v* = v~ + M^-1 G^T lambda, and substituting leaves the dual LCP
//     A = G M^-1 G^T,  b = G v~:   lambda >= 0,  w = A lambda + b = G v >= 0,  lambda^T w = 0,
// which is the optimality condition of the dual f(lambda) = 1/2 lambda^T A lambda + b^T lambda
// over lambda >= 0. PGS minimises f exactly along one lambda_k at a time:
//     lambda_k <- max(0, lambda_k - w_k / A_kk),
// and keeping v = v~ + M^-1 G^T lambda up to date makes w_k = G_k v cost one row, not a row of A.
// Being coordinate descent on a convex quadratic with A positive semidefinite, it converges in v
// (lambda itself need not be unique when contacts are redundant; v is).
//
// Why kinetic energy never grows (immovable bodies at rest). The feasible set K = {v: G v >= 0}
// is then a convex cone containing v = 0, and v* is the M-norm projection of v~ onto K; for a
// cone, <v~ - v*, v*>_M = 0 (the objective along the ray t v* is stationary at t = 1), so
// Pythagoras gives |v~|_M^2 = |v*|_M^2 + |v~ - v*|_M^2: the energy lost is exactly
// 1/2 |v~ - v*|_M^2 >= 0. Stronger, and what makes a non-converged result safe: for ANY lambda,
// |v|_M^2 = |v~|_M^2 + 2 f(lambda) (expand v = v~ + M^-1 G^T lambda; b has no contribution from
// resting immovable bodies), and PGS starts at f(0) = 0 and never increases f. So every sweep's
// v has at most the energy of v~. Rows with a bias b_k <= 0 (G_k v >= b_k: a pair still apart,
// ConstraintRow::bias) keep this: their dual objective is f(lambda) = 1/2 lambda^T A lambda +
// lambda^T (G v~ - b), so |v|_M^2 = |v~|_M^2 + 2 f(lambda) + 2 lambda^T b <= |v~|_M^2 + 2 f(lambda)
// (lambda >= 0 >= b): K is no longer a cone, but it still holds v = 0.
//
// Why tangential motion is kept. v* - v~ = M^-1 G^T lambda: each body's velocity changes only
// along the coefficients (contact normals) of its own rows. A disk sliding along a wall keeps its
// tangential speed; a pile keeps flowing. Momentum: row k changes the momentum of body b by
// coef * lambda_k, and pair and edge rows' coefficients sum to zero, so free bodies' total
// momentum is kept (fixed bodies and half-planes absorb the rest).
//
// The stopping rule and why it is scale-free. For a row with A_kk > 0, the PGS update moves w_k by
// A_kk * |lambda_k' - lambda_k| = |min(A_kk lambda_k, w_k)|. That single number is zero exactly
// when the row satisfies its KKT conditions (lambda_k >= 0 is kept by construction): if w_k < 0 it
// is >= the violation -w_k; if lambda_k > 0 and w_k > 0 it is the complementarity gap in velocity
// units. It has the units of G_k v, so it is divided by |G_k| V (row norm times the zone's largest
// predicted speed). Under v -> s v, M -> s' M, coef -> s'' coef: w_k scales by s s'', lambda by
// s s' / s'', A_kk by s''^2 / s', so A_kk lambda_k and w_k both scale by s s'', exactly like
// |G_k| V. Every PGS step is equivariant under the same scaling, so the iteration is the same
// sequence scaled, and so are the sweep count and the result (up to rounding). V also bounds b:
// |b_k| <= sqrt(3) |G_k| V (Cauchy-Schwarz over <= 3 entries), so "relative to |b|" is covered,
// and V, unlike |b|, does not vanish when the zone's approach speeds are tiny next to its motion.
// A sweep's largest update is only a candidate: the residual is then recomputed at the final v
// (one pass without updates) and that is what is reported and compared with the tolerance.
#include "fosssim/math/zone_projection.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "row_measures.h"

namespace fosssim::math {
namespace {

// G_k M^-1 G_k^T. Entries naming the same body add their coefficients first.
double rowDiagonal(const ConstraintRow& row, const std::vector<double>& inverseMass) {
  double d = 0.0;
  for (int j = 0; j < row.count; ++j) {
    bool seen = false;
    for (int i = 0; i < j; ++i) seen = seen || row.body[i] == row.body[j];
    if (seen) continue;
    Vec2 c = row.coef[j];
    for (int i = j + 1; i < row.count; ++i)
      if (row.body[i] == row.body[j]) c += row.coef[i];
    d += inverseMass[row.body[j]] * c.squaredNorm();
  }
  return d;
}

}  // namespace

ProjectionResult ZoneProjector::project(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                                        std::vector<Vec2>& v, const ProjectionSettings& settings) {
  ProjectionResult result;
  const int m = static_cast<int>(rows.size());
  lambda_.assign(m, 0.0);  // no allocation once the capacity has grown to the largest zone
  diag_.resize(m);
  rowScale_.resize(m);
  for (const ConstraintRow& row : rows) {
    assert(row.count >= 1 && row.count <= 3);
    for (int j = 0; j < row.count; ++j) {
      assert(row.body[j] >= 0 && row.body[j] < static_cast<int>(v.size()));
      assert(row.body[j] < static_cast<int>(inverseMass.size()) && inverseMass[row.body[j]] >= 0.0);
    }
  }

  const double speed = measure::zoneSpeed(rows, v);
  if (!std::isfinite(speed)) {
    result.residual = std::numeric_limits<double>::infinity();
    return result;  // v untouched
  }
  if (speed == 0.0) {  // every referenced body at rest: G v~ = 0 is feasible, lambda = 0 complementary
    result.converged = true;
    return result;
  }

  // Rows whose bodies are all immovable (A_kk == 0) cannot change: their violation is measured
  // once and can only be reported. Rows with no coefficients (|G_k| == 0) are trivially met.
  double immovableResidual = 0.0;
  for (int k = 0; k < m; ++k) {
    rowScale_[k] = measure::rowNorm(rows[k]) * speed;
    diag_[k] = rowDiagonal(rows[k], inverseMass);
    if (rowScale_[k] > 0.0 && diag_[k] == 0.0)
      immovableResidual = std::max(immovableResidual, std::max(0.0, -measure::rowVelocity(rows[k], v)) / rowScale_[k]);
  }

  auto movableResidual = [&]() {
    double r = 0.0;
    for (int k = 0; k < m; ++k) {
      if (rowScale_[k] == 0.0 || diag_[k] == 0.0) continue;
      r = std::max(r, std::abs(std::min(diag_[k] * lambda_[k], measure::rowVelocity(rows[k], v))) / rowScale_[k]);
    }
    return r;
  };

  double residual = std::numeric_limits<double>::infinity();
  while (result.sweeps < settings.maxSweeps) {
    double largestUpdate = 0.0;
    for (int k = 0; k < m; ++k) {
      if (rowScale_[k] == 0.0 || diag_[k] == 0.0) continue;
      const ConstraintRow& row = rows[k];
      const double w = measure::rowVelocity(row, v);
      largestUpdate = std::max(largestUpdate, std::abs(std::min(diag_[k] * lambda_[k], w)) / rowScale_[k]);
      const double updated = std::max(0.0, lambda_[k] - w / diag_[k]);
      const double delta = updated - lambda_[k];
      if (delta == 0.0) continue;
      lambda_[k] = updated;
      for (int j = 0; j < row.count; ++j) v[row.body[j]] += (inverseMass[row.body[j]] * delta) * row.coef[j];
    }
    ++result.sweeps;
    if (largestUpdate <= settings.tolerance) {
      residual = movableResidual();
      if (residual <= settings.tolerance) break;
    }
  }
  if (!(residual <= settings.tolerance)) residual = movableResidual();  // budget spent: measure at v

  result.residual = std::max(residual, immovableResidual);
  result.converged = result.residual <= settings.tolerance;
  return result;
}

// Reference: the KKT system on every active set S (rows held at w_k = 0), dense and exact. v* is
// unique; the multipliers need not be, but some multiplier vector is supported on rows whose
// A_SS is nonsingular (a vertex of the multiplier polyhedron), so singular A_SS are skipped.
bool projectByEnumeration(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                          std::vector<Vec2>& v) {
  std::vector<double> impulses;
  return projectByEnumeration(inverseMass, rows, v, 1e-9, impulses);
}

bool projectByEnumeration(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                          std::vector<Vec2>& v, double relTol, std::vector<double>& impulses) {
  const int m = static_cast<int>(rows.size());
  const int n = 2 * static_cast<int>(v.size());
  if (m > kMaxEnumerationRows || n > 2 * kMaxEnumerationBodies) return false;
  impulses.assign(m, 0.0);
  // A_SS has rank at most the movable bodies' dimensions: larger active sets are singular.
  const int dims =
      2 * static_cast<int>(std::count_if(inverseMass.begin(), inverseMass.end(), [](double w) { return w != 0.0; }));
  // Sizes bounded at compile time: the enumeration's 2^m small systems then allocate nothing
  // (malloc and free took a sixth of a rattling box's time, the LU factorisations half).
  constexpr int kRows = kMaxEnumerationRows, kDims = 2 * kMaxEnumerationBodies;
  using RowsByDims = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kRows, kDims>;
  using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kRows, kRows>;
  using RowVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kRows, 1>;
  using DimVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDims, 1>;
  RowsByDims G = RowsByDims::Zero(m, n);
  DimVector vt(n), minv(n);
  for (int b = 0; b < static_cast<int>(v.size()); ++b) {
    vt.segment<2>(2 * b) = v[b];
    minv(2 * b) = minv(2 * b + 1) = inverseMass[b];
  }
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < rows[k].count; ++j) G.block<1, 2>(k, 2 * rows[k].body[j]) += rows[k].coef[j].transpose();
  const Square A = G * minv.asDiagonal() * G.transpose();
  RowVector b = G * vt;
  for (int k = 0; k < m; ++k) b(k) -= rows[k].bias;  // the rows' velocities past their biases

  const double speed = measure::zoneSpeed(rows, v);
  if (speed == 0.0) return true;
  RowVector scale(m);
  for (int k = 0; k < m; ++k) scale(k) = relTol * measure::rowNorm(rows[k]) * speed;

  std::vector<int> active;
  for (unsigned mask = 0; mask < (1u << m); ++mask) {
    active.clear();
    for (int k = 0; k < m; ++k)
      if (mask & (1u << k)) active.push_back(k);
    const int s = static_cast<int>(active.size());
    if (s > dims) continue;
    RowVector lambda = RowVector::Zero(m);
    if (s > 0) {
      Square Ass(s, s);
      RowVector rhs(s);
      for (int i = 0; i < s; ++i) {
        rhs(i) = -b(active[i]);
        for (int j = 0; j < s; ++j) Ass(i, j) = A(active[i], active[j]);
      }
      Eigen::FullPivLU<Square> lu(Ass);
      lu.setThreshold(1e-10);
      if (lu.rank() < s) continue;
      const RowVector ls = lu.solve(rhs);
      bool ok = true;
      for (int i = 0; i < s && ok; ++i) ok = A(active[i], active[i]) * ls(i) >= -scale(active[i]);
      if (!ok) continue;
      for (int i = 0; i < s; ++i) lambda(active[i]) = std::max(0.0, ls(i));
    }
    // The rows' velocities from the velocities, not as A lambda + b: with bodies of very
    // different masses A's entries are huge and their products cancel to w, rounding to far more
    // than the slack (a disk 10^6 times lighter than its neighbour: 1e-10 of the speeds).
    const DimVector vs = vt + minv.asDiagonal() * (G.transpose() * lambda);
    RowVector w = G * vs;
    for (int k = 0; k < m; ++k) w(k) -= rows[k].bias;
    bool feasible = true;
    for (int k = 0; k < m && feasible; ++k) feasible = w(k) >= -scale(k);
    if (!feasible) continue;
    for (int bIdx = 0; bIdx < static_cast<int>(v.size()); ++bIdx) v[bIdx] = vs.segment<2>(2 * bIdx);
    for (int k = 0; k < m; ++k) impulses[k] = lambda(k);
    return true;
  }
  return false;
}

}  // namespace fosssim::math
