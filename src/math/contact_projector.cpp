#include "fosssim/math/contact_projector.h"

#include <algorithm>
#include <cmath>

#include "contact_projector_update.h"

// The projector's rows, bodies, queue and Gauss-Seidel solve; its welds and locks. A body alone
// against obstacles is solved in contact_projector_alone.cpp, the energy guard and restitution
// are in contact_projector_energy.cpp.
namespace fosssim::math {
namespace {

Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }

}  // namespace

void ContactProjector::reset(int capacity) {
  if (static_cast<int>(slot_.size()) != capacity) slot_.assign(capacity, -1);
  for (const Body& b : body_) slot_[b.id] = -1;
  body_.clear();
  welded_.clear();
  changedFlag_.clear();
  velocity_.clear();
  inverseMass_.clear();
  axis_.clear();
  row_.clear();
  replaced_.clear();
  queued_.clear();
  restitution_.clear();
  loadedRestitution_.clear();
  head_ = tail_ = 0;
  changed_.clear();
  startVelocity_.clear();
  touchedFlag_.clear();
  revisits_.clear();
  startLambda_.clear();
  startReplaced_.clear();
  touched_.clear();
  updates_ = 0;
}

void ContactProjector::addBody(int b, double inverseMass, const Vec2& v) {
  if (hasBody(b)) return;
  slot_[b] = static_cast<int>(body_.size());
  Body body;
  body.id = b;
  body_.push_back(std::move(body));
  welded_.emplace_back();
  changedFlag_.push_back(0);
  velocity_.push_back(v);
  inverseMass_.push_back(inverseMass);
  axis_.push_back(Vec2::Zero());
  startVelocity_.push_back(v);
}

int ContactProjector::addRow(const ConstraintRow& row, double warmStart, int group) {
  row_.emplace_back();
  replaced_.push_back(0.0);
  queued_.push_back(0);
  restitution_.push_back(0.0);
  loadedRestitution_.push_back(0.0);
  touchedFlag_.push_back(0);
  revisits_.push_back(0);
  startLambda_.push_back(0.0);
  startReplaced_.push_back(0.0);
  const int index = static_cast<int>(row_.size()) - 1;
  setRow(index, row, group);
  if (warmStart > 0.0) apply(index, warmStart);  // from 0
  return index;
}

// The row's bodies' lists name it once; a replaced row keeps its bodies' lists and adds itself
// to those of new bodies (a stale entry only queues a row needlessly). Its impulse so far stays
// applied to the velocities; lambda restarts at 0, so the row can only push further along its new
// normal: every later update is again a projection onto a half-space through v = 0.
void ContactProjector::setRow(int index, const ConstraintRow& row, int group) {
  Row& k = row_[index];
  // For the energy guard: what the multiplier gained since the guard's start leaves it for
  // replaced_, and the new multiplier starts from 0.
  touch(index);
  startReplaced_[index] += k.lambda - startLambda_[index];
  startLambda_[index] = 0.0;
  replaced_[index] += k.lambda;
  k.r = row;
  k.group = group;
  k.epoch = epoch_;
  k.diag = 0;
  k.lambda = 0;
  double normSquared = 0;
  for (int m = 0; m < row.count; ++m) {
    const int s = slot_[row.body[m]];
    k.r.body[m] = s;
    normSquared += row.coef[m].squaredNorm();
  }
  constrain(k.r);
  k.diag = diagonal(k.r);
  k.norm = std::sqrt(normSquared);
  for (int m = 0; m < row.count; ++m) {
    Body& body = body_[k.r.body[m]];
    if (!body.hasRow(index)) body.addRow(index);
  }
  queue(index);
}

void ContactProjector::queue(int k) {
  if (queued_[k]) return;
  queued_[k] = 1;
  makeRoom(1);
  work_[tail_++] = k;
}

