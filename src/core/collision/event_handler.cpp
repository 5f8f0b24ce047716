// EventHandler (event_handler.h): the step's phases in order, the response to one event, and the
// sleepers' part in it. The detection is event_detection.cpp; the check of a finished step,
// piecewise_verify.cpp.
#include "event_handler.h"

#include "impulse_response.h"
#include "pair_query.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fosssim {

EventHandler::EventHandler(const CollisionSettings& settings, int eventsPerParticle, const HandlerOptions& options)
    : cor_(settings.cor),
      eventsPerParticle_(std::max(eventsPerParticle, 0)),
      allPairs_(options.allPairs),
      threads_(std::max(options.threads, 1)) {
  zones_.setRigidOnly(settings.failsafe == Failsafe::Rigid);
  zones_.setSleepers(&sleepers_);
  zones_.setRestitution(settings.cor);
  if (options.zoneUpdatesPerRow > 0) zones_.setUpdatesPerRow(options.zoneUpdatesPerRow);
  zones_.setHold(options.hold);
  sleepers_.setEnabled(options.sleep);
  sleepers_.setThreads(threads_);
}

Status EventHandler::handle(const Scene& scene, const State& start, State& state, StepContext& ctx) {
  const int n = scene.numParticles();
  if (Status s = fixedAtRest(scene, start); !s) return s;
  if (ctx.log->polynomials.enabled()) logReferencePolynomials(scene, start, state, ctx);
  sleepers_.begin(scene, start, state, ctx.dt);  // sleepers back where they rest
  motion_.begin(start.x, state.x, threads_);
  events_.assign(n, 0);
  atInstant_.assign(n, InstantEvents{});
  zones_.reset(n);
  heap_.clear();
  // With every movable particle asleep no pair is queried (none has a particle that moves): a
  // pile at rest then needs neither the broad phase nor the detection.
  if (!sleepers_.allAsleep()) {
    {
      const StepTimer timer(ctx.timing, ctx.stats->broadPhase);
      candidates_.build(scene, motion_.from(), motion_.end(), 0.0, /*updates=*/true, threads_);
      if (allPairs_) candidates_.forceAllPairs();
      if (sleepers_.any()) wakeNearMoving(scene, *ctx.stats);
    }
    // Detect.
    if (Status s = detectAll(scene, ctx); !s) return s;
  }
  // Respond, in time order. Every event is dropped (stale, resolved), costs a particle one of its
  // quota of impulses, adds a contact's rows to a zone (bounded by the candidate pairs), or brings
  // one back (up to ContactZones::bounceLimit of those after solves that bounced, then counted as met
  // again); past kMaxZoneProjections of those a jam welds, locks or stops particles (each jam
  // takes one of those, at most three per particle: ContactZones::lockJammed) or a zone moves
  // rigidly, which also happens at most once per particle (a rigid zone that meets an obstacle
  // goes back to the projection, with a fresh count or that of the zone it merged with, and can
  // then only jam). So the loop ends; the budget below only guards that reasoning.
  const long budget =
      static_cast<long>(eventsPerParticle_ + kMaxZoneProjections + kMaxZoneBouncesCap + 2) * (n + 1) * 4 + 1000;
  long processed = 0;
  changed_.clear();
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const Event e = heap_.back();
    heap_.pop_back();
    if (!stale(scene, e)) {
      if (++processed > budget) return Status::error("contact events do not settle (internal error: budget exceeded)");
      processed += respond(scene, e, state, ctx);  // times itself: response, or failsafe for the zones
    }
    // Contacts that reach the zones at one instant join them before they are solved: a resting
    // pile's contacts all come at t = 0, and solving the zone once per contact cost hundreds of
    // solves a step. The next later event (or none) closes the instant.
    if (!pendingZones_.empty() && !heap_.empty() && heap_.front().t == e.t) continue;
    solvePendingZones(scene, e.t, state, ctx);
    if (Status s = detectChanged(scene, e.t, ctx); !s) return s;
    changed_.clear();
  }
  // Finish: the end of every particle's last piece; rattles keep their speed.
  copyByParticles(motion_.end(), state.x, threads_);
  zones_.giveBackRattles(state.v);
  sleepers_.end(scene, start, state);
  ctx.stats->asleep = sleepers_.sleeping();
  zones_.sizes(*ctx.stats);
  showMidStep(ctx, state);
  return Status::ok();
}

