#include "contact_zones.h"

#include "pair_query.h"

#include "fosssim/math/geometry.h"

#include <algorithm>

namespace fosssim {
namespace {

Vec2 unit(const Vec2& a) {
  const double n = a.norm();
  return n > 0.0 ? Vec2(a / n) : Vec2(Vec2::Zero());
}

Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }

}  // namespace

void ContactZones::reset(int n) {
  if (static_cast<int>(parent_.size()) != n) {
    parent_.assign(n, -1);
    slot_.assign(n, -1);
    members_.assign(n, {});
    contacts_.assign(n, {});
    projections_.assign(n, 0);
    solves_.assign(n, 0);
    solvedContacts_.assign(n, 0);
    rigid_.assign(n, 0);
    rateScale_.assign(n, 0.0);
    roots_.clear();
    return;
  }
  for (int r : roots_) {
    for (int p : members_[r]) parent_[p] = -1;
    members_[r].clear();
    contacts_[r].clear();
    projections_[r] = 0;
    solves_[r] = 0;
    solvedContacts_[r] = 0;
    rigid_[r] = 0;
  }
  roots_.clear();
}

int ContactZones::join(int p) {
  if (parent_[p] >= 0) return root(p);
  parent_[p] = p;
  members_[p].assign(1, p);
  contacts_[p].clear();
  projections_[p] = 0;
  solves_[p] = 0;
  solvedContacts_[p] = 0;
  rigid_[p] = 0;
  rateScale_[p] = 0;
  roots_.push_back(p);
  return p;
}

// Union by size keeps the trees shallow (root() does not compress: it is const).
int ContactZones::unite(int a, int b) {
  a = root(a), b = root(b);
  if (a == b) return a;
  if (members_[a].size() < members_[b].size()) std::swap(a, b);
  parent_[b] = a;
  members_[a].insert(members_[a].end(), members_[b].begin(), members_[b].end());
  contacts_[a].insert(contacts_[a].end(), contacts_[b].begin(), contacts_[b].end());
  projections_[a] = std::max(projections_[a], projections_[b]);
  solves_[a] = std::max(solves_[a], solves_[b]);
  solvedContacts_[a] += solvedContacts_[b];
  rigid_[a] = rigid_[a] || rigid_[b];
  rateScale_[a] = std::max(rateScale_[a], rateScale_[b]);
  members_[b].clear();
  contacts_[b].clear();
  return a;
}

void ContactZones::addContact(int zone, uint64_t key) { contacts_[zone].push_back(key); }

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
      const double reach = rs + left * (motion.rate(other) - motion.rate(i)).norm();
      return overlap(box(i, rs), box(other, 0.0)) && (motion.at(other, T) - x).squaredNorm() <= reach * reach;
    }
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      const double rs = (scene.radius[i] + e.radius) * (1.0 + kTouchingSlack);
      const double reach = rs + left * (motion.rate(i).norm() + motion.rate(e.i).norm() + motion.rate(e.j).norm());
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
      const double s0 = (x - h.point).dot(n), s1 = s0 + left * motion.rate(i).dot(n);
      return std::min(s0, s1) <= r && std::max(s0, s1) >= -r;
    }
  }
  return false;
}

int ContactZones::absorb(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, uint64_t key,
                         double T) {
  int zone = -1;
  queue_.clear();
  const PairParticles pair = pairParticles(scene, key);
  for (int k = 0; k < pair.count; ++k) zone = take(scene, pair.p[k], zone);
  if (zone < 0) return -1;  // every particle of the pair is fixed
  addContact(zone, key);
  return grow(scene, motion, candidates, zone, T);
}

int ContactZones::take(const Scene& scene, int p, int zone) {
  if (scene.isFixed(p)) return zone;
  if (parent_[p] < 0) queue_.push_back(p);  // new to the zones: its neighbours are looked at
  const int r = join(p);
  return zone < 0 ? r : unite(zone, r);
}

// Breadth-first over the pairs of the particles in queue_: every pair that is near joins the
// zone's contacts, and its particles the zone.
int ContactZones::grow(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, int zone,
                       double T) {
  while (!queue_.empty()) {
    const int q = queue_.back();
    queue_.pop_back();
    keys_.clear();
    candidates.pairsOf(q, keys_);
    for (uint64_t k : keys_) {
      if (!near(scene, motion, k, T)) continue;
      const PairParticles other = pairParticles(scene, k);
      for (int m = 0; m < other.count; ++m) zone = take(scene, other.p[m], zone);
      addContact(zone, k);
    }
  }
  return root(zone);
}

