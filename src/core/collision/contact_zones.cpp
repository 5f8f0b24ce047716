#include "contact_zones.h"

#include <algorithm>
#include <cassert>

namespace fosssim {
namespace {

// Appends list [first, last] (linked through next) to list [head, tail]; either may be empty (-1).
void splice(int& head, int& tail, int first, int last, std::vector<int>& next) {
  if (first < 0) return;
  if (head < 0) head = first;
  else next[tail] = first;
  tail = last;
}

}  // namespace

void ContactZones::reset(int n) {
  if (static_cast<int>(parent_.size()) != n) {
    parent_.assign(n, -1);
    record_.assign(n, ZoneRecord{});
    nextMember_.assign(n, -1);
    nextHoldable_.assign(n, -1);
    rateScale_.assign(n, 0.0);
    stopped_.assign(n, 0);
    jammed_.assign(n, 0);
    zoneWoken_.assign(n, 0);
  } else {
    for (int r : roots_) forEachMember(r, [&](int p) { parent_[p] = -1, stopped_[p] = 0, jammed_[p] = 0; });
  }
  roots_.clear();
  rattles_.clear();
  for (int p : zoneWokenList_) zoneWoken_[p] = 0;
  zoneWokenList_.clear();
  // The impulses of this step's contacts start the next step's (warm start; addRow): each one's
  // whole impulse. A contact that came back in the step had its row replaced and its multiplier
  // restarted at 0 with the impulse so far still applied; starting the next step from the last
  // multiplier alone (a fraction of the contact's load) left a resting column of 10 disks to a
  // cold solve in every step, which jammed every step.
  lastImpulse_.clear();
  rowOf_.forEach([&](uint64_t key, int row) {
    const double impulse = projector_.totalImpulse(row);
    if (impulse > 0.0) lastImpulse_.insert(key, impulse);
  });
  rowOf_.clear();
  unsolved_.clear();
  waiting_.clear();
  requeried_.clear();
  broughtForward_.clear();
  curving_.clear();
  meets_.clear();
  rowKey_.clear();
  instant_ = -1;
  solvedRows_ = 0;
  projector_.reset(n);
}

int ContactZones::join(int p) {
  if (parent_[p] >= 0) return root(p);
  parent_[p] = p;
  ZoneRecord& zone = record_[p];
  zone = ZoneRecord{};
  zone.size = 1;
  zone.first = zone.last = p;
  nextMember_[p] = -1;
  // Whether p may ever be held in this step (its start speed is the step's; see holdResting).
  if (hold_ && sleepers_ && !(sleepers_->startSpeed(p) > kHeldStartFraction * sleepers_->kick(p))) {
    zone.firstHoldable = zone.lastHoldable = p;
    nextHoldable_[p] = -1;
  }
  rateScale_[p] = 0;
  roots_.push_back(p);
  return p;
}

// Union by size keeps the trees shallow (root() does not compress: it is const).
int ContactZones::unite(int a, int b) {
  a = root(a), b = root(b);
  if (a == b) return a;
  if (record_[a].size < record_[b].size) std::swap(a, b);
  parent_[b] = a;
  ZoneRecord &za = record_[a], &zb = record_[b];
  splice(za.first, za.last, zb.first, zb.last, nextMember_);
  splice(za.firstHoldable, za.lastHoldable, zb.firstHoldable, zb.lastHoldable, nextHoldable_);
  za.size += zb.size;
  zb.first = zb.last = zb.firstHoldable = zb.lastHoldable = -1;  // b is no root: its lists are a's
  za.metAgain = std::max(za.metAgain, zb.metAgain);
  za.bounces = std::max(za.bounces, zb.bounces);
  za.lightest = std::min(za.lightest, zb.lightest);
  za.heaviest = std::max(za.heaviest, zb.heaviest);
  if (zb.firstBounce >= 0.0 && (za.firstBounce < 0.0 || zb.firstBounce < za.firstBounce))
    za.firstBounce = zb.firstBounce;
  za.lastBounce = std::max(za.lastBounce, zb.lastBounce);
  za.stalledBounces = std::max(za.stalledBounces, zb.stalledBounces);
  za.bounced = za.bounced && zb.bounced;
  za.solves = std::max(za.solves, zb.solves);
  za.rigid = za.rigid || zb.rigid;
  za.immovable = za.immovable || zb.immovable;
  za.rowCount += zb.rowCount;
  rateScale_[a] = std::max(rateScale_[a], rateScale_[b]);
  return a;
}

int ContactZones::take(const Scene& scene, const StepMotion& motion, int p, int zone, double h) {
  // An immobile particle (fixed, or in a zone that stopped) is an obstacle: a body of the
  // projection that nothing moves (frozen at rest already if it is in a stopped zone).
  if (isImmobile(scene, p) && (zone < 0 || zoneOf(p) != root(zone))) {
    projector_.addBody(p, 0.0, Vec2::Zero());
    return zone;
  }
  if (parent_[p] < 0) {  // new to the zones: its neighbours are looked at
    queue_.push_back(p);
    // A body already (an obstacle) is a sleeper that a hit woke after a zone met it: with the
    // obstacle's zero velocity it would stay put in every solve while its path moves on.
    if (projector_.hasBody(p)) projector_.release(p, 1.0 / scene.massOf(p), motion.rate(p) / h);
    else projector_.addBody(p, 1.0 / scene.massOf(p), motion.rate(p) / h);
  }
  const bool fresh = parent_[p] < 0;
  const int r = join(p);
  if (fresh) record_[r].lightest = record_[r].heaviest = scene.massOf(p);
  rateScale_[r] = std::max(rateScale_[r], motion.rate(p).norm());
  if (zone < 0) return r;
  // The count of the side that did not move rigidly, if one did (its contacts' record, not the raft's).
  const int a = root(zone), movingCount = record_[a].rigid ? record_[r].metAgain : record_[a].metAgain;
  const int merged = unite(a, r);
  if (record_[merged].rigid && record_[merged].immovable && !rigidOnly_) resumeProjection(scene, merged, movingCount);
  return merged;
}

int ContactZones::absorb(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, uint64_t key,
                         double T, double h, double deepest) {
  h_ = h;
  int zone = -1;
  queue_.clear();
  const PairParticles pair = pairParticles(scene, key);
  for (int k = 0; k < pair.count; ++k) zone = take(scene, motion, pair.p[k], zone, h);
  if (zone < 0) return -1;  // every particle of the pair is fixed
  // A contact whose row a solve has seen and that approaches again is met again: a jam if it
  // repeats. (One whose row is still waiting for its first solve, as contacts of one instant
  // wait for each other, is not; nor one back only because a solve ran out of budget before
  // settling it: that solve counted already.) Its fresh row (normal of now) replaces the old one.
  const int* known = rowOf_.find(key);
  const bool solved = known && *known < solvedRows_;
  int jammed = -1;       // a movable particle of a jammed contact (weldJammed)
  bool welded = false;   // whether that jam welded bodies that were apart
  // Nor one whose row let its pair, apart when the row was set, close the gap (contactRow's
  // bias): that is the meeting the row deferred to, once.
  const bool met = solved && meets_[*known];
  if (met) meets_[*known] = 0;
  if (solved && !requeried_[*known] && !met) {
    ZoneRecord& z = record_[root(zone)];
    // A bounce back at the instant of the one before has not moved the rattle on (a capsule
    // pinned between fixed disks, bouncing from one to the other at one instant, took 600 solves a
    // step): past kMaxStalledBounces of those, it counts as a jam's comeback.
    const bool stalled = z.bounces > 0 && T <= z.lastBounce;
    if (z.bounced && z.bounces < bounceLimit(z) && !(stalled && z.stalledBounces >= kMaxStalledBounces)) {
      if (z.bounces++ == 0) z.firstBounce = T;
      z.lastBounce = T;
      z.stalledBounces += stalled;
    } else {
      ++z.metAgain;
    }
  }
  int rattler = -1;      // a rattle's particle (rattlerOf), whose velocity the jam takes
  Vec2 beforeJam = Vec2::Zero();
  if (solved && record_[root(zone)].metAgain > kMaxZoneProjections && record_[root(zone)].immovable && !rigidOnly_) {
    // A jam against an obstacle: the contact keeps closing although it was solved for again and
    // again. Its particles move as one for the rest of the step, and lose the freedom to close
    // on the obstacles it has (weldJammed, lockJammed); the rest of the zone goes on.
    rattler = rattlerOf(scene, zone, pair);
    if (rattler >= 0) beforeJam = projector_.velocity(rattler);
    jammed = weldJammed(scene, pair, welded);
  }
  setRow(scene, motion, zone, key, T, deepest);
  if (const int* row = rowOf_.find(key); jammed >= 0 && row != nullptr)
    lockJammed(jammed, *row, welded, rateScale_[root(zone)] / h);
  if (rattler >= 0) keepRattle(rattler, beforeJam, zone, T);
  int added = 0;
  return grow(scene, motion, candidates, zone, T, h, added);
}

int ContactZones::grow(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, int zone,
                       double T, double h, int& added) {
  while (!queue_.empty()) {
    const int q = queue_.back();
    queue_.pop_back();
    auto consider = [&](uint64_t k) {
      if (rowOf_.contains(k) || !near(scene, motion, k, T)) return;
      const PairParticles other = pairParticles(scene, k);
      for (int m = 0; m < other.count; ++m) zone = take(scene, motion, other.p[m], zone, h);
      added += setRow(scene, motion, zone, k, T);
    };
    // In pair order (the broad phase lists them in grid order): the rows' order decides the
    // solve's rounding, which must not depend on how candidates were found.
    if (candidates.sortedPairs()) {
      candidates.forEachPairOf(q, consider);
      continue;
    }
    keys_.clear();
    candidates.pairsOf(q, keys_);  // each once
    std::sort(keys_.begin(), keys_.end());
    for (uint64_t k : keys_) consider(k);
  }
  return root(zone);
}

// Solve, apply, and look again from every particle the solve moved, with its new velocity:
// pairs that are near now join (with their particles) and the zone is solved again, until it
// stops growing (Harmon et al.'s merge-and-project loop, at one instant) or moves rigidly.
void ContactZones::resolve(const Scene& scene, StepMotion& motion, PairCandidates& candidates, int zone, double T,
                           double h, VecX& v, std::vector<int>& changed, StepStats& stats) {
  h_ = h;
  atInstant(T);
  RowsAt rowsNow(*this, scene, motion, T);
  for (;;) {
    zone = root(zone);
    ZoneRecord& z = record_[zone];  // until growth below merges it
    if (!z.rigid && !rigidOnly_ && (z.immovable || z.metAgain <= kMaxZoneProjections)) {
      ++stats.failsafeRounds;
      // A solve that runs out of its budget leaves safe velocities (no energy gained) that may
      // still let some contact close: that contact comes back as an event, counted as met again.
      // A zone's first solve in the step may sweep all its rows (warm-started, a resting pile
      // needs few); later solves pay for what they add, or for what waits in the queue (its rows
      // set aside by another zone's solve at this instant that spent its budget). Its own rows,
      // not the shared projector's: budgeted on every zone's rows of the step so far, a small
      // zone that did not settle spent a budget sized for all of them (pile-rest 10^5, steps
      // 700-800: 19 first solves a step ended on budgets of some 20 updates for each of the
      // ~56,000 rows then in the projector, and first solves made 23.6 million updates a step).
      if (!waiting_.empty()) requeueWaiting(zone);
      const int fresh =
          z.solves++ == 0 ? z.rowCount : std::max(projector_.rows() - solvedRows_, projector_.queuedRows());
      const bool jammed = z.metAgain > kMaxZoneProjections;
      const long divisor = jammed                   ? kJammedBudgetDivisor
                           : z.solves == 1 && hold_ ? kFirstSolveBudgetDivisor
                           : z.immovable && hold_   ? 1L << std::min(z.metAgain, kRepeatBudgetHalvings)
                                                    : 1;
      const long perRow = std::max(updatesPerRow_ / divisor, 1L);
      const long budget = perRow * std::max(fresh, 8);
      solvedRows_ = projector_.rows();
      // Each row settles to its own zone's tolerance (its group: the zone's root when the row
      // was set), whichever zone's solve runs the shared worklist. Under the solving zone's
      // tolerance, a slower zone's contact could pass as settled with its closing left above its
      // own zone's tolerance; that zone's solve would then find nothing queued, and the contact
      // was never queried again (an edge rotating into a chain's disk deepened 5e-9 unseen:
      // chains 2,500, --verify). A root merged into another since keeps the smaller scale it had
      // (scales only grow within a step), so its rows are held, if anything, tighter.
      const long before = projector_.updates();
      const bool solved = projector_.solve(rateScale_.data(), 1.0 / h, kZoneProjectionTolerance, budget, &rowsNow);
      stats.zoneUpdates += projector_.updates() - before;
      // A solve that stopped the zone against a sleeper it hits is taken back, and the zone is
      // solved again with the sleeper woken as a member (wakeHitSleepers).
      if (wakeHitSleepers(scene, zone, stats)) {
        projector_.rollBack();
        queue_.clear();
        for (int p : hitSleepers_) zone = take(scene, motion, p, zone, h);
        int added = 0;
        zone = grow(scene, motion, candidates, zone, T, h, added);
        continue;
      }
      // No energy from the zones: the warm starts applied since the last solve (and the rows'
      // changes to other zones' bodies waiting at this instant) are taken back as far as this
      // solve did not (ContactProjector::capEnergy). What that leaves closing comes back as
      // events: every body it scaled is in the changed list below, and every row it scaled is
      // queued.
      // The hits among the rows bounce (Moreau's restitution on the solve's impulses), unless
      // that would add energy.
      z.bounced = cor_ > 0.0 && projector_.restitute();
      const bool capped = projector_.capEnergy() < 1.0;
      stats.energyCaps += capped;
      // The rows set since the last solve stand for contacts whose events were taken: one that
      // the solve did not settle, or whose settling the cap took back, would not be queried
      // again where its bodies' velocities end unchanged, and its pair would close unseen for the
      // rest of the step. So this zone's are queried again at T: such a contact comes back as an
      // event, marked as back for this solve (not counted as met again).
      const auto queryAgain = [&](uint64_t key) {
        const PairParticles pair = pairParticles(scene, key);
        for (int k = 0; k < pair.count; ++k)
          if (!scene.isFixed(pair.p[k])) changed.push_back(pair.p[k]);
      };
      const auto requery = [&](uint64_t key) {
        queryAgain(key);
        requeried_[*rowOf_.find(key)] = 1;
      };
      if (!solved || capped) {
        // Counted once, as met again: the contacts it leaves closing come back marked as back
        // for this solve, so nothing else counts them. A cap too: the guard may take a solve
        // back whole, and uncounted, its contacts came back to be solved and capped again at one
        // instant without end (a pile of masses 10^11 apart, until the event budget's internal
        // error: ContactPhysicsRandom.ZoneSolvesTakenBackWholeStillEndTheStep).
        if (!solved && z.immovable) holdResting(scene, zone);
        ++z.metAgain;
        // A failure is its zone's alone (and so is a cap). This zone's rows still queued are
        // dropped; those of other zones waiting for their solves at this instant are set aside
        // for those solves (the worklist is shared: dropping them too sent their contacts back as
        // events counted against zones whose solves had not failed, and the fed rain pile then
        // had zones moving rigidly in up to twice as many steps; leaving them queued let this
        // zone's next solves spend their budgets on them).
        projector_.unqueueIf(memberOf(zone));
        projector_.takeQueued(waiting_);
        takeUnsolved(scene, zone, requery);  // a failure: metAgain counted it once
      } else {
        // A curving contact's row has its normal where the overlap would be deepest, and there
        // the overlap's rate is 0: the row can hold with nothing changed while the pair still
        // overlaps (dense packs with short edges ended 1e-7 deep). Such a contact is queried
        // again at T, and coming back it counts as met again: one that no row settles ends in a
        // jam, whose stop leaves it apart.
        const auto again = [&](uint64_t key) {
          if (curving_[*rowOf_.find(key)]) queryAgain(key);
        };
        if (waiting_.empty()) {  // every row settled, whichever zone's
          for (uint64_t key : unsolved_) again(key);
          unsolved_.clear();
        } else {
          takeUnsolved(scene, zone, again);  // this zone's settled; the rows set aside wait
        }
      }
    } else {
      z.rigid = 1;
      // Rigid motion projects the zone's velocities, warm starts included: what those added
      // (here, or to other zones' bodies waiting at this instant, which the transfer below
      // carries too) is taken back first.
      stats.energyCaps += projector_.capEnergy() < 1.0;
    }
    if (z.rigid) moveRigidly(scene, motion, zone, T);
    moved_.clear();
    projector_.takeChanged(moved_);
    queue_.clear();
    for (int p : moved_) {
      if (scene.isFixed(p)) continue;
      const Vec2 velocity = projector_.velocity(p), rate = h * velocity;
      if (rate == motion.rate(p)) continue;
      const double change = (rate - motion.rate(p)).norm();
      at(v, p) += velocity - motion.rate(p) / h;
      motion.setRate(p, T, rate);
      candidates.update(p);  // its box must cover the new motion before neighbours are sought
      changed.push_back(p);
      // Only a real change of motion can bring new pairs near; the tails of Gauss-Seidel
      // ripple through a whole pile and would make every solve re-examine all of it.
      if (change > kRegrowFraction * rateScale_[root(p)]) queue_.push_back(p);
      const int r = root(p);
      rateScale_[r] = std::max(rateScale_[r], rate.norm());
    }
    candidates.settle();
    int added = 0;
    zone = grow(scene, motion, candidates, zone, T, h, added);
    // Growing may have merged a zone whose rows wait set aside (a pair can join without a row of
    // its own, at coincident centres): they are this zone's now, and only its solve settles them.
    if (added == 0 && (record_[zone].rigid || !waitingFor(zone))) return;
  }
}

bool ContactZones::solvesNow(uint64_t key) {
  const int* row = rowOf_.find(key);
  if (row == nullptr || !requeried_[*row] || broughtForward_[*row]) return false;
  broughtForward_[*row] = 1;
  return true;
}

// Whether rows set aside wait for zone `zone`'s solve.
bool ContactZones::waitingFor(int zone) const {
  for (int k : waiting_)
    if (projector_.moves(k, memberOf(zone))) return true;
  return false;
}

// Queues again the rows set aside for zone `zone` (those of zones that rigid motion or a jam
// froze are dropped: no solve can move their bodies).
void ContactZones::requeueWaiting(int zone) {
  size_t kept = 0;
  for (int k : waiting_) {
    if (projector_.moves(k, memberOf(zone)))
      projector_.queueRow(k);
    else if (projector_.moves(k, [](int) { return true; }))
      waiting_[kept++] = k;
  }
  waiting_.resize(kept);
}

void ContactZones::sizes(StepStats& stats) const {
  for (int r : roots_) {
    if (parent_[r] != r) continue;
    ++stats.zones;
    stats.rigidZones += record_[r].rigid;
    stats.zoneParticles += record_[r].size;
    forEachMember(r, [&](int p) {
      stats.jammedParticles += jammed_[p];
      stats.heldParticles += stopped_[p] == kHeld;
    });
    stats.largestZone = std::max(stats.largestZone, record_[r].size);
  }
  stats.failsafeUsed = stats.failsafeUsed || stats.zones > 0;
}

}  // namespace fosssim
