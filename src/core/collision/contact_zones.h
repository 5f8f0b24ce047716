// Internal header: the default mode's failsafe, impact zones resolved at an instant of the step.
//
// When impulses cannot settle a cluster of contacts (a particle took its quota of impulse
// events in this step: a resting pile, a ball wedged in a corner; or a contact that deepens
// without closing), its particles join a zone at the current event time T, together with every
// particle that could touch one of them before the step ends (transitively). Each contact of a
// zone is a row n·(relative velocity) >= 0, and the zone's velocities become the closest ones,
// in the kinetic-energy norm, that satisfy every row (Harmon, Vouga, Tamstorf and Grinspun 2008):
// contacts stop closing, tangential motion is kept, kinetic energy can only fall. A pair still
// apart (by more than the step's kicks close) may close its gap by the step's end and no faster,
// n·(relative velocity) >= -gap / (time left): it is not stopped before it meets (contactRow).
// Later contacts of a zone's particles in the same step add rows (and particles) and the zone is
// solved again at their time. All zones of a step share one math::ContactProjector, whose
// worklist makes a solve cost what the new rows disturb, not the size of the zone (a disk landing
// on a pile of thousands).
//
// Last resort, when a contact keeps closing although its zone was solved for it again and again
// (more than kMaxZoneProjections times in a step: Gauss-Seidel stalls on a pile jammed against a
// wall, or creeps on a raft of disks): if the zone touches an obstacle (a fixed or sleeping
// particle, a half-plane), the particles of that contact move as one body for the rest of the
// step (welded: one velocity, their momentum's) and that body loses its freedom to close on the
// contact's obstacles (locked: it slides along a floor, and a second lock in another direction
// stops it as an obstacle), while the rest of the zone goes on; a zone touching nothing moves rigidly
// instead, with its centre-of-mass velocity and the angular velocity of its momentum (the
// M-orthogonal projection onto rigid motions, so no energy is gained and momentum is kept). A
// rigid zone that meets an obstacle later in the step (a contact with a half-plane or an immobile
// particle, or a merge with a zone touching one) goes back to the projection with the velocities
// it has, and its count of contacts met again starts over (a merged zone keeps the other side's):
// no zone stops whole. Stopping it whole, as the reference does, threw away motion no obstacle
// takes (a raft sliding along a frictionless floor), and froze the fed rain pile for the rest of
// the step whenever a raft landed on it. failsafe="rigid" makes every zone rigid at once, and a
// rigid zone touching an obstacle stops (the reference's rule). Contacts inside a rigid zone are
// exempt.
//
// Before that, particles held at rest: when the solve of a zone against an obstacle ends on its
// budget, the members that started the step at rest and that the solve has already brought back
// to rest stop for the rest of the step, as obstacles, and the rest of the zone goes on. "At rest"
// is measured against the kick, the velocity this step's forces gave the particle (Sleepers::
// kick): a particle resting on a pile gains a kick every step and its contacts take it back. On
// a jammed pile that is the answer Gauss-Seidel was creeping towards, reached without the
// thousands of sweeps a jammed pile needs (docs/performance-history.md). What it costs the
// physics: a held particle loses at most a kick of speed (g h under gravity, which vanishes with
// the step like the integrator's own error), and only if it was slower than a quarter of a kick
// to begin with, so nothing that flows or slides is held; without forces (kick 0) only a particle
// exactly at rest is.
#pragma once

#include "pair_candidates.h"
#include "pair_key_map.h"
#include "sleepers.h"
#include "step_motion.h"
#include "zone_tuning.h"

#include "fosssim/core/scene.h"
#include "fosssim/core/step_stats.h"
#include "fosssim/math/contact_projector.h"

#include <vector>

namespace fosssim {

/// The row of pair `key`, n . (relative velocity) >= 0, along unit normal n (from the particle
/// toward the other object; alpha: an edge's parameter), over the pair's particle ids
/// (zone_rows.cpp has its forms). The zones' rows and the simultaneous hits' rounds.
math::ConstraintRow contactRowAlong(const Scene& scene, uint64_t key, const Vec2& n, double alpha);

class ContactZones {
 public:
  /// No zones; storage for n particles.
  void reset(int n);