// The queue is a window [head_, tail_) sliding along work_. Each row is queued at most once, so
// the window holds at most rows() entries; sliding it back to the front when more was consumed
// than it holds keeps work_ within about twice the rows however long a solve runs (a pile's
// first solve makes a million updates at N = 10^5, and the slots it consumed used to stay).
void ContactProjector::growRoom(size_t n) {
  if (head_ >= tail_ - head_) {
    std::copy(work_.begin() + static_cast<long>(head_), work_.begin() + static_cast<long>(tail_), work_.begin());
    tail_ -= head_;
    head_ = 0;
    if (tail_ + n <= work_.size()) return;
  }
  work_.resize(2 * (tail_ + n));
}

// One Gauss-Seidel step on row k (ZoneProjector's, in velocity form): w = G_k v, then
// lambda' = max(0, lambda - w / A_kk) and v_b += w_b coef_b (lambda' - lambda). Its residual
// |min(A_kk lambda, w)| / (|G_k| V) is zero exactly when the row is satisfied and complementary.
bool ContactProjector::solve(const double* groupScale, double factor, double tolerance, long maxUpdates,
                             RowSource* source) {
  long updates = 0;
  bool rescued = false;  // the budget's exact rescue was tried (see below)
  ConstraintRow now;
  while (head_ < tail_) {
    const int k = work_[head_++];
    Row& row = row_[k];
    queued_[k] = 0;
    const double w = rowVelocity(k);
    const double threshold = tolerance * row.norm * (factor * groupScale[row.group]);
    if (row.diag <= 0.0) continue;  // every body immovable: nothing to move (a violation stays)
    // fmin and fmax written out (glibc's own definitions, NaN included): the calls were not
    // inlined, and this loop is the failsafe's.
    const double reached = row.diag * row.lambda <= w || std::isnan(w) ? row.diag * row.lambda : w;
    if (std::fabs(reached) <= threshold) continue;
    if (source != nullptr && row.epoch != epoch_) {  // stale: made again first (RowSource)
      if (source->rowNow(k, now)) {
        setRow(k, now, row.group);  // queued again, to be looked at with its new normal
        continue;
      }
      row.epoch = epoch_;  // kept as it is for this instant
    }
    // A solve about to end on its budget in a cluster small enough to be solved exactly (and
    // that the source lets be: RowSource::mayRescue) is solved exactly, whatever its masses,
    // once per solve: a budget-ended solve is a zone's failure, and enough of them make a jam,
    // which stops its particles (two light disks wedged in a corner by two heavy ones at COR 1
    // lost 87% of a fast box's energy so).
    if (++updates > maxUpdates && !rescued) {
      rescued = true;
      if (solveCluster(k, source, /*anyMasses=*/true)) {
        // The exact solve counts as one update, and what it queued may take kClusterRows more
        // (the worklist is shared: a fresh budget went to the other zones' rows, and pile-rest
        // 1,000 made 41% more updates a step).
        maxUpdates = updates + kClusterRows;
        continue;
      }
    }
    if (updates > maxUpdates) {  // row k stays queued, at the front, with the rest
      queued_[k] = 1;
      --head_;
      updates_ += maxUpdates;
      return false;
    }
    // A row Gauss-Seidel keeps coming back to, of a body alone against obstacles or of a small
    // cluster of bodies, is solved exactly with the body's or cluster's other rows (tried at its
    // 32nd, 64th, 128th... update: a row in neither costs a look at its bodies' rows now and
    // then, not at every update).
    if (const int seen = ++revisits_[k]; seen >= kAloneAfterUpdates && (seen & (seen - 1)) == 0 &&
                                         (solveAlone(k, source != nullptr) || solveCluster(k, source)))
      continue;
    const double lambda = row.lambda - w / row.diag;
    apply(k, 0.0 >= lambda || std::isnan(lambda) ? 0.0 : lambda);
  }
  head_ = tail_ = 0;
  updates_ += updates;
  return true;
}