void EventHandler::solvePendingZones(const Scene& scene, double T, State& state, StepContext& ctx) {
  if (pendingZones_.empty()) return;
  const StepTimer timer(ctx.timing, ctx.stats->failsafe);
  // Impulses of this instant changed some motions (changed_), and the zones look for near pairs
  // among the candidates: their boxes must cover the new motions first (detectChanged updates
  // them only after the zones). A stale box of a disk an impulse had set moving hid a pair that
  // its zone should have taken (found where the broad phase's absolute margin covered it: the
  // same pile scaled by 2^-30 then ran differently).
  for (int p : changed_) candidates_.update(p);
  candidates_.settle();
  for (int& z : pendingZones_) z = zones_.zoneOf(z);  // zones absorbed later may have merged them
  std::sort(pendingZones_.begin(), pendingZones_.end());
  pendingZones_.erase(std::unique(pendingZones_.begin(), pendingZones_.end()), pendingZones_.end());
  for (int z : pendingZones_)
    if (zones_.zoneOf(z) == z)  // one solve per zone, even if an earlier solve's growth merged it
      zones_.resolve(scene, motion_, candidates_, z, T, ctx.dt, state.v, changed_, *ctx.stats);
  pendingZones_.clear();
}

bool EventHandler::sleepingPair(const Scene& scene, uint64_t key) const {
  const PairParticles pair = pairParticles(scene, key);
  bool asleep = false;
  for (int k = 0; k < pair.count; ++k) {
    if (sleepers_.asleep(pair.p[k])) asleep = true;
    else if (!scene.isFixed(pair.p[k])) return false;
  }
  return asleep;
}

void EventHandler::wakeIfHit(const Scene& scene, const Event& e, double closing, StepStats& stats) {
  const PairParticles pair = pairParticles(scene, e.key);
  if (!sleepers_.anyAsleep(pair.p, pair.count)) return;
  const double kicksAlong = zones_.kicksAlong(scene, e.key, e.normal, e.alpha);
  if (closing <= sleepers_.wakeSpeed(scene, pair.p, pair.count, kicksAlong)) return;
  for (int k = 0; k < pair.count; ++k)
    stats.woken += sleepers_.wake(pair.p[k]);  // 0 when awake
}

// A sleeper wakes when a particle p that moved in the last step is among its candidates and
// touches it now or could reach it within what p moves in this step. The pairs of a sleeper and
// a mover are found from whichever side is fewer (candidates are symmetric: pairsOf lists a pair
// from each of its particles): in a gas where a few slow particles sleep, from the sleepers; in a
// resting pile where a few disks move, from the movers. Either way the same sleepers wake.
void EventHandler::wakeNearMoving(const Scene& scene, StepStats& stats) {
  const int n = scene.numParticles();
  auto moving = [&](int p) { return !sleepers_.asleep(p) && !scene.isFixed(p) && sleepers_.movedLastStep(p); };
  int movers = 0;
  for (int p = 0; p < n; ++p) movers += moving(p);
  const bool fromSleepers = sleepers_.sleeping() < movers;
  wakeFrom_.clear();
  for (int p = 0; p < n; ++p)
    if (fromSleepers ? sleepers_.asleep(p) : moving(p)) wakeFrom_.push_back(p);
  for (int p : wakeFrom_) {
    // Candidates, not neighbours: small scenes list every pair.
    candidates_.forEachPairOf(p, [&](uint64_t key) {
      const PairParticles pair = pairParticles(scene, key);
      // The largest reach of the pair's movers (-1: none) and whether it holds a sleeper.
      double reach = -1;
      bool sleeper = false;
      for (int k = 0; k < pair.count; ++k) {
        const int q = pair.p[k];
        sleeper = sleeper || sleepers_.asleep(q);
        if (!moving(q)) continue;
        reach = std::max(reach, motion_.rate(q).norm() + kTouchingSlack * scene.radius[q]);
      }
      if (!sleeper || reach < 0) return;
      // A neighbour: touching now, or within what a mover moves in this step.
      const double depth = pairDepth(scene, key, [&](int q) { return motion_.at(q, 0.0); });
      if (depth < -reach) return;
      // ... and whose boxes over the step meet (stepBoxesMeet: boxes inside the broad phase's),
      // so that the sleepers woken are the same with the broad phase and with every pair as
      // candidates. The reach above is a disk's; a mover leaving a sleeper behind stays within
      // it, yet its box never meets the sleeper's.
      if (!stepBoxesMeet(scene, key)) return;
      for (int k = 0; k < pair.count; ++k)
        stats.woken += sleepers_.wake(pair.p[k]);  // 0 when awake
    });
  }
}

// Boxes grown by the radius and kTouchingSlack of it only: scale-free (no absolute margin), and
// inside the broad phase's boxes, whose margins are at least kRelativeMargin (> kTouchingSlack)
// of the radius on top of it (pair_bounds.h).
bool EventHandler::stepBoxesMeet(const Scene& scene, uint64_t key) const {
  const VecX &from = motion_.from(), &end = motion_.end();
  const auto grown = [](double radius) { return radius * (1.0 + kTouchingSlack); };
  const int i = keyParticle(key), other = keyOther(key);
  const Box a = sweptPointBox(from, end, i, grown(scene.radius[i]));
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: return overlap(a, sweptPointBox(from, end, other, grown(scene.radius[other])));
    case PairKind::ParticleEdge:
      return overlap(a, sweptEdgeBox(scene, from, end, other, grown(scene.edges[other].radius)));
    case PairKind::ParticleHalfPlane: return true;  // one particle: never a sleeper with a mover
  }
  return true;
}