  /// Puts pair `key` (met at time T) and every particle that could touch its particles in the
  /// rest of the step (transitively) into one zone, with a row per contact; returns the zone, or
  /// -1 when every particle of the pair is fixed. h: the step. deepest (if >= 0): the caller
  /// found that the contact, barely closing at T, overlaps deepest at that step fraction (an edge
  /// rotating into a particle), so its row takes the normal there.
  int absorb(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, uint64_t key, double T,
             double h, double deepest = -1.0);

  /// Solves zone `zone` at time T, growing it while its new velocities bring more pairs near:
  /// writes its particles' new rates into `motion` (and the broad phase's boxes), their velocity
  /// changes into v (2N), and appends the particles whose rate changed to `changed`.
  void resolve(const Scene& scene, StepMotion& motion, PairCandidates& candidates, int zone, double T, double h,
               VecX& v, std::vector<int>& changed, StepStats& stats);

  /// The zone of particle p, or -1.
  int zoneOf(int p) const { return parent_.empty() || parent_[p] < 0 ? -1 : root(p); }
  bool isRigid(int zone) const { return record_[root(zone)].rigid != 0; }
  /// Whether particle p cannot move for the rest of the step: fixed, or in a rigid zone that
  /// stopped (it holds a fixed particle or touches a half-plane). Particles outside its zone meet
  /// it as an obstacle.
  bool isImmobile(const Scene& scene, int p) const {
    if (scene.isFixed(p) || (!stopped_.empty() && stopped_[p]) || (sleepers_ && sleepers_->asleep(p))) return true;
    const int z = zoneOf(p);
    return z >= 0 && record_[z].rigid && record_[z].immovable;
  }
  /// The largest rate (displacement per step) among the zone's particles: the scale of what
  /// its projection leaves closing.
  double rateScale(int zone) const { return rateScale_[root(zone)]; }
  /// Adds the zones (count, particles, largest, rigid ones) to the statistics.
  void sizes(StepStats& stats) const;
  void setRigidOnly(bool rigid) { rigidOnly_ = rigid; }
  /// The solves' budget per added row (kZoneUpdatesPerRow unless a test or measurement says).
  void setUpdatesPerRow(long updates) { updatesPerRow_ = updates; }
  /// Whether budget-ended solves hold the particles they brought to rest (on unless a test says).
  void setHold(bool hold) { hold_ = hold; }
  /// The handler's sleepers: obstacles, as fixed particles are, until a zone hits one
  /// (wakeHitSleepers).
  void setSleepers(Sleepers* sleepers) { sleepers_ = sleepers; }
  /// The scene's coefficient of restitution: a contact that reaches a zone closing faster than
  /// resting contact does (kRestingBounceKicks) bounces off with it after each solve
  /// (ContactProjector::restitute), unless that would add energy. 0 (the default): the zones are
  /// inelastic, Harmon et al.'s projection.
  void setRestitution(double cor) { cor_ = cor; }
  /// The step's kicks along normal n of pair `key` (alpha: an edge's parameter): each movable
  /// side's |kick . n|, summed (an obstacle's is 0). A kick across the normal (gravity, for disks
  /// side by side on a floor) does not close the contact, and the sides' kicks are not
  /// differenced, since a disk resting on another closes at its own kick once the floor has
  /// stopped the lower.
  double kicksAlong(const Scene& scene, uint64_t key, const Vec2& n, double alpha) const;
  /// Whether pair `key`, closing along n at `closing` (a speed), is resting contact, which does
  /// not bounce (kRestingBounceKicks, kRestingGainedShare).
  bool resting(const Scene& scene, uint64_t key, const Vec2& n, double alpha, double closing) const;

  /// Gives back to each rattle's particle (see rattlerOf) what its jams took from its velocity,
  /// reversed and times the share the rest of the step's bounces leave of it (keepRattle), in v
  /// (2N) at the end of the step: a ball rattling between walls keeps its speed across them,
  /// never above its speed before its first jam.
  void giveBackRattles(VecX& v) const;

