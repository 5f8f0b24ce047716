// The failsafe's projection grown one contact at a time: the same problem as ZoneProjector
// (zone_projection.h: v* = argmin 1/2 (v - v~)^T M (v - v~) subject to G v >= 0), kept open while
// rows keep arriving, and solved by Gauss-Seidel steps driven by a worklist instead of sweeps.
//
// Why a worklist: in a pile, the zone is the whole pile (thousands of bodies) and contacts join
// it one or a few at a time (a disk landing on it). A sweep costs every row; the effect of a new
// row, though, spreads only as far as its impulse changes velocities. The worklist holds the rows
// whose bodies changed; a row whose residual (ZoneProjector's measure) is within the tolerance is
// dropped without an update, and every update queues the other rows of the bodies it moved. The
// fixed point is ZoneProjector's (every row within the tolerance), reached at a cost that follows
// what moves, not the size of the zone.
//
// Rows added after a solve project the velocities that solve left, not the original v~: the
// result is a sequence of projections onto shrinking cones through v = 0 (convex sets holding it,
// when rows have biases: ConstraintRow::bias), so kinetic energy still never grows (each
// projection is an M-orthogonal projection onto a convex set containing 0, and so no longer than
// what it projects) and tangential motion is still kept, but it is not the single projection of
// v~ onto the final set. A batch (all rows, then one solve) is exactly that single projection.
#pragma once

#include <vector>

#include "fosssim/math/exact_solve_limits.h"
#include "fosssim/math/zone_projection.h"

namespace fosssim::math {

class ContactProjector : public ExactSolveLimits {
 public:
  /// Makes a stale row again for the current instant. Why: an impulse conserves angular momentum
  /// only if it acts along the line through the contact at the instant it is applied. A row
  /// keeps the normal (and, for an edge, the contact's parameter) of the instant it was set; a
  /// later solve that changes its multiplier would push along a line the bodies have since left
  /// (the line of centres of a pair in a zone turns between instants: free packs of disks moved
  /// L by up to 1.0e-4 of its scale). Made again, the row is replaced as setRow replaces it (its
  /// impulse so far stays applied, from the instant it acted), and what changes now acts along
  /// the line of now. The price: that impulse can no longer be taken back by this row (a solve
  /// that would have lowered it leaves it); every update is still a projection through v = 0, so
  /// no energy is added.
  class RowSource {
   public:
    /// Row `index` as of the current instant, in `out` (bodies by id, as addRow takes them);
    /// false keeps the row as it is for this instant (a row whose normal the caller chose
    /// deliberately, or with no direction now).
    virtual bool rowNow(int index, ConstraintRow& out) = 0;
    /// Whether a solve about to end on its budget may project the cluster of these `count`
    /// bodies (ids) exactly (solveCluster's rescue); every cluster may when there is no source.
    virtual bool mayRescue(const int* /*ids*/, int /*count*/) { return true; }

   protected:
    ~RowSource() = default;
  };

  /// Forgets every body and row; bodies are indices 0..capacity-1.
  void reset(int capacity);

  /// Puts body b into the system with inverse mass w (0: immovable) and velocity v; a body
  /// already in it keeps its state.
  void addBody(int b, double inverseMass, const Vec2& v);
  bool hasBody(int b) const { return b < static_cast<int>(slot_.size()) && slot_[b] >= 0; }

  /// Adds a row over bodies already in the system and queues it for the next solve; returns its
  /// index. A positive `warmStart` (the contact's impulse of the last step) is applied at once
  /// as its starting multiplier: resting contacts then start where they ended, which is what
  /// makes Gauss-Seidel affordable on a pile at rest (from zero it needs O(depth^2) sweeps).
  /// `group` indexes the speed scales a solve measures residuals against (see solve).
  int addRow(const ConstraintRow& row, double warmStart = 0.0, int group = 0);
  /// The multiplier (impulse) of row `index` along its current normal.
  double impulse(int index) const { return row_[index].lambda; }
  /// The impulse row `index` has applied since it was added: its multiplier plus those of the
  /// normals setRow replaced (the contact's whole impulse: what starts it in the next step).
  double totalImpulse(int index) const { return row_[index].lambda + replaced_[index]; }
  /// Replaces row `index` (a contact's normal of a later time), its impulse so far kept applied
  /// to the velocities (and counted in totalImpulse) and its multiplier restarted at 0; queues it.
  void setRow(int index, const ConstraintRow& row, int group = 0);