void ContactProjector::takeQueued(std::vector<int>& out) {
  for (size_t q = head_; q < tail_; ++q) {
    queued_[work_[q]] = 0;
    out.push_back(work_[q]);
  }
  head_ = tail_ = 0;
}

// A_kk = sum over the row's distinct bodies of w_b |sum of that body's coefficients|^2 (a body
// named twice acts as one: its coefficients add). Slots, not ids.
double ContactProjector::diagonal(const ConstraintRow& r) const {
  double diag = 0;
  for (int m = 0; m < r.count; ++m) {
    bool first = true;
    for (int q = 0; q < m; ++q) first = first && r.body[q] != r.body[m];
    if (!first) continue;
    Vec2 c = Vec2::Zero();
    for (int q = m; q < r.count; ++q)
      if (r.body[q] == r.body[m]) c += r.coef[q];
    diag += inverseMass_[r.body[m]] * c.squaredNorm();
  }
  return diag;
}

void ContactProjector::freeze(int b, const Vec2& v) {
  const int s = slot_[b];
  Body& body = body_[s];
  // Already immovable at v (a rigid zone moved again, a stopped particle stopped again): its rows'
  // diagonals know it. moveRigidly freezes every member of a zone each time the zone is resolved,
  // and recomputing their diagonals took a fifth of rain's time (N = 10^4).
  if (inverseMass_[s] == 0.0 && velocity_[s] == v) return;
  inverseMass_[s] = 0.0;
  body.forEachRow([&](int k) { row_[k].diag = diagonal(row_[k].r); });  // the body no longer takes a share
  if (velocity_[s] == v) return;
  setVelocity(s, v);
  markChanged(s);  // what freeze sets is its own, not the rows': the guard starts there
}

void ContactProjector::constrain(ConstraintRow& r) const {
  bool one = true;
  Vec2 sum = Vec2::Zero();
  double size = 0.0;
  for (int m = 0; m < r.count; ++m) {
    const Vec2& t = axis_[r.body[m]];
    if (t != Vec2::Zero()) r.coef[m] = t.dot(r.coef[m]) * t;
    one = one && r.body[m] == r.body[0];
    sum += r.coef[m];
    size += r.coef[m].norm();
  }
  // Two particles' opposite normals cancel exactly; a particle against an edge's ends leaves
  // n (1 - (1 - alpha) - alpha), rounding, which would make a row of a direction chosen by noise.
  if (one && sum.norm() <= kCancelledFraction * size)
    for (int m = 0; m < r.count; ++m) r.coef[m] = Vec2::Zero();
}

Vec2 ContactProjector::coefficientOn(int k, int b) const {
  const int s = slot_[b];
  const ConstraintRow& r = row_[k].r;
  Vec2 g = Vec2::Zero();
  for (int m = 0; m < r.count; ++m)
    if (r.body[m] == s) g += r.coef[m];
  return g;
}