  /// Whether the contact of pair `key`, found closing at a later time of the step, is to be
  /// solved at the current instant too (its event also stays at its own time, for a contact that
  /// is not closing yet at this instant); true at most once per contact and step. So it is
  /// for a contact that a budget-ended solve left closing (requeried, see requeried_): its row is
  /// in the zone already, the zone constrains it at its instant as it does every near pair, and
  /// the contacts one failed solve leaves then come back as one instant and one solve, not one
  /// solve each at its own time (on the fed rain pile, about six contacts per failure, 150
  /// failures a step at N = 10^4). Once: a second failure's contacts wait for their own times, so
  /// the loop of fail, requery and solve again at one instant ends.
  bool solvesNow(uint64_t key);

 private:
  int root(int p) const {
    while (parent_[p] != p) p = parent_[p];
    return p;
  }
  int join(int p);          ///< adds movable particle p to the zones (alone), returns its root
  int unite(int a, int b);  ///< merges two zones, returns the new root
  /// Movable p joins `zone` (or starts one); fixed p only enters the projector. Returns the zone.
  int take(const Scene& scene, const StepMotion& motion, int p, int zone, double h);
  /// Breadth-first from the particles in queue_: every pair that is near gets its rows, and its
  /// particles join the zone. Returns the zone; `added` counts the new rows.
  int grow(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, int zone, double T,
           double h, int& added);
  /// The contact's row (added, or replaced if it has one) with its normal at T, or where it
  /// would overlap deepest if it deepens without closing (at `deepest` if the caller found that
  /// already, >= 0); returns whether a row was added.
  bool setRow(const Scene& scene, const StepMotion& motion, int zone, uint64_t key, double T, double deepest = -1.0);
  /// The row of `key` with its particles at position(p), and its normal (zero: none).
  /// (contactRowAlong's with that normal.) With timeLeft > 0 (seconds: the rest of the step), a
  /// pair apart by more than kTouchingSlack of its radius sum and more than the step's kicks close
  /// (kicksAlong over the step) may close its gap in that time and no faster (ConstraintRow::bias):
  /// a zone's row for a neighbour it has not met yet must not stop the pair before it meets (four
  /// disks pushed through a zone went on as one with the last 2 cm apart, for ever).
  template <class Position>
  math::ConstraintRow contactRow(const Scene& scene, uint64_t key, Position&& position, Vec2& normal,
                                 double timeLeft = 0.0) const;
  bool near(const Scene& scene, const StepMotion& motion, uint64_t key, double T) const;
  /// Rows set from here on are of instant T (the projector's beginInstant when T is new).
  void atInstant(double T) {
    if (T == instant_) return;
    instant_ = T;
    projector_.beginInstant();
  }
  /// The projector's source of rows made again at instant T (ContactProjector::RowSource): a
  /// contact's row with its particles where they are at T; a curving row keeps its normal.
  class RowsAt final : public math::ContactProjector::RowSource {
   public:
    RowsAt(const ContactZones& zones, const Scene& scene, const StepMotion& motion, double T)
        : zones_(zones), scene_(scene), motion_(motion), T_(T) {}
    bool rowNow(int index, math::ConstraintRow& out) override;
    /// Only a cluster moving faster than kRescueKicks of its bodies' kicks (see there).
    bool mayRescue(const int* ids, int count) override;

