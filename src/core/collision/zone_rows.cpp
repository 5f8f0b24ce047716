// ContactZones' rows: which pairs are near enough to join a zone, and the constraint row of each
// contact (contact_zones.h). Geometry only: no solve, no zone bookkeeping beyond what a row sets.
#include "contact_zones.h"

#include "pair_query.h"

#include "fosssim/math/geometry.h"

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

Vec2 unit(const Vec2& a) {
  const double n = a.norm();
  return n > 0.0 ? Vec2(a / n) : Vec2(Vec2::Zero());
}

}  // namespace

// Could the pair touch before the step ends? Its distance at T against the radius sum plus what
// the pair can close in the rest of the step, and the boxes of its remaining motions (grown by
// the radii) must meet. The box test keeps zones from depending on the broad phase: its boxes
// contain these, so every pair found near here is among its candidates.
bool ContactZones::near(const Scene& scene, const StepMotion& motion, uint64_t key, double T) const {
  const int i = keyParticle(key), other = keyOther(key);
  const Vec2 x = motion.at(i, T);
  const double left = 1.0 - T;
  auto box = [&](int p, double grow) {
    const Vec2 a = motion.at(p, T), b = motion.end().segment<2>(2 * p);
    return Box{std::min(a.x(), b.x()) - grow, std::min(a.y(), b.y()) - grow, std::max(a.x(), b.x()) + grow,
               std::max(a.y(), b.y()) + grow};
  };
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: {
      const double rs = (scene.radius[i] + scene.radius[other]) * (1.0 + kTouchingSlack);
      const double reach = rs + std::min(left * (motion.rate(other) - motion.rate(i)).norm(), kZoneReach * rs);
      return overlap(box(i, rs), box(other, 0.0)) && (motion.at(other, T) - x).squaredNorm() <= reach * reach;
    }
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      const double rs = (scene.radius[i] + e.radius) * (1.0 + kTouchingSlack);
      const double reach =
          rs +
          std::min(left * (motion.rate(i).norm() + motion.rate(e.i).norm() + motion.rate(e.j).norm()), kZoneReach * rs);
      const Box a = box(e.i, 0.0), b = box(e.j, 0.0);
      const Box edge{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
      return overlap(box(i, rs), edge) &&
             math::segmentContactVector(x, motion.at(e.i, T), motion.at(e.j, T)).squaredNorm() <= reach * reach;
    }
    case PairKind::ParticleHalfPlane: {
      // The signed distance is linear in time: its extremes over [T, 1] are at the two ends.
      const HalfPlane& h = scene.halfplanes[other];
      const Vec2 n = unit(h.normal);
      const double r = scene.radius[i] * (1.0 + kTouchingSlack);
      const double s0 = (x - h.point).dot(n),
                   s1 = s0 + std::clamp(left * motion.rate(i).dot(n), -kZoneReach * r, kZoneReach * r);
      return std::min(s0, s1) <= r && std::max(s0, s1) >= -r;
    }
  }
  return false;
}

