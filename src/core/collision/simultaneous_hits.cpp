// EventHandler's simultaneous hits (event_handler.h): hits of one instant that share particles,
// answered together instead of one after another.
//
// Why. Impulses of one instant answered one at a time, in pair order, make the outcome depend on
// how the particles are numbered. A disk dropped straight onto the gap between two touching disks
// on a floor (COR 0.5) hits both at once; answered in pair order it left sideways at 0.88 m/s from
// a 3.9 m/s fall, the first disk it met at -1.74 m/s and the second at 0.86, and numbering the two
// the other way round mirrored all three. A symmetric scene has to stay symmetric whatever its
// numbering.
//
// How (Moreau's impact law on the hits that act together, the step of Smith, Kaufman, Vouga,
// Tamstorf and Grinspun 2012, "Reflections on simultaneous impact", taken with inequalities).
// With G the hits' rows (n . relative velocity >= 0, contact_zones.h's convention) and M the
// masses, P v is the closest velocity to v in the kinetic-energy norm with G P v >= 0, the
// inelastic projection (math::projectByActiveSet, exact), and the hits leave with
//
//     v+ = v + (1 + e)(P v - v),
//
// e the scene's COR. For one hit this is the single impulse of impulse_response.h. P projects onto
// a convex cone, so (Moreau's decomposition) v - P v is orthogonal to P v in that norm, and
//
//     |v+|^2 = |P v|^2 + e^2 |v - P v|^2 <= |P v|^2 + |v - P v|^2 = |v|^2   (e <= 1):
//
// no energy is gained, and at COR 1 none is lost. The impulses act along the contacts' normals
// through the contact points, so momentum and angular momentum are kept; P is unique, so the
// outcome does not depend on the order of the rows. Contacts that the hits leave closing (the
// floor under the two disks above) are found again at the same instant and answered in the next
// round, together if they are several: a Newton's cradle's touching balls still pass the hit
// along one by one, since only one of its contacts closes at a time.
//
// Only hits are taken together: resting contact (closing at about the step's kick, which does not
// bounce) is answered one contact at a time as before, and the zones settle what that leaves.
// So a resting pile's first instant, with thousands of contacts at t = 0, costs what it did.
#include "event_handler.h"

#include "pair_query.h"

#include "fosssim/math/active_set_projection.h"

#include <algorithm>