  /// Gauss-Seidel updates from the queued rows until every row it reaches is within `tolerance`
  /// (ZoneProjector's residual, with V = speedScale), or `maxUpdates` updates: false then (the
  /// velocities are still safe, see above, but some contact may approach), and the rows not yet
  /// settled stay queued for the next solve (unqueueIf drops some, takeQueued sets them aside).
  bool solve(double speedScale, double tolerance, long maxUpdates) {
    return solve(&speedScale, 1.0, tolerance, maxUpdates);  // every row in group 0
  }
  /// The same with a speed scale per group of rows: row k's residual is measured against
  /// V = factor * groupScale[group of k]. Independent problems can then share the worklist (no
  /// body in two groups' rows moves) and each still settle to its own tolerance: under one
  /// scale, the largest group's would let a slow group's approaching rows pass as settled.
  /// With a `source`, a row set before the current instant (beginInstant) is first made again
  /// by the source before its multiplier changes (see RowSource).
  bool solve(const double* groupScale, double factor, double tolerance, long maxUpdates,
             RowSource* source = nullptr);

  /// Rows set from now on belong to a new instant of the caller's time; those set before are
  /// stale: a solve with a RowSource asks for them again before it changes their multipliers.
  void beginInstant() { ++epoch_; }

  /// Drops from the queue every row with a movable body b for which dropBody(b) holds (a solve
  /// that spent its budget leaves its rows queued: a caller solving independent problems drops
  /// only the failed problem's and lets the others' wait for their own solves).
  template <class Pred>
  void unqueueIf(Pred&& dropBody) {
    size_t kept = head_;
    for (size_t q = head_; q < tail_; ++q) {
      const int k = work_[q];
      if (moves(k, dropBody)) queued_[k] = 0;
      else work_[kept++] = k;
    }
    tail_ = kept;
  }
  /// Moves every queued row, in queue order, out of the queue and onto `out` (to be queued again
  /// with queueRow when its problem is solved).
  void takeQueued(std::vector<int>& out);
  /// Queues row k (if it is not queued).
  void queueRow(int k) { queue(k); }
  /// Whether row k has a movable body b for which pred(b) holds.
  template <class Pred>
  bool moves(int k, Pred&& pred) const {
    const Row& row = row_[k];
    for (int m = 0; m < row.r.count; ++m) {
      const int s = row.r.body[m];
      if (inverseMass_[s] != 0.0 && pred(body_[s].id)) return true;
    }
    return false;
  }
  /// Rows waiting in the queue.
  int queuedRows() const { return static_cast<int>(tail_ - head_); }

