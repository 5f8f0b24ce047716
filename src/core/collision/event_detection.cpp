// EventHandler's detection (event_handler.h): the step's first detection over every candidate
// pair, in row ranges on the handler's threads, and the detection again of the pairs of the
// particles an impulse or a zone's solve changed, over the rest of the step. Each contact found
// is an event; the heap orders them by time, then pair, whatever order they were found in.
#include "event_handler.h"

#include "collision_search.h"
#include "pair_query.h"
#include "parallel_rows.h"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace fosssim {
namespace {

std::string pairName(uint64_t key) {
  std::ostringstream s;
  const char* other = keyKind(key) == PairKind::ParticleParticle ? "particle"
                      : keyKind(key) == PairKind::ParticleEdge   ? "edge"
                                                                 : "half-plane";
  s << pairKindName(keyKind(key)) << " pair (particle " << keyParticle(key) << ", " << other << " " << keyOther(key)
    << ")";
  return s.str();
}

}  // namespace

// Rows are collected in blocks of candidates and then queried: two clock reads per block, not per
// particle (with timing on, per-row timers cost more than the sparse scenes' narrow phase). With
// threads, each range's broad and narrow times share out the wall time (joinRangeStats).
//
// In a scene mostly asleep (without edges), rows are read from the particles that move: a
// sleeper's pairs are queried only with movers (sleepingPair), so its row is skipped, and a
// mover's row lists its sleeping neighbours below it as well. Every pair that is queried is
// still queried once, and events leave the heap by time and pair, so the result is the same; a
// resting pile then no longer reads the grid for every particle in every step.
//
// When the last step's event loop read many particles' pair lists (PairCandidates::
// keepsAllNext: a pile's zones grow from thousands of particles a step), the rows' keys, read
// anyway, make all of this step's lists at once (keepAll) instead of a grid search and a sort
// per list later: rain 10^4 7.9-8.0 -> 7.7 ms/step, 10^5 53.5 -> 49.3, identical results.
Status EventHandler::detectAll(const Scene& scene, StepContext& ctx) {
  const int n = scene.numParticles();
  const bool fromMovers = !candidates_.allPairs() && scene.edges.empty() && 2L * sleepers_.sleeping() > n;
  // Every row read: its keys, ascending across the ranges, also make the broad phase's kept lists.
  const bool keepAll = !fromMovers && candidates_.keepsAllNext();
  const int ranges = rowRangesFor(n, threads_);
  if (workers_.size() < static_cast<size_t>(ranges)) workers_.resize(ranges);
  const auto start = std::chrono::steady_clock::now();
  forRowRanges(n, threads_, [&](int range, int first, int end) {
    Worker& w = workers_[range];
    w.events.clear();
    w.stats.clear();
    w.status = Status::ok();
    w.keys.clear();
    for (int i = first; i < end && w.status;) {
      if (!keepAll) w.keys.clear();
      const size_t from = w.keys.size();
      {
        const StepTimer timer(ctx.timing, w.stats.broadPhase);
        for (; i < end && w.keys.size() - from < CollisionSearch::kKeysPerBlock; ++i) {
          if (fromMovers && sleepers_.asleep(i)) continue;
          candidates_.forEachInRow(i, w.row,
                                   [&](PairKind kind, int other) { w.keys.push_back(pairKey(i, kind, other)); });
          if (!fromMovers || scene.isFixed(i)) continue;
          w.row.clear();
          candidates_.particlesBefore(i, w.row);
          for (int k : w.row)
            if (sleepers_.asleep(k)) w.keys.push_back(pairKey(k, PairKind::ParticleParticle, i));
        }
      }
      const StepTimer timer(ctx.timing, w.stats.narrowPhase);
      for (size_t k = from; k < w.keys.size(); ++k)
        if (w.status = query(scene, w.keys[k], 0.0, w.stats, w.events); !w.status) break;
    }
  });
  for (int k = 0; k < ranges; ++k) {
    if (!workers_[k].status) return workers_[k].status;  // the first range's failure: the first in pair order
    pushEvents(workers_[k].events);
  }
  joinRangeStats(ranges, [&](int k) -> const StepStats& { return workers_[k].stats; }, start, ctx.timing, *ctx.stats);
  if (keepAll) {
    const StepTimer timer(ctx.timing, ctx.stats->broadPhase);
    candidates_.keepAll([&](auto&& visit) {
      for (int k = 0; k < ranges; ++k)
        for (uint64_t key : workers_[k].keys) visit(key);
    });
  }
  return Status::ok();
}