bool ContactZones::setRow(const Scene& scene, const StepMotion& motion, int zone, uint64_t key, double T,
                          double deepest) {
  atInstant(T);
  const int z = root(zone);
  const PairParticles pair = pairParticles(scene, key);
  ZoneRecord& record = record_[z];
  record.immovable = record.immovable || keyKind(key) == PairKind::ParticleHalfPlane;
  for (int k = 0; k < pair.count; ++k)
    record.immovable = record.immovable || (isImmobile(scene, pair.p[k]) && zoneOf(pair.p[k]) != z);
  if (record.rigid && record.immovable && !rigidOnly_) resumeProjection(scene, z, 0);  // never stopped whole
  Vec2 n = Vec2::Zero();
  math::ConstraintRow row = contactRow(scene, key, [&](int p) { return motion.at(p, T); }, n, (1.0 - T) * h_);
  // A contact that does not close at T but deepens later in the step (an edge rotating under a
  // resting disk) takes the normal where it would overlap deepest: only that normal sees the
  // approach. (One row per contact: two nearly parallel rows would stall Gauss-Seidel.)
  double scale = 0, alpha = 0;
  if (keyKind(key) == PairKind::ParticleEdge) {
    const Edge& e = scene.edges[keyOther(key)];
    alpha = math::segmentParameterClamped(motion.at(keyParticle(key), T), motion.at(e.i, T), motion.at(e.j, T));
  }
  const auto rate = [&](int p) { return motion.rate(p); };
  bool curving = deepest >= 0.0;
  double closing = 0.0;  // a rate (per step), along the normal of T (when not curving)
  if (curving) {  // the caller found it deepening already
    row = contactRow(scene, key, [&](int p) { return motion.at(p, deepest); }, n);
  } else if (closing = closingSpeed(scene, key, n, alpha, rate, scale); closing <= kRestingClosingFraction * scale) {
    const double td = deepeningTime(scene, key, [&](int p, double t) { return motion.at(p, t); }, closing, T);
    curving = td >= 0.0;
    if (curving) row = contactRow(scene, key, [&](int p) { return motion.at(p, td); }, n);
  }
  if (n == Vec2::Zero()) return false;  // coincident centres: no direction to keep apart along
  // A hit restitutes (ContactProjector::restitute) as an impulse event would: the zones keep the
  // scene's COR, not only the projection's inelastic answer (a COR 1 ball wedged between two
  // walls stopped dead). Resting contact does not bounce (kRestingBounceKicks, as for events),
  // and a curving row's normal is not the one it closes along now.
  // A row that is not closing at all (apart, or opening: the second wall of a wedge) takes a
  // COR below 1 only if a hit loads it and the hit's restitution alone would add energy
  // (ContactProjector::restitute). At COR 1 every row restitutes: Moreau's pushes with e = 1 on
  // all of an exact projection's impulses keep the energy (KE(v + 2 dv) - KE(v) = 2 lambda.G(v +
  // dv) = 0 by complementarity), while a loaded row left inelastic loses what it took (a light
  // disk pushed by a hit into a wall it was not closing on: a tenth of a fast box's energy).
  double restitution = 0.0, loaded = 0.0;
  if (cor_ > 0.0 && !curving) {
    if (closing <= 0.0 && cor_ < 1.0) loaded = cor_;
    else if (cor_ >= 1.0 || !resting(scene, key, n, alpha, closing / h_)) restitution = cor_;
  }
  // Only an inelastic row waits for its pair to meet (contactRow's bias). A row that bounces
  // bounces at once, as Moreau's law has it: deferred to the step's end, the closing beyond the
  // gap's rate would be taken inelastically (kinetic energy lost at COR 1: 2 lambda |bias|).
  const bool speculative = !curving && restitution == 0.0 && loaded == 0.0;
  if (!speculative) row.bias = 0.0;
  if (const int* known = rowOf_.find(key)) {
    // A row no solve has seen yet was set at this instant (contacts of one instant wait for one
    // solve together): it stands. Replacing it would make its warm start, already applied, a
    // push that the solve could no longer take back, and that can add energy.
    if (*known >= solvedRows_) return false;
    projector_.setRow(*known, row, z);
    projector_.setRestitution(*known, restitution, loaded);
    requeried_[*known] = 0;
    curving_[*known] = curving;
    unsolved_.push_back(key);
    return false;
  }
  // No warm start inside a rigid zone: its members are frozen in the projector (immovable, at
  // their rigid velocities), so the impulse would act on the pair's other particle alone, which
  // the next rigid move then carries into the zone's momentum (free packs lost up to 15% of
  // their momentum so: ZoneAngularMomentum). Contacts inside a rigid zone are exempt anyway.
  // Nor for a hit: last step's impulse is a resting contact's, and it would bounce.
  const double* last = record.rigid || restitution > 0.0 ? nullptr : lastImpulse_.find(key);
  const int index = projector_.addRow(row, last ? *last : 0.0, z);
  projector_.setRestitution(index, restitution, loaded);
  rowOf_.insert(key, index);
  rowKey_.push_back(key);
  ++record.rowCount;
  requeried_.push_back(0);
  broughtForward_.push_back(0);
  curving_.push_back(curving);
  meets_.push_back(row.bias < 0.0);
  unsolved_.push_back(key);
  return true;
}

// Rows, n·(relative velocity) >= 0 with n the unit contact normal (from the particle toward the
// other object), written as sum_k coef_k · v_k >= 0:
//   particle-particle (i, j):       n·(v_j - v_i)                       >= 0
//   particle-edge (p; a, b; alpha): n·((1 - alpha) v_a + alpha v_b - v_p) >= 0
//   particle-half-plane (p):        -n·v_p = m^·v_p                     >= 0
math::ConstraintRow contactRowAlong(const Scene& scene, uint64_t key, const Vec2& n, double alpha) {
  const int i = keyParticle(key), other = keyOther(key);
  math::ConstraintRow row;
  row.count = 1;
  row.body[0] = i, row.coef[0] = -n;
  switch (keyKind(key)) {
    case PairKind::ParticleParticle:
      row.count = 2;
      row.body[1] = other, row.coef[1] = n;
      break;
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      row.count = 3;
      row.body[1] = e.i, row.coef[1] = (1.0 - alpha) * n;
      row.body[2] = e.j, row.coef[2] = alpha * n;
      break;
    }
    case PairKind::ParticleHalfPlane: break;
  }
  return row;
}