  const Vec2& velocity(int b) const { return velocity_[slot_[b]]; }
  /// Whether body b can still move (not immovable, not frozen, not locked in both directions).
  bool movable(int b) const { return inverseMass_[slot_[b]] != 0.0; }
  /// Makes an immovable body b movable again, with inverse mass w and velocity v, and queues its
  /// rows (a sleeper that met the zones as an obstacle and woke later in the step); no-op for a
  /// movable body.
  void release(int b, double inverseMass, const Vec2& v);
  /// Makes body b immovable from now on, at velocity v (the rigid fallback moves it instead).
  void freeze(int b, const Vec2& v);
  /// Makes movable bodies a and b one body from now on (the failsafe's answer to a jammed contact
  /// between them): one velocity, their momentum's (m_a v_a + m_b v_b) / (m_a + m_b), and the sum
  /// of their masses; each row on either acts on the pair. Momentum is kept and kinetic energy
  /// can only fall (an inelastic merge); their contact can no longer close. Rows and multipliers
  /// stay consistent with the velocities: v = v~ + M^-1 G^T lambda holds for the merged body with
  /// its merged v~ and each row's coefficients on it summed, so the energy guard (capEnergy) and
  /// later solves go on as before. A lock on either carries over.
  void weld(int a, int b);
  /// Takes from movable body b its freedom along g (a jammed contact against immovable bodies at
  /// rest, g its row's coefficient on b): b moves on only perpendicular to g, so that contact can
  /// no longer close, and its velocity loses its component along g (in the mass norm: kinetic
  /// energy can only fall, and momentum changes only along g, as an obstacle's impulse changes
  /// it). A second lock along another direction leaves b no freedom: it is frozen at rest.
  /// Returns what it did: Added, Frozen, or Unchanged (b had no freedom along g already, or g = 0,
  /// or b is immovable).
  enum class Lock { Added, Frozen, Unchanged };
  Lock lock(int b, const Vec2& g);
  /// Whether bodies a and b are one body (welded, or the same).
  bool sameBody(int a, int b) const { return slot_[a] == slot_[b]; }
  /// Row k's coefficient on body b: the sum of its entries on b's body (welded bodies share one).
  Vec2 coefficientOn(int k, int b) const;
  /// Row k at the current velocities: G_k v - b_k (negative: its contact closes faster than the
  /// row allows; ConstraintRow::bias), and |G_k|.
  double rowVelocity(int k) const {
    const ConstraintRow& r = row_[k].r;
    double w = 0.0;
    for (int m = 0; m < r.count; ++m) w += r.coef[m].dot(velocity_[r.body[m]]);
    return w - r.bias;
  }
  double rowNorm(int k) const { return row_[k].norm; }
  /// Row k at the velocities its bodies had before the changes since the last takeChanged.
  double rowVelocityAtStart(int k) const {
    const ConstraintRow& r = row_[k].r;
    double w = 0.0;
    for (int m = 0; m < r.count; ++m) {
      const int s = r.body[m];
      w += r.coef[m].dot(changedFlag_[s] ? startVelocity_[s] : velocity_[s]);
    }
    return w - r.bias;
  }
  /// Row k's A_kk = G_k M^-1 G_k^T: the row's velocity change per unit of its impulse.
  double rowDiagonal(int k) const { return row_[k].diag; }
  /// Calls f(id, v0, m) for every movable body whose velocity changed since the last takeChanged:
  /// its id, its velocity before those changes, its mass (a weld's: all its bodies').
  template <class F>
  void forEachChangedBody(F&& f) const {
    for (int s : changed_)
      if (inverseMass_[s] != 0.0 && slot_[body_[s].id] == s) f(body_[s].id, startVelocity_[s], 1.0 / inverseMass_[s]);
  }
  /// Calls f(k) for every row whose multiplier changed since the last takeChanged.
  template <class F>
  void forEachTouchedRow(F&& f) const {
    for (int k : touched_) f(k);
  }
  /// Calls f(id) for body b and every body welded to it.
  template <class F>
  void forEachWelded(int b, F&& f) const {
    const int s = slot_[b];
    f(body_[s].id);
    for (int id : welded_[s]) f(id);
  }
  /// Appends the bodies whose velocity changed since the last call, each once, and starts the
  /// next interval of the energy guard (capEnergy) there.
  void takeChanged(std::vector<int>& out);