   private:
    const ContactZones& zones_;  ///< the zones whose rows it makes again
    const Scene& scene_;         ///< the step's scene
    const StepMotion& motion_;   ///< the step's motion, which places the particles at T_
    double T_;                   ///< the instant, as a fraction of the step
  };
  /// The predicate "particle p is in zone `zone`" (a root), for the projector's row filters.
  auto memberOf(int zone) const {
    return [this, zone](int p) { return zoneOf(p) == zone; };
  }
  void requeueWaiting(int zone);
  bool waitingFor(int zone) const;
  /// Removes zone `zone`'s pairs from unsolved_, calling take(key) for each.
  template <class Take>
  void takeUnsolved(const Scene& scene, int zone, Take&& take) {
    size_t kept = 0;
    for (uint64_t key : unsolved_) {
      const PairParticles pair = pairParticles(scene, key);
      bool ours = false;
      for (int k = 0; k < pair.count; ++k) ours = ours || memberOf(zone)(pair.p[k]);
      if (ours) take(key);
      else unsolved_[kept++] = key;
    }
    unsolved_.resize(kept);
  }
  void moveRigidly(const Scene& scene, const StepMotion& motion, int zone, double T);
  /// Zone `zone` (a root) moved rigidly and has met an obstacle: its members go back to the
  /// projection with their rigid velocities.
  void resumeProjection(const Scene& scene, int zone, int metAgain);
  /// Wakes the sleepers that zone `zone`'s last solve pushed harder than resting contact does,
  /// listed in hitSleepers_; returns whether any woke (resolve then solves again).
  bool wakeHitSleepers(const Scene& scene, int zone, StepStats& stats);
  /// Stops the members of zone `zone` (a root) held at rest (see the top of this file).
  void holdResting(const Scene& scene, int zone);
  /// A jammed contact: welds its movable particles into one body of the projector (returns one of
  /// them, -1 if none; `welded`: whether bodies apart were welded), then locks that body against
  /// the contact's obstacles (its row `row`), or stops it if the jam took nothing else.
  int weldJammed(const Scene& scene, const PairParticles& pair, bool& welded);
  void lockJammed(int p, int row, bool welded, double speedScale);
  /// The one movable particle of a zone that jams after spending its bounces (kMaxZoneBounces,
  /// a COR above 0) alone against obstacles: a rattle, not a pile. -1 for any other jam.
  int rattlerOf(const Scene& scene, int zone, const PairParticles& pair) const;
  /// Records what a rattle's jam at instant T took from particle p's velocity (`before`: its
  /// velocity then), and what share of it the rest of the step leaves.
  void keepRattle(int p, const Vec2& before, int zone, double T);
  /// Whether a jammed contact's particles stop at rest instead (kJamRestKicks).
  bool stopsAtRest(const Scene& scene, const PairParticles& pair) const;
  /// Marks the particles welded to p jammed, and stopped if the weld has no freedom left.
  void settleJam(int p);
  /// Stops p, and every particle welded to it, at rest for the rest of the step (a jam).
  void stopJammed(int p);