// Body a's slot is left empty (inverse mass 0, no rows); a, and every body welded to it before,
// name b's slot from now on. Each of a's rows is re-pointed to b's slot and listed there; a row
// that named both now names b's slot twice, which diagonal() and apply() treat as one body with
// the coefficients added (their own contact: -n + n = 0).
void ContactProjector::weld(int a, int b) {
  const int sa = slot_[a], sb = slot_[b];
  if (sa == sb || inverseMass_[sa] == 0.0 || inverseMass_[sb] == 0.0) return;  // both must be movable
  // The velocity and the energy guard's start merge alike: the multipliers since the start still
  // account for the change between them, so capEnergy's line from start to now stays theirs.
  markChanged(sa);
  markChanged(sb);
  const double ma = 1.0 / inverseMass_[sa], mb = 1.0 / inverseMass_[sb];
  Vec2 now = (ma * velocity_[sa] + mb * velocity_[sb]) / (ma + mb);
  Vec2 start = (ma * startVelocity_[sa] + mb * startVelocity_[sb]) / (ma + mb);
  if (const Vec2 t = axis_[sb]; t != Vec2::Zero()) {  // b's lock holds for the pair (a's: below)
    now = t.dot(now) * t;
    start = t.dot(start) * t;
  }
  startVelocity_[sb] = start;
  velocity_[sb] = now;
  inverseMass_[sb] = 1.0 / (ma + mb);
  const Vec2 lockA = axis_[sa];
  Body& from = body_[sa];
  Body& into = body_[sb];
  std::vector<int>& intoWelded = welded_[sb];
  intoWelded.push_back(from.id);
  for (int id : welded_[sa]) intoWelded.push_back(id);
  for (int id : intoWelded) slot_[id] = sb;
  welded_[sa].clear();
  from.forEachRow([&](int k) {
    ConstraintRow& r = row_[k].r;
    for (int m = 0; m < r.count; ++m)
      if (r.body[m] == sa) r.body[m] = sb;
    if (!into.hasRow(k)) into.addRow(k);
  });
  from.rowCount = 0;
  from.moreRows.clear();
  inverseMass_[sa] = 0.0;
  axis_[sa] = Vec2::Zero();
  if (lockA != Vec2::Zero()) lock(b, perp(lockA));  // a's lock is the pair's now
  into.forEachRow([&](int k) {
    constrain(row_[k].r);
    row_[k].diag = diagonal(row_[k].r);
    queue(k);
  });
}

ContactProjector::Lock ContactProjector::lock(int b, const Vec2& g) {
  const int s = slot_[b];
  if (inverseMass_[s] == 0.0 || g == Vec2::Zero()) return Lock::Unchanged;
  const Vec2 t = perp(g).normalized();
  if (axis_[s] != Vec2::Zero()) {
    if (std::fabs(axis_[s].dot(t)) >= 1.0 - kParallelLock) return Lock::Unchanged;  // the freedom it has left
    freeze(b, Vec2::Zero());
    return Lock::Frozen;
  }
  // The velocity and the energy guard's start are cut alike (as weld merges them).
  axis_[s] = t;
  markChanged(s);
  startVelocity_[s] = t.dot(startVelocity_[s]) * t;
  velocity_[s] = t.dot(velocity_[s]) * t;
  body_[s].forEachRow([&](int k) {
    constrain(row_[k].r);
    row_[k].diag = diagonal(row_[k].r);
    queue(k);
  });
  return Lock::Added;
}

void ContactProjector::setVelocity(int s, const Vec2& v) {
  if (changedFlag_[s]) startVelocity_[s] += v - velocity_[s];
  velocity_[s] = v;
}

// Its rows' diagonals take its share again; their multipliers so far stay applied to the other
// bodies (it had none of them while immovable), and they are queued: the next solve checks them
// with its velocity.
void ContactProjector::release(int b, double inverseMass, const Vec2& v) {
  const int s = slot_[b];
  if (inverseMass_[s] != 0.0) return;
  inverseMass_[s] = inverseMass;
  setVelocity(s, v);
  body_[s].forEachRow([&](int k) {
    row_[k].diag = diagonal(row_[k].r);
    queue(k);
  });
}

bool ContactProjector::Body::hasRow(int k) const {
  bool found = false;
  forEachRow([&](int row) { found = found || row == k; });
  return found;
}

void ContactProjector::Body::addRow(int k) {
  if (rowCount < kInlineRows) rows[rowCount] = k;
  else moreRows.push_back(k);
  ++rowCount;
}

void ContactProjector::takeChanged(std::vector<int>& out) {
  for (int s : changed_) {
    Body& body = body_[s];
    changedFlag_[s] = 0;
    if (slot_[body.id] != s) continue;  // welded into another body, which lists it
    out.push_back(body.id);
    out.insert(out.end(), welded_[s].begin(), welded_[s].end());
  }
  changed_.clear();
  for (int k : touched_) touchedFlag_[k] = 0, revisits_[k] = 0;
  touched_.clear();
}

}  // namespace fosssim::math