  /// The energy guard: keeps the kinetic energy of the bodies whose velocity the rows changed
  /// since the last takeChanged from growing (beyond kEnergyRoundingFraction of it, plus what
  /// moved). A warm start (addRow) is applied before any solve and can add energy that only a
  /// solve takes back; a solve that ends on its budget may not have (dense packs of disks at COR
  /// 0 gained up to 2% in a step). If the changes added energy, every row's multiplier and every
  /// body's velocity go back along the line to where they were, v = v0 + f (v - v0) and
  /// lambda = lambda0 + f (lambda - lambda0), to the largest f in [0, 1) whose kinetic energy is
  /// at most the starting one:
  ///   KE(f) - KE(0) = f B + f^2 C,  B = sum m v0 . dv,  C = sum m |dv|^2 / 2,  dv = v - v0,
  /// so f = -B / C (0 when B >= 0). Velocities and multipliers move together, so the rows'
  /// impulses stay those the velocities carry. Bodies frozen or released since then keep what
  /// freeze or release gave them. Every row moved back is queued (it may close again). Returns
  /// f (1: nothing scaled).
  double capEnergy();
  /// The f capEnergy would move back to, without moving anything (1: no energy gained).
  double energyFraction() const;
  /// Row k's coefficients of restitution from now on (0 when added: inelastic). setRow keeps
  /// them: a row made again for a later instant (RowSource) is the same contact. `hit`: the
  /// coefficient restitute() gives the row first (a contact that hit); `loaded`: the one it takes
  /// in restitute()'s second try, when the hits' restitution alone would add energy (a row that
  /// was apart or opening when it was set, which the solve loaded only because a hit pushed its
  /// bodies into it: the second wall of a wedge).
  void setRestitution(int k, double hit, double loaded = 0.0) {
    restitution_[k] = hit;
    loadedRestitution_[k] = loaded;
  }
  /// Whether row k has a coefficient of restitution, as a hit or when loaded (setRestitution).
  bool restitutes(int k) const { return restitution_[k] > 0.0 || loadedRestitution_[k] > 0.0; }
  /// Moreau's restitution, after a solve: every row k with a coefficient e_k > 0 pushes again by
  /// e_k times the impulse it applied since the last takeChanged, along its normal, outside its
  /// multiplier (later solves cannot take it back as they can an impulse; the multiplier so far
  /// is set aside as setRow sets it) and outside totalImpulse (which warm-starts the contact in
  /// the next step: a resting contact's measure, not a bounce's). With one coefficient e
  /// for all the rows, the velocities become P v + e (P v - v), v the velocities before the solve
  /// and P v its projection; since P v is M-orthogonal to v - P v (complementarity: every row
  /// with an impulse ends with G_k P v = 0), the kinetic energy becomes |Pv|^2 + e^2 |v - Pv|^2
  /// (halved, in the mass norm), at most what it was for e <= 1. With different coefficients per
  /// row (resting rows take 0) that bound does not hold, and a solve that ended on its budget is
  /// not a projection: if the energy guard's measure (capEnergy) would then scale the changes
  /// back, the restitution is taken back exactly and tried again with the loaded rows'
  /// coefficients too (a ball wedged between two walls at COR 1: the hit's wall alone would push
  /// it back at twice its speed, both walls send it back as it came, where the projection alone
  /// stopped it); if that too would add energy, it is taken back and false returned (the rows
  /// stay inelastic for this solve).
  bool restitute();
  /// Takes back every change the rows made since the last takeChanged, as capEnergy does with
  /// f = 0 (velocities and multipliers where they were, the rows queued): for a caller that
  /// changes the problem (a body released) and solves again.
  void rollBack();
  /// Kinetic energy gains up to this fraction of the changed bodies' energy are rounding.
  static constexpr double kEnergyRoundingFraction = 1e-13;
  int rows() const { return static_cast<int>(row_.size()); }
  /// Gauss-Seidel updates the solves have made since the last reset.
  long updates() const { return updates_; }

