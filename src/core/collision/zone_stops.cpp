// The failsafe's answers beyond the projection (contact_zones.h): sleepers that a zone hits
// woken; and its last resorts short of rigid motion: particles held at rest after a budget-ended
// solve, and jammed contacts, whose particles are welded into one body and locked against their
// obstacles, or stopped at rest.
#include "contact_zones.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace fosssim {
namespace {

// Appends p alone to the list [head, tail] linked through next.
void append(int& head, int& tail, int p, std::vector<int>& next) {
  next[p] = -1;
  if (head < 0) head = p;
  else next[tail] = p;
  tail = p;
}

}  // namespace

// A sleeper is an obstacle to the zones, as a fixed particle is, so a zone that ran into one
// stopped against it. A row of ten sleeping disks on a floor, hit end-on at COR 0 by a disk of
// 1,000 kg at 30 m/s, took all of its momentum and left seven disks asleep: the events woke the
// first few, then the contacts went to the zones (kEventsPerInstant), whose solve met the next
// sleeper as a wall. An event wakes the sleepers it hits harder than resting contact does
// (Sleepers::wakeSpeed); a zone wakes them when two things hold:
//   * a row against a sleeper stopped more than that: the velocity its impulse gave the row's
//     movable particles, A_kk lambda, beyond what the impulse the contact carried in the last
//     step gives them (its warm start: a resting load), and the push is a hit's, not a load's:
//     the contact closed that fast before the solve, or one of its particles is a sleeper a
//     zone woke in this step (through which the hit travels on). A new contact under a load
//     carries many kicks without closing (the poured pile-low-cor0.5 at 10^4 with the impulse
//     test alone: 17% awake after 1,000 steps instead of 2%, its last block 3.5 -> 12.7 ms);
//   * the zone is moving, not resting: the bodies the solve changed had more kinetic energy
//     before it than kWakeKickFactor kicks each (plus the sleep speed) would give them. A
//     resting pile's zone has its kicks and little more, and the weight of a particle that a
//     moving neighbour woke, resting on a sleeper, is many kicks (pile-rest 2,500 with the
//     first test alone: the pile woke itself, 1.5 -> 4.7 ms/step, 53% -> 99.5% of its steps in
//     the failsafe).
// The solve is then taken back (resolve), and the zone is solved again with the sleepers woken as
// members, so a hit travels through a sleeping row as far as its impulses do.
bool ContactZones::wakeHitSleepers(const Scene& scene, int zone, StepStats& stats) {
  hitSleepers_.clear();
  if (!sleepers_ || !sleepers_->any()) return false;
  // The awake movable side's kicks along a row (its coefficients: the normal, weighted at an
  // edge's ends), each body once (a weld's coefficient is its particles' together). A held or
  // stopped member counts: what the row stopped was its motion.
  const auto moves = [&](int q) { return !scene.isFixed(q) && !sleepers_->asleep(q) && projector_.hasBody(q); };
  const auto kicksAlong = [&](int row, const PairParticles& pair) {
    double kicks = 0;
    for (int k = 0; k < pair.count; ++k) {
      const int p = pair.p[k];
      bool counted = !moves(p);
      for (int j = 0; j < k && !counted; ++j) counted = moves(pair.p[j]) && projector_.sameBody(p, pair.p[j]);
      if (!counted) kicks += std::fabs(sleepers_->kickVector(p).dot(projector_.coefficientOn(row, p)));
    }
    return kicks;
  };
  projector_.forEachTouchedRow([&](int row) {
    const uint64_t key = rowKey_[row];
    const PairParticles pair = pairParticles(scene, key);
    if (!sleepers_->anyAsleep(pair.p, pair.count)) return;
    bool ours = false;
    for (int k = 0; k < pair.count; ++k) ours = ours || zoneOf(pair.p[k]) == zone;
    if (!ours) return;
    const double wakeSpeed = sleepers_->wakeSpeed(scene, pair.p, pair.count, kicksAlong(row, pair));
    const double* last = lastImpulse_.find(key);
    // A_kk with the particles' own masses: a member the solve has since held or stopped is
    // immovable in the projector, yet what the row stopped was its motion.
    double diagonal = 0;
    for (int k = 0; k < pair.count; ++k)
      if (!isImmobile(scene, pair.p[k]) || stopped_[pair.p[k]])
        diagonal += projector_.coefficientOn(row, pair.p[k]).squaredNorm() / scene.massOf(pair.p[k]);
    const double pushed = (projector_.totalImpulse(row) - (last ? *last : 0.0)) * diagonal;
    if (!(pushed > wakeSpeed)) return;
    // ... and the push is a hit's: the contact was closing that fast before the solve, or a
    // particle of it was woken by a zone in this step (the hit travelling on through it: a
    // woken sleeper starts at rest, and only the solve moves it into the next).
    bool carried = -projector_.rowVelocityAtStart(row) > wakeSpeed;
    for (int k = 0; k < pair.count && !carried; ++k) carried = zoneWoken_[pair.p[k]] != 0;
    if (!carried) return;
    for (int k = 0; k < pair.count; ++k)
      if (sleepers_->asleep(pair.p[k])) hitSleepers_.push_back(pair.p[k]);
  });
  if (hitSleepers_.empty()) return false;
  // Twice the kinetic energies of the bodies' own motion (their velocities before the solve less
  // this step's kicks: what they brought into the step) and of rest. A resting body brings what
  // its contacts left it of the last kick, up to about a kick. Measured on the whole velocity
  // against kWakeKickFactor kicks, a disk sliding along a floor slower than 2 g h (the kick across
  // its contact) counted as resting, and the sleeper it hit was a wall.
  double moving = 0, resting = 0;
  projector_.forEachChangedBody([&](int p, const Vec2& v0, double m) {
    const double restingSpeed = (kWakeKickFactor - 1.0) * sleepers_->kick(p) + sleepers_->sleepSpeed(scene, p);
    moving += m * (v0 - sleepers_->kickVector(p)).squaredNorm();
    resting += m * restingSpeed * restingSpeed;
  });
  if (!(moving > resting)) {
    hitSleepers_.clear();
    return false;
  }
  for (int p : hitSleepers_) {
    stats.woken += sleepers_->wake(p);  // 0 when woken already
    if (!zoneWoken_[p]) zoneWoken_[p] = 1, zoneWokenList_.push_back(p);
  }
  return true;
}