template <class Position>
math::ConstraintRow ContactZones::contactRow(const Scene& scene, uint64_t key, Position&& position, Vec2& n,
                                             double timeLeft) const {
  const int i = keyParticle(key), other = keyOther(key);
  const Vec2 x = position(i);
  double alpha = 0, distance = 0, radii = scene.radius[i];  // between the centre and the other's core
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: {
      const Vec2 d = position(other) - x;
      n = unit(d), distance = d.norm(), radii += scene.radius[other];
      break;
    }
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      const Vec2 d = math::segmentContactVector(x, position(e.i), position(e.j), &alpha);
      n = unit(d), distance = d.norm(), radii += e.radius;
      break;
    }
    case PairKind::ParticleHalfPlane: {
      const HalfPlane& h = scene.halfplanes[other];
      n = -unit(h.normal), distance = -(x - h.point).dot(n);
      break;
    }
  }
  math::ConstraintRow row = contactRowAlong(scene, key, n, alpha);
  // A gap closed at gap / timeLeft closes at the step's end: the pair meets no sooner than it
  // would have, and its contact is answered when it meets (an event later in the step, or the
  // next step's first instant). A gap the step's kicks alone close (kicksAlong over a step: a
  // disk settling onto a pile) is held as contact, as every gap was before: allowed to close,
  // the settling pile's gaps came back as events within the step, and `rain` 1,000 made 27% more
  // Gauss-Seidel updates and jammed twice as many particles (docs/performance-history.md).
  if (timeLeft <= 0.0) return row;
  const double gap = distance - radii;
  if (gap > kTouchingSlack * radii && gap > kicksAlong(scene, key, n, alpha) * h_) row.bias = -gap / timeLeft;
  return row;
}

double ContactZones::kicksAlong(const Scene& scene, uint64_t key, const Vec2& n, double alpha) const {
  const auto along = [&](int p) {
    const bool obstacle = isImmobile(scene, p) || sleepers_ == nullptr;
    return obstacle ? 0.0 : std::fabs(sleepers_->kickVector(p).dot(n));
  };
  const int i = keyParticle(key), other = keyOther(key);
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: return along(i) + along(other);
    case PairKind::ParticleEdge: {
      const Edge& edge = scene.edges[other];
      return along(i) + (1.0 - alpha) * along(edge.i) + alpha * along(edge.j);
    }
    case PairKind::ParticleHalfPlane: return along(i);
  }
  return 0.0;
}

// The closing speed the step gave the contact is its closing now less the one its particles had
// at the step's start (before their kicks). A disk resting on the floor or on a pile had none and
// gained all of it; a disk landing slowly (start closing u below one kick g h, closing now u + g h)
// gained more than a quarter, as the closing bound alone already asks of it (u + g h <= 2 g h); two disks
// falling together into each other close at their start speed u and gained nothing, whatever
// their kicks, so they bounce at any u above a hundredth of a kick (kRestingStartKicks).
bool ContactZones::resting(const Scene& scene, uint64_t key, const Vec2& n, double alpha, double closing) const {
  if (sleepers_ == nullptr) return false;
  const double kicks = kicksAlong(scene, key, n, alpha);
  if (closing > kRestingBounceKicks * kicks) return false;
  double scale = 0.0;
  const double atStart = closingSpeed(scene, key, n, alpha, [&](int p) { return sleepers_->startVelocity(p); }, scale);
  return atStart <= (1.0 - kRestingGainedShare) * closing || atStart <= kRestingStartKicks * kicks;
}

bool ContactZones::RowsAt::rowNow(int index, math::ConstraintRow& out) {
  if (zones_.curving_[index]) return false;  // its normal is where it deepens, on purpose
  Vec2 n = Vec2::Zero();
  // A row that bounces keeps bias 0 (setRow); a curving one returned above.
  const double timeLeft = zones_.projector_.restitutes(index) ? 0.0 : (1.0 - T_) * zones_.h_;
  out = zones_.contactRow(scene_, zones_.rowKey_[index], [&](int p) { return motion_.at(p, T_); }, n, timeLeft);
  return n != Vec2::Zero();
}

bool ContactZones::RowsAt::mayRescue(const int* ids, int count) {
  if (zones_.sleepers_ == nullptr) return true;
  double speed = 0.0, kick = 0.0;
  for (int k = 0; k < count; ++k) {
    speed = std::max(speed, zones_.projector_.velocity(ids[k]).norm());
    kick = std::max(kick, zones_.sleepers_->kickVector(ids[k]).norm());
  }
  return speed > kRescueKicks * kick;
}

}  // namespace fosssim