 private:
  /// A row all of whose entries are one welded body, with coefficients summing to at most this
  /// fraction of their sizes, is its pair's own contact (rounding of n - (1 - alpha) n - alpha n).
  static constexpr double kCancelledFraction = 1e-12;
  /// A second lock whose direction is within this (1 - |cos|) of the first takes nothing more.
  static constexpr double kParallelLock = 1e-12;
  /// Rows a body keeps beside it: a disk in a pile touches up to six others and a wall.
  static constexpr int kInlineRows = 7;
  /// A body's bookkeeping; its velocity and inverse mass, which every update reads, are kept
  /// apart in dense arrays (velocity_, inverseMass_): a pile's velocities then fit the first-level
  /// cache, and an update does not pull its bodies' row lists through it just to read them.
  /// What the hot loop does not read (the bodies welded to it, whether it changed) is kept apart
  /// too (welded_, changedFlag_), so that a body is one aligned cache line: the queue's reads of
  /// a body's rows then touch one line, not two (cachegrind, chains 1,000: 8% fewer first-level
  /// data misses over the run, the same instructions). One line with a 24-byte std::vector; not
  /// asserted, so that a debugging standard library's larger vector still builds.
  struct alignas(64) Body {
    int id = 0;             ///< the body's id; slot_[id] is this slot unless it was welded into another
    int rowCount = 0;       ///< rows it appears in: the first kInlineRows in `rows`, the rest in `moreRows`
    int rows[kInlineRows] = {};  ///< the indices of its first kInlineRows rows
    std::vector<int> moreRows;  ///< the indices of the rest of its rows
    bool hasRow(int k) const;
    void addRow(int k);
    /// Calls f(k) for each of its rows (inline: the worklist's hot loop reads them with the body).
    template <class F>
    void forEachRow(F&& f) const {
      const int stored = rowCount < kInlineRows ? rowCount : kInlineRows;
      for (int q = 0; q < stored; ++q) f(rows[q]);
      for (int k : moreRows) f(k);
    }
  };
  struct Row {
    ConstraintRow r;        ///< bodies as slots into body_
    double diag = 0;        ///< A_kk = G_k M^-1 G_k^T
    double norm = 0;        ///< |G_k|
    double lambda = 0;      ///< its multiplier (impulse) along its current normal, >= 0
    int group = 0;          ///< index into solve's groupScale
    long epoch = 0;         ///< the instant (beginInstant's count) it was set at
  };
  void apply(int k, double lambda);
  /// Row k, about to be updated, is one body's whose rows move no other body (a disk against
  /// walls, fixed particles or sleepers): sets all their multipliers at once to the exact
  /// projection (see the .cpp) and returns true. False, with nothing changed, when the rows are
  /// not so (another body moves in one, the body is locked to an axis, a row waits to be made
  /// again for this instant) or when the projection is degenerate: Gauss-Seidel then goes on.
  bool solveAlone(int k, bool refreshing);
  /// The same for row k's cluster: at most kClusterBodies movable bodies (none locked) whose at
  /// most kClusterRows rows move no other body, projected exactly (see the .cpp); its rows set
  /// at an earlier instant are made again first from `source` (if any). Only for bodies of
  /// masses kClusterMassRatio apart, unless `anyMasses` (a solve about to end on its budget).
  bool solveCluster(int k, RowSource* source, bool anyMasses = false);
  std::vector<int> clusterRows_, clusterStale_,
      clusterSlots_;  ///< solveCluster's scratch: its rows, those to make again, bodies then obstacles
  std::vector<double> clusterMass_, clusterImpulses_;  ///< ... their inverse masses, the rows' multipliers
  std::vector<Vec2> clusterVelocity_;                  ///< ... their velocities
  std::vector<ConstraintRow> clusterLocal_;            ///< ... the rows on local indices
  /// Moves velocities and multipliers back to lambda0 + f (lambda - lambda0) (see capEnergy).
  void moveBack(double f);
  /// Row k's multiplier is about to change: remembers where it started (capEnergy).
  void touch(int k) {
    if (touchedFlag_[k]) return;
    touchedFlag_[k] = 1;
    startLambda_[k] = row_[k].lambda;
    startReplaced_[k] = 0.0;
    touched_.push_back(k);
  }
  /// Body slot s's velocity is about to be set to v by freeze or release: the guard's starting
  /// point moves with it (what those set is theirs, not the rows').
  void setVelocity(int s, const Vec2& v);
  void queue(int k);
  /// Room in work_ for n more queued rows (growRoom: the rare case, slide or grow).
  void makeRoom(size_t n) {
    if (tail_ + n > work_.size()) growRoom(n);
  }
  void growRoom(size_t n);
  double diagonal(const ConstraintRow& r) const;  ///< A_kk of a row whose bodies are slots
  /// Row r (bodies as slots) as the bodies' locks and welds see it: a coefficient on a locked
  /// body keeps only its part along the body's axis, and a row whose bodies are all one welded
  /// body, with coefficients that cancel to rounding, gets exact zeros (it can never close).
  void constrain(ConstraintRow& r) const;
  /// Body slot s's velocity is about to change: the energy guard starts it where it is now (once
  /// per interval, see takeChanged), and it is listed as changed.
  void markChanged(int s) {
    if (changedFlag_[s]) return;
    changedFlag_[s] = 1;
    changed_.push_back(s);
    startVelocity_[s] = velocity_[s];
  }
  void queueRowsOf(int slot, int except);