// The members of a zone against an obstacle that its budget-ended solve has brought to rest stop
// for the rest of the step (kHeldKickFraction, kHeldStartFraction). Only the members that started
// the step slow enough are looked at (the zone's holdable list, in the order of its members;
// empty with holding off or without sleepers), and those that stop leave the list for good: a
// fed pile's zone ends a hundred solves a step on its budget, and scanning all its members each
// time took 5% of rain's time at 10^4.
void ContactZones::holdResting([[maybe_unused]] const Scene& scene, int zone) {
  ZoneRecord& z = record_[zone];
  int first = -1, last = -1;  // the list of those that stay holdable, relinked in order
  for (int p = z.firstHoldable, next; p >= 0; p = next) {
    next = nextHoldable_[p];
    // Stopped (held or jammed) for the rest of the step. Of isImmobile's other cases none can
    // hold for a member here: take() makes fixed and sleeping particles obstacles, not members,
    // and the zone solves by projection, so it is not rigid. (isImmobile's union-find walk took
    // two fifths of this scan: holdResting fell from 5.8% to 3.4% of rain 10^5's profile.)
    if (stopped_[p]) continue;
    assert(!isImmobile(scene, p));
    if (projector_.velocity(p).norm() > kHeldKickFraction * sleepers_->kick(p)) {
      append(first, last, p, nextHoldable_);
      continue;
    }
    projector_.forEachWelded(p, [&](int q) { stopped_[q] = kHeld; });
    projector_.freeze(p, Vec2::Zero());
  }
  z.firstHoldable = first;
  z.lastHoldable = last;
}