bool EventHandler::stale(const Scene& scene, const Event& e) const {
  const PairParticles pair = pairParticles(scene, e.key);
  for (int k = 0; k < pair.count; ++k)
    if (motion_.version(pair.p[k]) != e.version[k]) return true;
  return false;
}

EventHandler::Assessment EventHandler::assess(const Scene& scene, const Event& e, double h, StepStats& stats,
                                              bool wake) {
  Assessment a;
  auto rate = [&](int p) { return motion_.rate(p); };
  double scale = 0;
  a.closing = closingSpeed(scene, e.key, e.normal, e.alpha, rate, scale);
  // A contact that does not close now yet deepens later in the step (an edge rotating under a
  // resting disk: the overlap grows at second order) is one that impulses cannot settle: it goes
  // to the zones, whose projection uses the normals where the overlap would be. One that does not
  // deepen beyond rounding is resolved already.
  const auto deepestTime = [&] {
    return deepeningTime(scene, e.key, [&](int p, double t) { return motion_.at(p, t); }, a.closing, e.t);
  };
  if (a.closing <= kRestingClosingFraction * scale && (a.deepest = deepestTime()) < 0.0) return a;
  const bool curving = a.deepest >= 0.0;
  // closing is a rate (displacement per step); the wake rule compares speeds.
  if (wake && sleepers_.any()) wakeIfHit(scene, e, curving ? 0.0 : a.closing / h, stats);

  // A contact is inside one rigid zone (exempt) only if every particle of it moves with that zone:
  // a half-plane or a fixed particle met by a rigid zone is an obstacle, which joins the zone. A
  // particle of a zone that stopped for the rest of the step is an obstacle too, for particles
  // outside it: they meet it as a fixed particle and do not join (so a disk landing on a pile at
  // rest can still roll off it).
  const PairParticles pair = pairParticles(scene, e.key);
  bool toZones = curving, sameRigidZone = keyKind(e.key) != PairKind::ParticleHalfPlane, sameZone = true;
  int rigidZone = -2, zone = -2;  // -2: none seen yet
  for (int k = 0; k < pair.count; ++k) {
    const int p = pair.p[k];
    const int z = zones_.zoneOf(p);
    sameRigidZone = sameRigidZone && z >= 0 && zones_.isRigid(z) && (rigidZone == -2 || rigidZone == z);
    rigidZone = z;
    if (scene.isFixed(p) || zones_.isImmobile(scene, p)) continue;
    toZones = toZones || z >= 0 || events_[p] >= eventsPerParticle_ ||
              (atInstant_[p].t == e.t && atInstant_[p].count >= kEventsPerInstant);
    sameZone = sameZone && z >= 0 && (zone == -2 || zone == z);
    zone = z;
  }
  if (sameRigidZone) return a;  // rigid to first order inside: exempt
  if (zone == -2) return a;     // nothing of the pair can move
  // Inside one zone that its projection solved, closing speeds within the projection's tolerance
  // of the zone's speeds are what the solve leaves, not new approaches (solving again would
  // change nothing but the count that sends the zone to rigid motion).
  // Unless it deepens later in the step all the same (an edge rotating into a particle: the
  // overlap grows at second order while the normal at T sees almost no approach); the zone then
  // takes its row with the normal where it would overlap deepest, as for a curving contact.
  if (sameZone && !curving && a.closing <= kZoneClosingFraction * zones_.rateScale(zone) &&
      (a.deepest = deepestTime()) < 0.0)
    return a;
  a.route = toZones ? Route::Zones : Route::Impulse;
  return a;
}

long EventHandler::respond(const Scene& scene, const Event& e, State& state, StepContext& ctx) {
  const double h = ctx.dt;
  const Assessment a = assess(scene, e, h, *ctx.stats, /*wake=*/true);
  if (a.route == Route::Zones) {
    const StepTimer timer(ctx.timing, ctx.stats->failsafe);
    const int z = zones_.absorb(scene, motion_, candidates_, e.key, e.t, h, a.deepest);
    if (z >= 0) pendingZones_.push_back(z);
    return 0;
  }
  if (a.route != Route::Impulse) return 0;
  // A hit with other events at its instant answers the instant's other hits with it, as one
  // round (simultaneous_hits.cpp).
  long taken = 0;
  if (!heap_.empty() && heap_.front().t <= e.t + kSimultaneousHits && isHit(scene, e, a, h) &&
      respondTogether(scene, e, state, ctx, taken))
    return taken;
  impulse(scene, e, a.closing, state, ctx);
  return 0;
}