  std::vector<int> slot_;     ///< per body id: index into body_, -1 when absent
  std::vector<Body> body_;    ///< per slot: the body's bookkeeping (see Body), in the order bodies were added
  /// Per slot: the ids of the bodies welded to it (weld), which share the slot. Apart from body_,
  /// whose row lists every update reads: a Body is then one cache line.
  std::vector<std::vector<int>> welded_;
  std::vector<char> changedFlag_;  ///< per slot: in changed_
  std::vector<Vec2> velocity_;       ///< per slot: the body's velocity
  std::vector<double> inverseMass_;  ///< per slot: 0 for an immovable body
  std::vector<Vec2> axis_;           ///< per slot: the one direction a locked body moves along; 0: free
  std::vector<Row> row_;  ///< per row, indexed as addRow returned them: the row (bodies as slots) and its multiplier
  /// Per row: the multipliers of the normals setRow replaced (still applied). Apart from the rows,
  /// which every Gauss-Seidel update reads: this is read once a step (totalImpulse).
  std::vector<double> replaced_;
  std::vector<char> queued_;  ///< per row: in work_ (apart from the rows: queueing touches only these bytes)
  std::vector<double> restitution_;  ///< per row: its coefficient of restitution as a hit (setRestitution)
  std::vector<double> loadedRestitution_;  ///< per row: its coefficient when loaded by a hit (setRestitution)
  /// What one try of restitute's did: no row had a coefficient and an impulse, the pushes were
  /// kept, or they were taken back (they would have added energy).
  enum class Push { Nothing, Kept, TakenBack };
  /// One try of restitute's with coefficients e(k); `shorten`: pushes that would add energy are
  /// scaled down to where they add none (shortenPushes) before they are taken back whole.
  template <class Coefficient>
  Push pushAgain(const Coefficient& e, bool shorten);
  bool shortenPushes();
  std::vector<std::pair<int, Vec2>> restituted_;  ///< restitute's scratch: slots and their velocities before it
  std::vector<std::pair<int, Vec2>>
      pushedFrom_;            ///< shortenPushes' scratch: each pushed slot once, its velocity before
  std::vector<int> work_;     ///< FIFO of row indices: work_[head_, tail_) (the rest is room)
  size_t head_ = 0, tail_ = 0;  ///< the queue: the first queued row and one past the last, in work_
  std::vector<int> changed_;  ///< body slots changed since the last takeChanged
  /// The energy guard's starting point (capEnergy), since the last takeChanged. Per slot: its
  /// velocity when its rows first changed it (moved by what freeze and release set since).
  std::vector<Vec2> startVelocity_;
  /// Per row: changed since the last takeChanged (listed in touched_), its multiplier then, and
  /// what setRow moved from its multiplier into replaced_ since then.
  std::vector<char> touchedFlag_;
  std::vector<int> revisits_;  ///< per row: Gauss-Seidel updates since the last takeChanged (solveAlone's trigger)
  /// Per row (see touchedFlag_): its multiplier then, and what setRow moved into replaced_ since.
  std::vector<double> startLambda_, startReplaced_;
  std::vector<int> touched_;  ///< rows whose multiplier changed since the last takeChanged, each once
  long updates_ = 0;          ///< see updates()
  long epoch_ = 0;            ///< instants begun (beginInstant); rows carry the one they were set at
};

}  // namespace fosssim::math