// Why weld, not stop: a jam used to stop its particles at rest, obstacles for the rest of the
// step. That took their tangential motion with it: a pile landing on a frictionless floor while
// sliding along it at 1 m/s (tests/core/jam_momentum_test.cpp) lost 61-68% of its momentum in the
// step it landed, and the stopped particles were held at rest in the steps after. Stopped at a
// common moving velocity instead, they were obstacles of infinite mass moving into their
// neighbours: the same pile's energy grew 30-fold. Welded, they keep their momentum, their
// contact closes no more, and what they meet is met by their mass: nothing is pushed by an
// obstacle that does not give way. Returns a movable particle of the weld, or -1 (none: every
// particle of the contact is an obstacle already).
int ContactZones::weldJammed(const Scene& scene, const PairParticles& pair, bool& welded) {
  welded = false;
  if (stopsAtRest(scene, pair)) {
    for (int k = 0; k < pair.count; ++k)
      if (!isImmobile(scene, pair.p[k])) stopJammed(pair.p[k]);
    return -1;
  }
  int first = -1;
  for (int k = 0; k < pair.count; ++k) {
    const int p = pair.p[k];
    if (isImmobile(scene, p)) continue;
    if (first < 0) {
      first = p;
    } else if (projector_.movable(first)) {
      welded = welded || !projector_.sameBody(p, first);
      projector_.weld(p, first);
    } else {  // the weld so far was locked in two directions: it is at rest, and p stops with it
      stopJammed(p);
    }
  }
  if (first >= 0) settleJam(first);
  return first;
}

// Stopped at rest, a jam's particles leave the problem, which welded they do not (rain at 2,500
// took 1.35-1.38 times as long as with every jam stopped, and 1.93 times with a rest rule on the
// weld's speed: kJamRestKicks). What stopping takes is their motion. Along their kick (the
// velocity this step's forces gave them: gravity's, down) that is what their supports would take
// (a disk landing on a pile); across it, it is what nothing else would (a pile sliding along a
// floor). So they stop when their common velocity, the weld's, moves across the kick by at most
// kJamRestKicks kicks: the speed a jam takes from motion across the forces is then bounded as a
// held particle's is, and vanishes with the step. Without forces (no kick) only particles at
// rest stop.
bool ContactZones::stopsAtRest(const Scene& scene, const PairParticles& pair) const {
  Vec2 momentum = Vec2::Zero(), kick = Vec2::Zero();
  double mass = 0.0;
  for (int k = 0; k < pair.count; ++k) {
    const int p = pair.p[k];
    if (isImmobile(scene, p)) continue;
    const double m = scene.massOf(p);
    momentum += m * projector_.velocity(p);
    if (sleepers_) kick += m * sleepers_->kickVector(p);
    mass += m;
  }
  if (mass == 0.0) return false;
  const Vec2 mean = momentum / mass;
  kick /= mass;
  const double kickSquared = kick.squaredNorm();
  const Vec2 across = kickSquared > 0.0 ? Vec2(mean - (mean.dot(kick) / kickSquared) * kick) : mean;
  return across.norm() <= kJamRestKicks * std::sqrt(kickSquared);
}

// The weld's coefficient in the jammed contact's row (of now) is what it has against the contact's
// obstacles, which are at rest (a half-plane, a fixed or sleeping particle, a stopped one): the
// weld loses its freedom along it, so that contact cannot close again either (between two movable
// particles the coefficients cancel and nothing is locked). Every jam whose contact still closes
// takes something: bodies welded, a freedom locked, or, when neither was left to take, the weld's
// motion: it stops at rest. (Events of one instant come before its zones' solve, so a contact
// can come back as a jam after an earlier jam of the instant has settled it: nothing is taken
// then.) So jams end: there are at most three that take something per movable particle and step
// (EventHandler::handle's bound).
void ContactZones::lockJammed(int p, int row, bool welded, double speedScale) {
  if (!projector_.movable(p)) return;
  const auto lock = projector_.lock(p, projector_.coefficientOn(row, p));
  const bool closes = projector_.rowVelocity(row) < -kZoneProjectionTolerance * speedScale * projector_.rowNorm(row);
  if (!welded && lock == math::ContactProjector::Lock::Unchanged && closes) stopJammed(p);
  else settleJam(p);
}

void ContactZones::stopJammed(int p) {
  projector_.freeze(p, Vec2::Zero());
  settleJam(p);  // p and the particles welded to it stop
}

// Every particle of the weld counts as jammed; a weld left without freedom (locked in two
// directions) is frozen at rest, and its particles are obstacles for the rest of the step.
void ContactZones::settleJam(int p) {
  const bool frozen = !projector_.movable(p);
  projector_.forEachWelded(p, [&](int q) {
    jammed_[q] = 1;
    if (frozen) stopped_[q] = kJam;
  });
}

