// ContactProjector::solveCluster: the exact projection of a few bodies whose rows move no body
// outside them.
#include <algorithm>
#include <limits>
#include <vector>

#include "contact_projector_update.h"
#include "fosssim/math/active_set_projection.h"

namespace fosssim::math {

// A cluster's bodies, and the obstacles its rows name (up to two a row), must fit the solver.
static_assert(ContactProjector::kClusterRows <= kMaxActiveSetRows, "a cluster's rows must fit the solver");
static_assert(ContactProjector::kClusterBodies <= kMaxActiveSetMovable, "a cluster's bodies must fit the solver");
static_assert(ContactProjector::kClusterBodies + 2 * ContactProjector::kClusterRows <= kMaxActiveSetBodies,
              "a cluster's bodies and obstacles must fit the solver");

// Why: Gauss-Seidel contracts slowly where bodies of very different masses are squeezed
// together. A light disk between a heavy one and a wall is pushed back and forth between its two
// rows, each update passing on a share of about m / M of what is left: a disk 245 times lighter
// ran through 65,536 updates without settling, every solve of its zone ended on its budget, and
// the zone, taken for a jam, stopped both disks (all their kinetic energy, at COR 1). Such
// clusters are small, and their projection is found exactly by the dual active-set method
// (projectByActiveSet, active_set_projection.cpp) from v0, the cluster's velocities without its
// rows' impulses: v* = v0 + M^-1 G^T lambda with lambda >= 0, G v* >= 0 and complementarity.
// Its steps grow with the rows, where the enumeration of active sets it replaced took up to
// 2^rows systems. Tried, like solveAlone, only for rows Gauss-Seidel keeps coming back to
// (masses kClusterMassRatio apart), and once when a solve is about to end on its budget
// (`anyMasses`: two light disks wedged in a corner by two heavy ones stall it as well).
bool ContactProjector::solveCluster(int k, RowSource* source, bool anyMasses) {
  // The cluster: row k's movable bodies and, through their rows, every movable body they meet.
  // Rows set at an earlier instant are made again first, as Gauss-Seidel makes them when it
  // reaches them (RowSource), and the cluster is gathered again with their new normals.
  int bodies[kClusterBodies];
  int nb = 0;
  std::vector<int>& rows = clusterRows_;
  std::vector<int>& stale = clusterStale_;
  const auto listed = [&](int s) { return std::find(bodies, bodies + nb, s) != bodies + nb; };
  const auto takeBodies = [&](const Row& row) {
    for (int m = 0; m < row.r.count; ++m) {
      const int s = row.r.body[m];
      if (inverseMass_[s] == 0.0 || listed(s)) continue;
      // Too many, locked to an axis, or a weld (a jam's bodies moving as one: the zones' budgets
      // and jams settle those, as they settle a pile)
      if (nb == kClusterBodies || axis_[s] != Vec2::Zero() || !welded_[s].empty()) return false;
      bodies[nb++] = s;
    }
    return true;
  };
  const auto gather = [&]() {
    nb = 0;
    rows.clear(), stale.clear();
    if (!takeBodies(row_[k])) return false;
    for (int head = 0; head < nb; ++head) {
      bool ok = true;
      body_[bodies[head]].forEachRow([&](int q) {
        const Row& rq = row_[q];
        if (!ok || rq.diag <= 0.0 || std::find(rows.begin(), rows.end(), q) != rows.end()) return;
        bool mine = false;  // a list's stale entry names the body no more
        for (int m = 0; m < rq.r.count; ++m) mine = mine || rq.r.body[m] == bodies[head];
        if (!mine) return;
        ok = static_cast<int>(rows.size()) < kClusterRows && takeBodies(rq);
        rows.push_back(q);
        if (source != nullptr && rq.epoch != epoch_) stale.push_back(q);
      });
      if (!ok) return false;
    }
    return true;
  };
  if (!gather() || nb < 2) return false;  // one body: solveAlone's (a locked one: Gauss-Seidel's)
  // Decided before anything changes: masses far apart, or the rescue where the source allows it.
  if (!anyMasses) {
    double lightest = 0.0, heaviest = std::numeric_limits<double>::infinity();  // as inverse masses
    for (int i = 0; i < nb; ++i)
      lightest = std::max(lightest, inverseMass_[bodies[i]]), heaviest = std::min(heaviest, inverseMass_[bodies[i]]);
    if (!(lightest >= kClusterMassRatio * heaviest)) return false;
  } else if (source != nullptr) {
    int ids[kClusterBodies];
    for (int i = 0; i < nb; ++i) ids[i] = body_[bodies[i]].id;
    if (!source->mayRescue(ids, nb)) return false;
  }
  if (!stale.empty()) {
    ConstraintRow now;
    for (int q : stale) {
      if (source->rowNow(q, now)) setRow(q, now, row_[q].group);
      else row_[q].epoch = epoch_;  // kept as it is for this instant
    }
    if (!gather() || !stale.empty() || nb < 2) return false;
  }

  // The solver's problem: the cluster's bodies first, then each obstacle a row names (its
  // velocity a constant of the row), rows on local indices, v0 without the rows' impulses.
  std::vector<double>& invMass = clusterMass_;
  std::vector<Vec2>& v = clusterVelocity_;
  std::vector<ConstraintRow>& local = clusterLocal_;
  std::vector<int>& slots = clusterSlots_;
  invMass.clear(), v.clear(), local.clear(), slots.assign(bodies, bodies + nb);
  for (int s : slots) invMass.push_back(inverseMass_[s]), v.push_back(velocity_[s]);
  for (int q : rows) {
    ConstraintRow r = row_[q].r;
    for (int m = 0; m < r.count; ++m) {
      const int s = r.body[m];
      auto at = std::find(slots.begin(), slots.end(), s);
      if (at == slots.end()) {
        slots.push_back(s), invMass.push_back(0.0), v.push_back(velocity_[s]);
        at = slots.end() - 1;
      }
      const int i = static_cast<int>(at - slots.begin());
      r.body[m] = i;
      if (i < nb) v[i] -= (inverseMass_[s] * row_[q].lambda) * r.coef[m];
    }
    local.push_back(r);
  }
  if (!projectByActiveSet(invMass, local, v, kClusterSlack, clusterImpulses_)) return false;
  // As for solveAlone: exact arithmetic never ends above the guard's start; rounding, on nearly
  // dependent rows, can, and Gauss-Seidel then goes on instead.
  double after = 0.0, start = 0.0;
  for (int i = 0; i < nb; ++i) {
    const int s = slots[i];
    after += v[i].squaredNorm() / inverseMass_[s];
    start += (changedFlag_[s] ? startVelocity_[s] : velocity_[s]).squaredNorm() / inverseMass_[s];
  }
  if (!(after <= start)) return false;
  for (size_t j = 0; j < rows.size(); ++j)
    if (clusterImpulses_[j] != row_[rows[j]].lambda) apply(rows[j], clusterImpulses_[j]);
  // The exact answer holds every row to kClusterSlack of the cluster's fastest body, which can be
  // looser than the solve's tolerance for a row (its zone's speeds): a wall's row under a light
  // disk squeezed by a heavy one was left closing at 1e-7 m/s, unqueued (apply queues the rows of
  // the bodies it moves but its own), and its pair ended the step 1e-9 m deep. Queued, each row
  // is measured against its own tolerance again, as after any update.
  for (int q : rows) queue(q);
  return true;
}

}  // namespace fosssim::math
