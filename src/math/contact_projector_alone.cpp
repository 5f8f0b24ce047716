// ContactProjector::solveAlone: the exact projection of one body whose rows move no other body.
#include <algorithm>
#include <cmath>
#include <limits>

#include "contact_projector_update.h"

namespace fosssim::math {
namespace {

Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

// One body b alone against obstacles (every other body in its rows immovable, though a frozen
// one may move): its rows are G_k v = g_k . u + c_k >= 0, with g_k its coefficient and c_k the
// obstacles' part (0 unless one moves), and the projection is
//     u = argmin |u - v0|^2 (mass norm: one mass, so the plain norm) subject to g_k . u + c_k >= 0,
// v0 = v - w sum_k lambda_k g_k being b's velocity without its rows' impulses (w = 1/m). The
// feasible set is a convex polygon of the plane (maybe unbounded), so u is v0 itself, or v0
// projected onto one row's line, u = v0 - ((g_k . v0 + c_k) / |g_k|^2) g_k, or a corner where two
// rows' lines meet: of those that are feasible, the nearest to v0 (the projection onto a convex
// set is the feasible point nearest to v0, and it is one of them). Its multipliers follow from
// u - v0 = w sum_k mu_k g_k, on the one or two rows it lies on (a corner's by Cramer's rule, kept
// only with both mu >= 0, the projection's optimality condition). Gauss-Seidel converges on such
// rows at the rate of the cosine between their normals, squared, per sweep: in a wedge of
// 2 degrees, 0.9988, and a solve's budget ended long before it stopped the disk.
bool ContactProjector::solveAlone(int k, bool refreshing) {
  int b = -1;
  {
    const Row& row = row_[k];
    for (int m = 0; m < row.r.count; ++m) {
      const int s = row.r.body[m];
      if (inverseMass_[s] == 0.0 || s == b) continue;
      if (b >= 0) return false;  // two bodies move
      b = s;
    }
  }
  if (b < 0 || axis_[b] != Vec2::Zero() || body_[b].rowCount > kAloneRows) return false;
  int rows[kAloneRows];
  Vec2 g[kAloneRows];
  double c[kAloneRows];
  int count = 0;
  bool alone = true;
  const double w = inverseMass_[b];
  Vec2 v0 = velocity_[b];
  double scale = 0;  // of the rows' terms, for the slack
  body_[b].forEachRow([&](int q) {
    const Row& rq = row_[q];
    Vec2 gq = Vec2::Zero();
    double cq = -rq.r.bias;  // the row reads gq . v + cq >= 0
    bool mine = false;
    for (int m = 0; m < rq.r.count; ++m) {
      const int s = rq.r.body[m];
      if (s == b) gq += rq.r.coef[m], mine = true;
      else if (inverseMass_[s] != 0.0) alone = false;
      else cq += rq.r.coef[m].dot(velocity_[s]), scale = std::max(scale, velocity_[s].norm());
    }
    if (!mine || rq.diag <= 0.0) return;   // a list's stale entry, or a row that cannot act
    if (refreshing && rq.epoch != epoch_) alone = false;  // to be made again first (RowSource)
    v0 -= (w * rq.lambda) * gq;
    rows[count] = q, g[count] = gq, c[count] = cq, ++count;
  });
  if (!alone || count == 0) return false;
  scale = std::max(scale, v0.norm());
  const auto feasible = [&](const Vec2& u) {
    for (int j = 0; j < count; ++j)
      if (g[j].dot(u) + c[j] < -kAloneSlack * scale * g[j].norm()) return false;
    return true;
  };
  double mu[kAloneRows] = {};
  if (!feasible(v0)) {
    double nearest = std::numeric_limits<double>::infinity();
    int first = -1, second = -1;
    double muFirst = 0, muSecond = 0;
    for (int i = 0; i < count; ++i) {
      const double violation = g[i].dot(v0) + c[i];
      if (violation >= 0.0) continue;  // a line the projection can lie on is one v0 violates
      const double m = -violation / (w * g[i].squaredNorm());
      const Vec2 u = v0 + (w * m) * g[i];
      const double distance = (u - v0).squaredNorm();
      if (distance < nearest && feasible(u)) nearest = distance, first = i, second = -1, muFirst = m;
    }
    for (int i = 0; i < count; ++i)
      for (int j = i + 1; j < count; ++j) {
        const double det = cross(g[i], g[j]);
        if (!(std::abs(det) > kAloneParallel * g[i].norm() * g[j].norm())) continue;  // no corner to trust
        // The corner: g_i . u = -c_i and g_j . u = -c_j; then u - v0 = w (mu_i g_i + mu_j g_j).
        const Vec2 u = (-c[i] * perp(g[j]) + c[j] * perp(g[i])) / -det;
        const Vec2 d = (u - v0) / w;
        const double mi = cross(d, g[j]) / det, mj = cross(g[i], d) / det;
        const double distance = (u - v0).squaredNorm();
        if (mi < 0.0 || mj < 0.0 || !(distance < nearest) || !feasible(u)) continue;
        nearest = distance, first = i, second = j, muFirst = mi, muSecond = mj;
      }
    if (first < 0) return false;  // infeasible (a frozen obstacle moving in): Gauss-Seidel's budget
    mu[first] = muFirst;
    if (second >= 0) mu[second] = muSecond;
  }
  // Exact arithmetic would never end above where the energy guard started the body (the
  // projection of v0 is no faster than any feasible velocity, the guard's start included when it
  // was feasible); rounding can, where two rows' lines are nearly parallel (a corner with huge
  // multipliers that nearly cancel) or the speeds are tiny against the multipliers' history.
  // The guard would then scale the solve back (capEnergy) and its contacts come back, to be
  // solved the same way again: Gauss-Seidel's update goes on instead.
  Vec2 u = v0;
  for (int j = 0; j < count; ++j) u += (w * mu[j]) * g[j];
  const Vec2& start = changedFlag_[b] ? startVelocity_[b] : velocity_[b];
  if (u.squaredNorm() > start.squaredNorm()) return false;
  for (int j = 0; j < count; ++j)
    if (mu[j] != row_[rows[j]].lambda) apply(rows[j], mu[j]);
  return true;
}

}  // namespace fosssim::math