  static constexpr char kJam = 1, kHeld = 2;  ///< why a particle stopped (stopped_)
  bool rigidOnly_ = false;                    ///< every zone moves rigidly at once (failsafe="rigid"; setRigidOnly)
  /// The solves' budget in Gauss-Seidel updates per added row (setUpdatesPerRow).
  long updatesPerRow_ = kZoneUpdatesPerRow;
  bool hold_ = true;              ///< budget-ended solves hold the particles they brought to rest (setHold)
  Sleepers* sleepers_ = nullptr;  ///< the handler's sleepers, or null (setSleepers)
  double cor_ = 0.0;  ///< see setRestitution
  double h_ = 0.0;    ///< the step (absorb and resolve set it: kicks are speeds, rates are per step)
  std::vector<int> hitSleepers_;  ///< wakeHitSleepers' obstacles to wake (scratch)
  std::vector<char> zoneWoken_;   ///< N: woken by a zone in this step (wakeHitSleepers)
  std::vector<int> zoneWokenList_;  ///< those particles, to clear zoneWoken_ at reset
  std::vector<int> parent_;  ///< N: union-find parent, -1 when in no zone
  /// What is known of one zone, kept at its root: a particle that joins writes this record and
  /// its own links, not a dozen arrays (and no list of its own on the heap: with one vector of
  /// members per particle, reading a joining particle's one-element list was a cache miss, and
  /// merging lists took 4% of rain's time at N = 10^4, perf). Members and holdable members are
  /// lists linked through nextMember_ and nextHoldable_, in the order they joined: a merge
  /// splices the smaller zone's lists after the larger's.
  struct ZoneRecord {
    int metAgain = 0;  ///< contacts back after a solve, failed solves (jam count)
    int bounces = 0;   ///< contacts back after a solve that bounced (not jams: bounceLimit)
    double lightest = 0, heaviest = 0;  ///< its movable members' extreme masses (bounceLimit)
    double firstBounce = -1.0;  ///< the instant (fraction of the step) of the first of those; -1: none
    double lastBounce = -1.0;   ///< ... and of the last; -1: none
    int stalledBounces = 0;     ///< those back at the instant of the bounce before (kMaxStalledBounces)
    int solves = 0;    ///< solves in this step
    int rowCount = 0;  ///< the projector rows set for its contacts in this step
    int size = 0;      ///< members
    int first = -1, last = -1;  ///< its members (nextMember_), -1: none
    /// Its members that may still be held (started the step slower than kHeldStartFraction
    /// kicks and not stopped yet), in the order of its members (nextHoldable_).
    int firstHoldable = -1, lastHoldable = -1;
    int lastFrozen = -1;  ///< its members up to this one are frozen at rest (immovable and rigid); -1: none
    char rigid = 0;       ///< moving rigidly for the rest of the step
    char immovable = 0;   ///< a fixed particle or a half-plane among its rows
    char bounced = 0;     ///< its last solve's restitution was kept (ContactProjector::restitute)
  };
  /// The bounces zone record z may take in a step (kMaxZoneBounces, kBouncesPerGalperinCount).
  static int bounceLimit(const ZoneRecord& z);
  /// Calls f(p) for every member of zone `zone` (a root), in the order they joined.
  template <class F>
  void forEachMember(int zone, F&& f) const {
    for (int p = record_[zone].first; p >= 0; p = nextMember_[p]) f(p);
  }
  std::vector<ZoneRecord> record_;  ///< per root
  std::vector<int> nextMember_;     ///< N: the member after p in its zone, -1 last
  std::vector<int> nextHoldable_;   ///< N: the holdable member after p in its zone, -1 last
  std::vector<double> rateScale_;   ///< per root: see rateScale() (an array: the projector reads it by group)
  std::vector<char> stopped_;       ///< N: stopped for the rest of the step: kJam, kHeld or 0
  std::vector<char> jammed_;        ///< N: welded or locked by a jam in this step (statistics)
  std::vector<int> roots_;          ///< every particle that has been a root this step
  /// A rattle's particle (rattlerOf), what its jams took from its velocity in this step (summed),
  /// and its squared speed before the first.
  struct Rattle {
    int p = -1;
    Vec2 taken = Vec2::Zero();
    double speedSquared = 0.0;
    double share = 1.0;  ///< of `taken`, given back reversed (keepRattle)
  };
  std::vector<Rattle> rattles_;     ///< this step's (few: a rattle is one particle's)
  PairKeyMap<int> rowOf_;           ///< the projector's row of each pair with one this step
  PairKeyMap<double> lastImpulse_;  ///< each contact's positive impulse at the end of the last step
  std::vector<uint64_t> unsolved_;  ///< pairs whose rows were set since the last solve (any zone's)
  /// Projector rows of zones waiting for their solves at this instant, set aside (out of the
  /// queue) when another zone's solve spent its budget; requeueWaiting queues a zone's again.
  std::vector<int> waiting_;
  /// Per projector row: its contact was queried again because a solve spent its budget before
  /// settling it. Coming back as an event then shows the budget, not a jam (the failed solve was
  /// counted once, in metAgain), so it is not counted again; it comes back at the failure's
  /// instant if it closes within the step (solvesNow). Cleared when the row is set again.
  std::vector<char> requeried_;
  std::vector<char> broughtForward_;  ///< per projector row: solvesNow said yes in this step
  /// Per projector row: its normal is where its contact would overlap deepest (a contact that
  /// deepens without closing: an edge rotating into a particle). See resolve.
  std::vector<char> curving_;
  /// Per projector row: set with a gap to close (a bias), and its pair has not met yet: its first
  /// event is that meeting, not a comeback (absorb does not count it toward a jam).
  std::vector<char> meets_;
  std::vector<uint64_t> rowKey_;  ///< per projector row: its pair
  double instant_ = -1;           ///< the instant rows are set at now (atInstant); -1: none yet this step
  std::vector<int> queue_;                 ///< grow()'s worklist: particles whose near pairs are still to be looked at
  std::vector<uint64_t> keys_;             ///< grow()'s scratch: one particle's candidate pairs, sorted
  std::vector<int> moved_;                 ///< resolve()'s scratch: the particles whose velocity the solve changed
  math::ContactProjector projector_;       ///< every zone's rows and velocities of this step
  int solvedRows_ = 0;                     ///< rows in the projector at its last solve
};

}  // namespace fosssim
