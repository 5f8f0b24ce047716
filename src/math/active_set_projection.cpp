// Goldfarb and Idnani's dual active-set method for the zone projection (active_set_projection.h).
//
// Coordinates. Only movable bodies have unknowns. With y = M^1/2 (v - v~) (movable bodies'
// components, 2 per body) the objective is 1/2 |y|^2, and row k reads
//     a_k . y + s_k >= 0,   a_k = M^-1/2 G_k^T (the row's movable coefficients, each times
//                           sqrt of its body's inverse mass),   s_k = G_k v~
// (s_k includes what the row's obstacles contribute: their velocities are constants). The
// problem is the point of least norm in a polyhedron, whose optimum is y* = sum_k u_k a_k with
// u >= 0 and u_k = 0 on rows that are not tight: then v* = v~ + M^-1/2 y* = v~ + M^-1 G^T u, so
// the multipliers u are the rows' impulses lambda.
//
// The method. Start at the unconstrained optimum y = 0 with no active rows. While some row is
// violated, take the most violated p (by its distance a_p . y + s_p over |a_p|, which does not
// depend on the units) and move towards satisfying it while keeping the active rows tight:
//     z = a_p - Q Q^T a_p   (the part of a_p orthogonal to the active normals; Q an orthonormal
//                            basis of them, Q R = N = [a_j] over the active rows j),
//     r = R^-1 Q^T a_p      (how the active multipliers must change: a_p = N r + z).
// Along y + t z, row p's violation falls at |z|^2 per unit t and the active rows stay tight
// (a_j . z = 0); stationarity, y = N u_N + u_p a_p, holds on with u_N -> u_N - t r and
// u_p -> u_p + t, since t z = t a_p - N (t r). The step is the least of
//     t2 = -(a_p . y + s_p) / |z|^2   (row p becomes tight: it joins the active set), and
//     t1 = min over active j with r_j > 0 of u_j / r_j   (an active multiplier reaches 0: row j
//                                                         leaves the active set, and p is tried
//                                                         again from there).
// When a_p depends on the active normals (z = 0) only the multipliers move (a step t1 in the
// dual alone); if then no r_j is positive, a_p is a non-positive combination of tight rows that
// all hold: no y satisfies them and p together, and the problem is infeasible. The dual
// objective grows at every step and no active set repeats, so the method ends after finitely
// many (Goldfarb and Idnani's theorem); a cap on the steps guards against rounding.
//
// Active normals stay linearly independent (a dependent row never joins), so there are at most
// as many as the unknowns, 2 per movable body. Q and R are rebuilt for each step by classical
// Gram-Schmidt applied twice ("twice is enough", Giraud et al. 2005): at these sizes (16 columns
// at most) that costs less than updating a factorisation, and is as accurate.
#include "fosssim/math/active_set_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "row_measures.h"