size_t ContactZones::uniqueContacts(int zone) {
  std::vector<uint64_t>& contacts = contacts_[zone];
  std::sort(contacts.begin(), contacts.end());
  contacts.erase(std::unique(contacts.begin(), contacts.end()), contacts.end());
  return contacts.size();
}

// Solve, apply, and look again from every particle of the zone with its new velocities: pairs that
// are near now join (with their particles) and the zone is solved again, until it stops growing
// (Harmon et al.'s merge-and-project loop, run here at one instant) or moves rigidly.
void ContactZones::resolve(const Scene& scene, StepMotion& motion, PairCandidates& candidates, int zone,
                           double T, double h, VecX& v, std::vector<int>& changed, StepStats& stats) {
  zone = root(zone);
  for (;;) {
    const size_t contacts = uniqueContacts(zone);
    const size_t before = changed.size();
    solve(scene, motion, zone, T, h, v, changed, stats);
    if (rigid_[zone]) return;
    // The broad phase's boxes must cover the new motions before it is asked for neighbours.
    for (size_t k = before; k < changed.size(); ++k) candidates.update(changed[k]);
    candidates.settle(false);
    queue_.assign(members_[zone].begin(), members_[zone].end());
    zone = grow(scene, motion, candidates, zone, T);
    if (uniqueContacts(zone) == contacts) return;
  }
}

void ContactZones::solve(const Scene& scene, StepMotion& motion, int zone, double T, double h, VecX& v,
                         std::vector<int>& changed, StepStats& stats) {
  const std::vector<uint64_t>& contacts = contacts_[zone];
  // Bodies: the zone's particles (in ascending order, so that results do not depend on the order
  // in which the zone was discovered), then the fixed particles its contacts touch.
  std::vector<int>& members = members_[zone];
  std::sort(members.begin(), members.end());
  bodies_.assign(members.begin(), members.end());
  for (uint64_t key : contacts) {
    const PairParticles pair = pairParticles(scene, key);
    for (int k = 0; k < pair.count; ++k)
      if (scene.isFixed(pair.p[k]) && std::find(bodies_.begin() + static_cast<long>(members.size()), bodies_.end(),
                                                pair.p[k]) == bodies_.end())
        bodies_.push_back(pair.p[k]);
  }
  inverseMass_.resize(bodies_.size());
  velocity_.resize(bodies_.size());
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const int p = bodies_[b];
    slot_[p] = static_cast<int>(b);
    inverseMass_[b] = scene.isFixed(p) ? 0.0 : 1.0 / scene.massOf(p);
    velocity_[b] = motion.rate(p) / h;
  }

  bool converged = false;
  if (contacts.size() <= solvedContacts_[zone]) ++projections_[zone];  // nothing new: a jam?
  solvedContacts_[zone] = contacts.size();
  if (!rigid_[zone] && !rigidOnly_ && projections_[zone] <= kMaxZoneProjections && solves_[zone] < kMaxZoneSolves) {
    ++solves_[zone];
    ++stats.failsafeRounds;
    project(scene, motion, zone, T, converged);
  }
  if (!converged) {
    rigid_[zone] = 1;
    moveRigidly(scene, motion, zone, T, h);
  }
  double scale = 0;
  for (int p : members) {
    const Vec2 rate = h * velocity_[slot_[p]];
    scale = std::max({scale, rate.norm(), motion.rate(p).norm()});
    if (rate == motion.rate(p)) continue;
    at(v, p) += velocity_[slot_[p]] - motion.rate(p) / h;
    motion.setRate(p, T, rate);
    changed.push_back(p);
  }
  for (int p : bodies_) slot_[p] = -1;
  rateScale_[zone] = std::max(rateScale_[zone], scale);
}