// The heap's pop order depends only on its contents (events are ordered by time, then pair),
// not on the order they were pushed in.
void EventHandler::pushEvents(std::vector<Event>& events) {
  for (const Event& e : events) {
    heap_.push_back(e);
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }
  events.clear();
}

Status EventHandler::detectChanged(const Scene& scene, double T, StepContext& ctx) {
  if (changed_.empty()) return Status::ok();
  {
    const StepTimer timer(ctx.timing, ctx.stats->broadPhase);
    for (int p : changed_) candidates_.update(p);
    candidates_.settle();
    // Each pair once, from the lowest of its changed particles: candidates are symmetric (every
    // particle of a pair lists it), so a pair of two changed particles is listed from both. A
    // zone's solve changes thousands of particles: sorting their keys to drop the repeats took
    // an eighth of a settling pile's time. The order of the queries does not matter: events
    // leave the heap by time, then pair.
    if (inChanged_.size() != static_cast<size_t>(scene.numParticles())) inChanged_.assign(scene.numParticles(), 0);
    for (int p : changed_) inChanged_[p] = 1;
    keys_.clear();
    for (int p : changed_) {
      if (inChanged_[p] != 1) continue;  // listed already
      inChanged_[p] = 2;
      candidates_.forEachPairOf(p, [&](uint64_t key) {
        if (listsFrom(scene, key, p)) keys_.push_back(key);
      });
    }
    for (int p : changed_) inChanged_[p] = 0;
  }
  const StepTimer timer(ctx.timing, ctx.stats->narrowPhase);
  found_.clear();
  for (uint64_t key : keys_)
    if (Status s = query(scene, key, T, *ctx.stats, found_); !s) return s;
  // A contact that a zone's budget-ended solve left closing joins the zone at this instant,
  // not at its own time (ContactZones::solvesNow). It stays queued at its own time too: at this
  // instant it may be neither touching nor closing (an edge rotating toward a particle it meets
  // later in the step), and then nothing here constrains it; if the zone's solve changes its
  // particles, that copy is stale and dropped.
  const size_t found = found_.size();
  for (size_t k = 0; k < found; ++k)
    if (found_[k].t > T && zones_.solvesNow(found_[k].key)) {
      found_.push_back(found_[k]);
      found_.back().t = T;
    }
  pushEvents(found_);
  return Status::ok();
}

// The pair over [T, 1]: every particle is on its last piece there (events come in time order).
Status EventHandler::query(const Scene& scene, uint64_t key, double T, StepStats& stats,
                           std::vector<Event>& out) const {
  if (sleepers_.any() && sleepingPair(scene, key)) return Status::ok();
  ++stats.candidatePairs;
  ++stats.queries[static_cast<int>(keyKind(key))];
  const double left = 1.0 - T;
  if (left <= 0.0) return Status::ok();
  math::ExactContact contact;
  const math::CcdOutcome outcome = queryPair(scene, key, [&](int p, Vec2& x, Vec2& d) {
    x = motion_.at(p, T);
    d = left * motion_.rate(p);
  }, contact);
  if (outcome == math::CcdOutcome::Miss) return Status::ok();
  if (outcome == math::CcdOutcome::Overflow)
    return Status::error("the " + pairName(key) + " cannot be tested for contact: its coordinates or motion are too "
                         "large to represent (overflow); check the scene's positions and velocities");
  Event e;
  e.t = std::min(T + contact.tau * left, 1.0);
  e.key = key;
  e.normal = contact.normal;
  e.alpha = contact.alpha;
  const PairParticles pair = pairParticles(scene, key);
  for (int k = 0; k < pair.count; ++k) e.version[k] = motion_.version(pair.p[k]);
  out.push_back(e);
  return Status::ok();
}

bool EventHandler::listsFrom(const Scene& scene, uint64_t key, int p) const {
  const PairParticles pair = pairParticles(scene, key);
  for (int k = 0; k < pair.count; ++k)
    if (pair.p[k] < p && inChanged_[pair.p[k]] != 0) return false;
  return true;
}

}  // namespace fosssim