// A small zone's rattles (kSmallZoneMembers), then Galperin's count (kBouncesPerGalperinCount): a
// zone of alike masses keeps kMaxZoneBounces.
static_assert(kSmallZoneMembers <= math::ContactProjector::kClusterBodies,
              "a small zone's bounces are cheap only where its cluster is solved exactly");
int ContactZones::bounceLimit(const ZoneRecord& z) {
  if (z.size >= 2 && z.size <= kSmallZoneMembers) return kMaxZoneBouncesCap;
  if (!(z.lightest > 0.0) || !(z.heaviest > z.lightest)) return kMaxZoneBounces;
  const double galperin = 3.14159265358979323846 * std::sqrt(z.heaviest / z.lightest);
  const double limit = kBouncesPerGalperinCount * galperin;  // NaN-free: both masses positive
  if (!(limit < kMaxZoneBouncesCap)) return kMaxZoneBouncesCap;
  return std::max(kMaxZoneBounces, static_cast<int>(std::ceil(limit)));
}

// A rattle: a ball between two walls a hair wider than it bounces u h / gap times in a step (200
// at 20 m/s across a gap of 1 mm, dt 0.01), past the zone's bounces, and jams; its lock took its
// speed across the walls for good (at COR 1, four fifths of its kinetic energy there). The
// time-ordered events cannot follow it (their count has no bound as the gap shrinks), but its
// outcome is plain: it goes on rattling, its mean motion across the walls nil, which is what the
// lock gives its path for the rest of the step. So its velocity at the step's end gets back what
// the jams took, reversed (away from the wall it last closed on), times what the bounces of the
// rest of the step leave of it. Those follow from the rattle so far: between parallel walls each
// bounce multiplies the speed across by e and the time to the next by 1 / e, so from an interval
// d the bounces in the time R left take e^n with d (e^-n - 1) / (1 / e - 1) = R, that is
//     e^n = 1 / (1 + (R / d) (1 / e - 1)),
// and with the jam's own bounce the share given back is e^(n + 1); at COR 1 it is 1, exactly.
// d is the zone's mean interval since its first bounce of the step: the last one is longer when
// e < 1, so n comes out high and the share low, on the side of losing energy. Only a zone with
// one movable particle qualifies (its obstacles take what its momentum changes), and never above
// the speed it had before its first jam: the lock leaves it its motion along the walls, so with
// one jam |v_end|^2 + share^2 |taken|^2 is at most that speed squared; with two (a second lock
// stops it) the cap decides.
int ContactZones::rattlerOf(const Scene& scene, int zone, const PairParticles& pair) const {
  const ZoneRecord& z = record_[root(zone)];
  if (!(cor_ > 0.0) || z.bounces < bounceLimit(z) || z.size != 1) return -1;
  for (int k = 0; k < pair.count; ++k)
    if (!isImmobile(scene, pair.p[k])) return pair.p[k];
  return -1;
}

void ContactZones::keepRattle(int p, const Vec2& before, int zone, double T) {
  const Vec2 taken = before - projector_.velocity(p);
  if (taken == Vec2::Zero()) return;
  for (Rattle& r : rattles_)
    if (r.p == p) {
      r.taken += taken;
      return;
    }
  const ZoneRecord& z = record_[root(zone)];
  double share = cor_;
  if (cor_ < 1.0) {
    const double elapsed = T - z.firstBounce, bounces = z.bounces + z.metAgain;
    share = elapsed > 0.0 ? cor_ / (1.0 + (1.0 - T) * bounces / elapsed * (1.0 / cor_ - 1.0)) : 0.0;
  }
  rattles_.push_back(Rattle{p, taken, before.squaredNorm(), share});
}

void ContactZones::giveBackRattles(VecX& v) const {
  for (const Rattle& r : rattles_) {
    const Vec2 now = at(v, r.p), back = -r.share * r.taken;
    // The largest s in [0, 1] with |now + s back|^2 <= speedSquared: a s^2 + 2 b s + c <= 0.
    const double a = back.squaredNorm(), b = now.dot(back), c = now.squaredNorm() - r.speedSquared;
    double s = 1.0;
    if (a + 2.0 * b + c > 0.0) s = c > 0.0 ? 0.0 : std::min(1.0, (-b + std::sqrt(std::max(0.0, b * b - a * c))) / a);
    at(v, r.p) = now + s * back;
  }
}

}  // namespace fosssim