// Rows per contact, n·(relative velocity) >= 0 with n a unit contact normal (from the particle
// toward the other object), written as sum_k coef_k · v_k >= 0:
//   particle-particle (i, j):       n·(v_j - v_i)                       >= 0
//   particle-edge (p; a, b; alpha): n·((1 - alpha) v_a + alpha v_b - v_p) >= 0
//   particle-half-plane (p):        -n·v_p = m^·v_p                     >= 0
// One row with the normal at T; and for a contact that does not close at T but deepens later in
// the step (an edge rotating under a resting disk), one more with the normal where it would
// overlap deepest: only that normal sees the approach. Each row is a half-space through v = 0, so
// the projection still never adds energy.
void ContactZones::project(const Scene& scene, const StepMotion& motion, int zone, double T, bool& converged) {
  rows_.clear();
  const auto position = [&](int p, double t) { return motion.at(p, t); };
  const auto rate = [&](int p) { return motion.rate(p); };
  for (uint64_t key : contacts_[zone]) {
    const Vec2 n = addRow(scene, key, [&](int p) { return motion.at(p, T); });
    double scale = 0, alpha = 0;
    if (keyKind(key) == PairKind::ParticleEdge) {
      const Edge& e = scene.edges[keyOther(key)];
      alpha = math::segmentParameterClamped(motion.at(keyParticle(key), T), motion.at(e.i, T), motion.at(e.j, T));
    }
    if (closingSpeed(scene, key, n, alpha, rate, scale) > kRestingClosingFraction * scale) continue;
    double deepest = 0, length = 0;
    const double td = deepestTime(scene, key, position, T, 1.0, deepest);
    if (pairDeepening(scene, key, position, T, 1.0, length) > kDepthTolerance * length)
      addRow(scene, key, [&](int p) { return motion.at(p, td); });
  }
  math::ProjectionSettings settings;
  settings.tolerance = kZoneProjectionTolerance;
  const math::ProjectionResult result = projector_.project(inverseMass_, rows_, velocity_, settings);
  converged = result.converged;
}

template <class Position>
Vec2 ContactZones::addRow(const Scene& scene, uint64_t key, Position&& position) {
  const int i = keyParticle(key), other = keyOther(key);
  const Vec2 x = position(i);
  math::ConstraintRow row;
  Vec2 n;
  switch (keyKind(key)) {
    case PairKind::ParticleParticle:
      n = unit(position(other) - x);
      row.count = 2;
      row.body[0] = slot_[i], row.coef[0] = -n;
      row.body[1] = slot_[other], row.coef[1] = n;
      break;
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      double alpha = 0;
      n = unit(math::segmentContactVector(x, position(e.i), position(e.j), &alpha));
      row.count = 3;
      row.body[0] = slot_[i], row.coef[0] = -n;
      row.body[1] = slot_[e.i], row.coef[1] = (1.0 - alpha) * n;
      row.body[2] = slot_[e.j], row.coef[2] = alpha * n;
      break;
    }
    case PairKind::ParticleHalfPlane:
      n = -unit(scene.halfplanes[other].normal);
      row.count = 1;
      row.body[0] = slot_[i], row.coef[0] = -n;
      break;
  }
  if (n != Vec2::Zero()) rows_.push_back(row);  // coincident centres: no direction to keep apart along
  return n;
}

// Rigid velocities closest to the zone's in the kinetic-energy norm: the centre of mass's
// velocity vc = sum m u / M and the angular velocity w = L / I of the momentum about it,
// L = sum m (x - c) x (u - vc), I = sum m |x - c|^2; u' = vc + w perp(x - c). An immovable zone
// (a fixed particle or a half-plane among its contacts) stops.
void ContactZones::moveRigidly(const Scene& scene, const StepMotion& motion, int zone, double T, double h) {
  (void)h;
  const std::vector<int>& members = members_[zone];
  bool immovable = bodies_.size() > members.size();
  for (uint64_t key : contacts_[zone]) immovable = immovable || keyKind(key) == PairKind::ParticleHalfPlane;
  if (immovable) {
    for (int p : members) velocity_[slot_[p]] = Vec2::Zero();
    return;
  }
  double mass = 0;
  Vec2 c = Vec2::Zero(), vc = Vec2::Zero();
  for (int p : members) {
    const double m = scene.massOf(p);
    mass += m;
    c += m * motion.at(p, T);
    vc += m * velocity_[slot_[p]];
  }
  c /= mass;
  vc /= mass;
  double angular = 0, inertia = 0;
  for (int p : members) {
    const double m = scene.massOf(p);
    const Vec2 r = motion.at(p, T) - c, u = velocity_[slot_[p]] - vc;
    angular += m * (r.x() * u.y() - r.y() * u.x());
    inertia += m * r.squaredNorm();
  }
  const double w = inertia > 0.0 ? angular / inertia : 0.0;
  for (int p : members) velocity_[slot_[p]] = vc + w * perp(motion.at(p, T) - c);
}

void ContactZones::sizes(StepStats& stats) const {
  for (int r : roots_) {
    if (parent_[r] != r) continue;
    ++stats.zones;
    stats.rigidZones += rigid_[r];
    stats.zoneParticles += static_cast<int>(members_[r].size());
    stats.largestZone = std::max(stats.largestZone, static_cast<int>(members_[r].size()));
  }
  stats.failsafeUsed = stats.failsafeUsed || stats.zones > 0;
}

}  // namespace fosssim