namespace fosssim {
namespace {

/// Events of an instant that respondTogether looks at for the hits of its round: the instant's
/// first, by time and pair, after the hit that opens the round. A resting pile's first instant
/// holds thousands of contacts, few of them hits; looking at all of them for every hit would cost
/// their number each time. Hits past these are answered in later rounds of the same instant. (In
/// the benchmark's piles of 1,000, 260 to 600 hits over the run found another event of their
/// instant, and each look took 6 to 8 events.) A symmetric impact of a few bodies has a few.
constexpr size_t kTiedEventsLooked = 64;

}  // namespace

bool EventHandler::isHit(const Scene& scene, const Event& e, const Assessment& a, double h) const {
  return a.route == Route::Impulse && !zones_.resting(scene, e.key, e.normal, e.alpha, a.closing / h);
}

bool EventHandler::respondTogether(const Scene& scene, const Event& e, State& state, StepContext& ctx, long& taken) {
  const double h = ctx.dt;
  StepStats& stats = *ctx.stats;
  tied_.clear();
  tied_.push_back(e);
  while (!heap_.empty() && heap_.front().t <= e.t + kSimultaneousHits && tied_.size() <= kTiedEventsLooked) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    tied_.push_back(heap_.back());
    heap_.pop_back();
  }
  // The round: e and the instant's other hits, in pair order at the front of tied_; the rest go
  // back to the heap, to be answered after the round as they would have been.
  const auto putBack = [&](size_t from) {
    for (size_t k = from; k < tied_.size(); ++k) {
      heap_.push_back(tied_[k]);
      std::push_heap(heap_.begin(), heap_.end(), Later{});
    }
    tied_.resize(from);
  };
  size_t hits = 1;
  for (size_t k = 1; k < tied_.size(); ++k)
    if (!stale(scene, tied_[k]) && isHit(scene, tied_[k], assess(scene, tied_[k], h, stats, false), h))
      std::swap(tied_[hits++], tied_[k]);
  putBack(hits);
  if (hits == 1) return false;
  // The hits wake the sleepers they hit, as respond's do; if one is then no longer a hit (a
  // sleeper woken is no obstacle), e is answered alone and the others in their turn.
  for (const Event& x : tied_) {
    if (isHit(scene, x, assess(scene, x, h, stats, /*wake=*/true), h)) continue;
    putBack(1);
    return false;
  }
  // Groups: hits joined through movable particles, transitively (a fixed particle joins nothing:
  // it does not move). Hits in different groups touch different particles, so answering one
  // group leaves the velocities the others see as they were.
  const int count = static_cast<int>(tied_.size());
  std::vector<int> groupOf(count);
  for (int k = 0; k < count; ++k) groupOf[k] = k;
  const auto sharesMovable = [&](const Event& a, const Event& b) {
    const PairParticles pa = pairParticles(scene, a.key), pb = pairParticles(scene, b.key);
    for (int i = 0; i < pa.count; ++i)
      for (int j = 0; j < pb.count; ++j)
        if (pa.p[i] == pb.p[j] && !scene.isFixed(pa.p[i])) return true;
    return false;
  };
  for (int a = 0; a < count; ++a)
    for (int b = a + 1; b < count; ++b)
      if (groupOf[b] != groupOf[a] && sharesMovable(tied_[a], tied_[b])) {
        const int from = groupOf[b], into = groupOf[a];
        for (int& g : groupOf) g = g == from ? into : g;
      }
  long answered = 0;  // hits answered in this round, e's included
  for (int first = 0; first < count; ++first) {
    if (groupOf[first] != first) continue;  // not a group's first hit
    group_.clear();
    for (int k = first; k < count; ++k)
      if (groupOf[k] == first) group_.push_back(k);
    if (group_.size() == 1 || !respondAsOne(scene, e.t, state, ctx)) {
      // Alone, or a group the exact solve cannot take: its first hit now, the others found
      // again after it (their particles changed) or as they are.
      Event x = tied_[group_[0]];
      x.t = e.t;  // the round's instant (the hits' times differ by rounding at most)
      impulse(scene, x, assess(scene, x, h, stats, false).closing, state, ctx);
      for (size_t k = 1; k < group_.size(); ++k) {
        heap_.push_back(tied_[group_[k]]);
        std::push_heap(heap_.begin(), heap_.end(), Later{});
      }
      answered += 1;
    } else {
      answered += static_cast<long>(group_.size());
    }
  }
  taken = answered - 1;  // e's own is the caller's
  return true;
}

// The group group_ of tied_ by Moreau's law (above), at the round's instant T; false, nothing
// changed, when the exact solve cannot take it (more than its limits, or rows that no velocities
// satisfy).
bool EventHandler::respondAsOne(const Scene& scene, double T, State& state, StepContext& ctx) {
  const double h = ctx.dt;
  bodies_.clear();
  std::vector<math::ConstraintRow> rows;
  for (int k : group_) {
    math::ConstraintRow row = contactRowAlong(scene, tied_[k].key, tied_[k].normal, tied_[k].alpha);
    for (int m = 0; m < row.count; ++m) {  // particle ids to the solve's body slots, added as they come
      const int p = row.body[m];
      const auto at = std::find(bodies_.begin(), bodies_.end(), p);
      row.body[m] = static_cast<int>(at - bodies_.begin());
      if (at == bodies_.end()) bodies_.push_back(p);
    }
    rows.push_back(row);
  }
  std::vector<double> inverseMass, impulses;
  std::vector<Vec2> v;
  for (int p : bodies_) {
    inverseMass.push_back(zones_.isImmobile(scene, p) ? 0.0 : 1.0 / scene.massOf(p));
    v.push_back(motion_.rate(p) / h);
  }
  std::vector<Vec2> projected = v;
  const StepTimer timer(ctx.timing, ctx.stats->response);
  if (!math::projectByActiveSet(inverseMass, rows, projected, math::kProjectionTolerance, impulses)) return false;
  for (size_t k = 0; k < group_.size(); ++k) {
    if (impulses[k] <= 0.0) continue;  // a hit the others' impulses already turned away
    const Event& x = tied_[group_[k]];
    ++ctx.stats->collisions;
    ctx.log->impulses.push_back(Impulse{keyKind(x.key), keyParticle(x.key), keyOther(x.key), x.normal, T});
  }
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const Vec2 dv = (1.0 + cor_) * (projected[b] - v[b]);
    if (inverseMass[b] != 0.0 && dv != Vec2::Zero()) applyChange(scene, bodies_[b], dv, T, state, h);
  }
  return true;
}

}  // namespace fosssim