namespace fosssim::math {
namespace {

constexpr int kDims = 2 * kMaxActiveSetMovable;
using RowsByDims = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor, kMaxActiveSetRows, kDims>;
using DimsByActive = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kDims, kDims>;
using DimVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDims, 1>;
using ActiveVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDims, 1>;

/// Steps (a row joining or leaving) a solve may take per row and unknown before it gives up: the
/// method needs about one per row joining, and a few leaving, on the clusters it is given.
constexpr int kStepsPerSize = 8;

/// Passes of iterative refinement of the active rows' multipliers at the end (see there).
constexpr int kRefinements = 2;

struct Basis {
  DimsByActive q;  ///< dims x dims, its first `count` columns orthonormal, spanning the active normals
  DimsByActive r;  ///< dims x dims, its top left count x count upper triangular: N = q r
  int count = 0;   ///< the active rows it holds (the first `count` of the active list)
};

// Takes from col its part in the span of q's first `columns` columns, twice (classical
// Gram-Schmidt, reorthogonalised), and returns that part's coefficients.
ActiveVector orthogonalise(const Basis& basis, int columns, DimVector& col) {
  ActiveVector coefficients = ActiveVector::Zero(columns);
  for (int pass = 0; pass < 2; ++pass) {
    const ActiveVector proj = basis.q.leftCols(columns).transpose() * col;
    col -= basis.q.leftCols(columns) * proj;
    coefficients += proj;
  }
  return coefficients;
}

// Column c of Q R = N: col is the active normal N_c orthogonalised against the columns before it
// (orthogonalise), `coefficients` what it took, `length` |N_c|. False when N_c is (nearly)
// dependent on the columns before it, which the method never lets join: rounding may still bring
// it there, and the solve then gives up.
bool setColumn(Basis& basis, int c, const DimVector& col, const ActiveVector& coefficients, double length) {
  const double left = col.norm();
  if (!(left > kActiveSetDependence * length)) return false;
  basis.r.col(c).head(c) = coefficients;
  basis.r(c, c) = left;
  basis.q.col(c) = col / left;
  basis.count = c + 1;
  return true;
}

// Q R = N for the active normals a.row(active[0..count)), each column orthogonalised against the
// earlier ones. Columns the basis holds already are kept: a column depends only on those before
// it, so they are what a factorisation from scratch makes, to the bit. A row that joins is the
// last column (appended by the caller); one that leaves takes the columns after it with it.
bool factor(const RowsByDims& a, const int* active, int count, Basis& basis) {
  for (int c = basis.count; c < count; ++c) {
    DimVector col = a.row(active[c]).transpose();
    const double length = col.norm();
    const ActiveVector coefficients = orthogonalise(basis, c, col);
    if (!setColumn(basis, c, col, coefficients, length)) return false;
  }
  return true;
}

}  // namespace

bool projectByActiveSet(const std::vector<double>& inverseMass, const std::vector<ConstraintRow>& rows,
                        std::vector<Vec2>& v, double relTol, std::vector<double>& impulses) {
  const int m = static_cast<int>(rows.size());
  const int bodies = static_cast<int>(v.size());
  if (m > kMaxActiveSetRows || bodies > kMaxActiveSetBodies) return false;
  const double speed = measure::zoneSpeed(rows, v);
  if (speed == 0.0) {  // nothing moves, so nothing closes: v* = v~ with no impulse
    impulses.assign(m, 0.0);
    return true;
  }
  int column[kMaxActiveSetBodies];  // a movable body's first unknown, -1 for an obstacle
  int dims = 0;
  for (int b = 0; b < bodies; ++b) {
    column[b] = inverseMass[b] != 0.0 ? dims : -1;
    if (inverseMass[b] != 0.0) dims += 2;
    if (dims > kDims) return false;
  }

  RowsByDims a = RowsByDims::Zero(m, dims);
  double s[kMaxActiveSetRows], slack[kMaxActiveSetRows], join[kMaxActiveSetRows], length[kMaxActiveSetRows],
      u[kMaxActiveSetRows];
  for (int k = 0; k < m; ++k) {
    const ConstraintRow& row = rows[k];
    for (int j = 0; j < row.count; ++j)
      if (const int c = column[row.body[j]]; c >= 0)
        a.block<1, 2>(k, c) += std::sqrt(inverseMass[row.body[j]]) * row.coef[j].transpose();
    s[k] = measure::rowVelocity(row, v);
    slack[k] = relTol * measure::rowNorm(row) * speed;
    join[k] = std::min(relTol, kActiveSetJoin) * measure::rowNorm(row) * speed;
    length[k] = a.row(k).norm();
    u[k] = 0.0;
    if (length[k] == 0.0 && s[k] < -slack[k]) return false;  // obstacles alone, closing
  }

  DimVector y = DimVector::Zero(dims);
  int active[kDims];
  int count = 0;
  bool isActive[kMaxActiveSetRows] = {};
  bool givenUp[kMaxActiveSetRows] = {};  // within the slack, and no step can do better (below)
  Basis basis;
  basis.q.resize(dims, dims);
  basis.r.resize(dims, dims);
  const int maxSteps = kStepsPerSize * (m + dims) + 16;
  int steps = 0;
  while (true) {
    // The most violated row, by distance in y (rows of obstacles alone are settled above).
    int p = -1;
    double worst = 0.0;
    for (int k = 0; k < m; ++k) {
      if (isActive[k] || givenUp[k] || length[k] == 0.0) continue;
      const double w = a.row(k).dot(y) + s[k];
      if (w >= -join[k]) continue;
      if (const double distance = w / length[k]; p < 0 || distance < worst) p = k, worst = distance;
    }
    if (p < 0) break;
    const DimVector ap = a.row(p).transpose();
    while (true) {  // until p joins (or the problem is found infeasible)
      if (++steps > maxSteps || !factor(a, active, count, basis)) return false;
      DimVector z = ap;
      const ActiveVector proj = orthogonalise(basis, count, z);
      const ActiveVector r = basis.r.topLeftCorner(count, count).triangularView<Eigen::Upper>().solve(proj);
      double t1 = std::numeric_limits<double>::infinity();
      int leaving = -1;
      for (int i = 0; i < count; ++i)
        if (r(i) > 0.0 && u[active[i]] / r(i) < t1) t1 = u[active[i]] / r(i), leaving = i;
      const bool dependent = !(z.norm() > kActiveSetDependence * length[p]);
      if (dependent && leaving < 0) {
        // p closes against tight rows: infeasible, unless p is within the caller's slack (its
        // violation then rounding of the tight rows it depends on) and took no multiplier yet
        // (so y stays the active rows' combination alone)
        if (ap.dot(y) + s[p] < -slack[p] || u[p] != 0.0) return false;
        givenUp[p] = true;
        break;
      }
      const double t2 = dependent ? std::numeric_limits<double>::infinity() : -(ap.dot(y) + s[p]) / z.squaredNorm();
      const double t = std::min(t1, t2);
      if (!dependent) y += t * z;
      for (int i = 0; i < count; ++i) u[active[i]] = std::max(0.0, u[active[i]] - t * r(i));
      u[p] += t;
      if (t2 <= t1) {
        // z is p's normal orthogonalised against the basis, as factor would make it: appended
        // (if it is dependent after all, the next factor finds so, as it did from scratch).
        (void)setColumn(basis, count, z, proj, ap.norm());
        active[count++] = p;
        isActive[p] = true;
        break;
      }
      u[active[leaving]] = 0.0;
      isActive[active[leaving]] = false;
      for (int i = leaving; i + 1 < count; ++i) active[i] = active[i + 1];
      --count;
      basis.count = std::min(basis.count, leaving);  // the columns from `leaving` on are made again
    }
  }

  // v* from the multipliers (v~ + M^-1 G^T u), and the active rows' multipliers refined so that
  // those rows are tight on the velocities themselves: the steps' rounding accumulates in y, and
  // a row left closing by a few ulps of a large impulse comes back to the caller as a contact
  // that still closes. Refinement: the active rows' velocities w_A are linear in their
  // multipliers, dw_A = N^T N du_A = R^T R du_A, so du_A = -(R^T R)^-1 w_A; twice, as iterative
  // refinement goes. Each row is then checked on the velocities, where the y coordinates would
  // hide the cancellations of very different masses.
  Vec2 out[kMaxActiveSetBodies];
  const auto velocities = [&]() {
    std::copy(v.begin(), v.end(), out);
    for (int k = 0; k < m; ++k)
      for (int j = 0; j < rows[k].count && u[k] != 0.0; ++j)
        out[rows[k].body[j]] += (inverseMass[rows[k].body[j]] * u[k]) * rows[k].coef[j];
  };
  const auto rowVelocity = [&](int k) { return measure::rowVelocity(rows[k], out); };
  velocities();
  if (count > 0 && factor(a, active, count, basis)) {
    for (int pass = 0; pass < kRefinements; ++pass) {
      ActiveVector w(count);
      for (int i = 0; i < count; ++i) w(i) = -rowVelocity(active[i]);
      const auto R = basis.r.topLeftCorner(count, count).triangularView<Eigen::Upper>();
      const ActiveVector du = R.solve(R.transpose().solve(w));
      for (int i = 0; i < count; ++i) u[active[i]] = std::max(0.0, u[active[i]] + du(i));
      velocities();
    }
  }
  for (int k = 0; k < m; ++k)
    if (!(rowVelocity(k) >= -slack[k])) return false;
  std::copy(out, out + bodies, v.begin());
  impulses.assign(u, u + m);
  return true;
}

}  // namespace fosssim::math