// One impulse against the current velocities (the paths' rates over h). A particle of a zone
// that stopped for the rest of the step is an obstacle, as a fixed particle is.
void EventHandler::impulse(const Scene& scene, const Event& e, double closing, State& state, StepContext& ctx) {
  const double h = ctx.dt;
  const StepTimer timer(ctx.timing, ctx.stats->response);
  const int i = keyParticle(e.key), other = keyOther(e.key);
  const auto v = [&](int p) -> Vec2 { return motion_.rate(p) / h; };
  const auto w = [&](int p) { return zones_.isImmobile(scene, p) ? 0.0 : 1.0 / scene.massOf(p); };
  // Resting contact does not bounce (COR < 1): a contact closing no faster than this step's
  // forces close it is one whose closing speed the step's kick made, and a bounce off it would
  // be undone by the next kick, step after step (a ball on the floor at COR 0.5 bounced h g / 2
  // in every step, forever, and never slept). A contact that hits harder, or that was closing
  // before the step (two disks falling into each other: ContactZones::resting), keeps its COR, and COR 1
  // stays elastic: no energy is lost that the scene asked to keep.
  const double cor = cor_ < 1.0 && zones_.resting(scene, e.key, e.normal, e.alpha, closing / h) ? 0.0 : cor_;
  VelocityChange change;
  switch (keyKind(e.key)) {
    case PairKind::ParticleParticle:
      change = particleParticleImpulse(w, i, other, e.normal, cor, v(i), v(other));
      break;
    case PairKind::ParticleEdge: {
      const Edge& edge = scene.edges[other];
      change = particleEdgeImpulse(w, i, edge, e.alpha, e.normal, cor, v(i), v(edge.i), v(edge.j));
      break;
    }
    case PairKind::ParticleHalfPlane:
      change = particleHalfPlaneImpulse(w(i), i, e.normal, cor, v(i));
      break;
  }
  ++ctx.stats->collisions;
  ctx.log->impulses.push_back(Impulse{keyKind(e.key), i, other, e.normal, e.t});
  for (int k = 0; k < change.count; ++k) applyChange(scene, change.particle[k], change.dv[k], e.t, state, h);
}

void EventHandler::applyChange(const Scene& scene, int p, const Vec2& dv, double T, State& state, double h) {
  InstantEvents& now = atInstant_[p];
  // Its quota counts its first event and those close on its last, in time or in the distance it
  // travelled since (kContinuousEventsPerParticle, kQuotaFreeTravel).
  const double since = now.t < 0.0 ? 0.0 : T - now.t;
  if (now.t < 0.0 || since < 1.0 / eventsPerParticle_ ||
      since * motion_.rate(p).norm() < kQuotaFreeTravel * scene.radius[p])
    ++events_[p];
  at(state.v, p) += dv;
  motion_.setRate(p, T, motion_.rate(p) + h * dv);
  now.count = now.t == T ? now.count + 1 : 1;
  now.t = T;
  changed_.push_back(p);
}

// The trajectory file's polynomial log: every pair's polynomials over the predicted motion, in
// the reference's order and form (what the course's files hold), independent of the events.
void EventHandler::logReferencePolynomials(const Scene& scene, const State& start, const State& state,
                                           StepContext& ctx) {
  logger_.forEachCollision(scene, start.x, state.x, &ctx.log->polynomials, [](const Collision&) {});
}

// The contacts here rely on fixed particles at rest: a jam locks what it welds against them or
// stops it, a held particle waits, each of them at rest or sliding past them. The reference's
// integrators move a fixed particle at the velocity it starts with (x += h v, its force zeroed),
// so a scene can give one a velocity; here it would plough through the disks its contacts
// stopped (a 4 m/s fixed disk pushing two disks into a wall left 14 pairs overlapping in 50
// steps), so the step fails with a message instead. One pass over the flags, as Sleepers::begin
// makes every step.
Status EventHandler::fixedAtRest(const Scene& scene, const State& start) const {
  for (int p = 0; p < scene.numParticles(); ++p) {
    if (!scene.isFixed(p)) continue;
    const Vec2 v = at(start.v, p);
    if (v == Vec2::Zero()) continue;
    std::ostringstream s;
    s << "particle " << p << " is fixed but moves (velocity (" << v.x() << ", " << v.y() << ")): the default mode "
      << "keeps pairs apart only against fixed particles at rest; give it velocity 0, or run with --compat, whose "
      << "fixed particles move at their initial velocity as the course simulator's do";
    return Status::error(s.str());
  }
  return Status::ok();
}

int EventHandler::zoneOf(int particle) const {
  const int z = zones_.zoneOf(particle);
  return z >= 0 && zones_.isRigid(z) ? z : -1;
}

}  // namespace fosssim
