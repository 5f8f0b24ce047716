// The failsafe's rigid motion (contact_zones.h): a jammed zone touching nothing moves as one
// body, and goes back to the projection when it meets an obstacle.
#include "contact_zones.h"

namespace fosssim {
namespace {

Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }

}  // namespace

// Rigid velocities closest to the zone's in the kinetic-energy norm: the centre of mass's
// velocity vc = sum m u / M and the angular velocity w = L / I of the momentum about it,
// L = sum m (x - c) x (u - vc), I = sum m |x - c|^2; u' = vc + w perp(x - c). An immovable zone
// (a fixed particle or a half-plane among its contacts) stops. Either way its particles leave
// the projection (frozen there at these velocities).
void ContactZones::moveRigidly(const Scene& scene, const StepMotion& motion, int zone, double T) {
  ZoneRecord& z = record_[zone];
  if (z.immovable) {
    // Members stay frozen, and unite() only appends: only the members that joined since the
    // last time are new. (Visiting all of them at every resolve of a zone of 20,000 particles,
    // which new contacts join all through a step, took 4% of rain's time at N = 10^5.)
    for (int p = z.lastFrozen < 0 ? z.first : nextMember_[z.lastFrozen]; p >= 0; p = nextMember_[p])
      projector_.freeze(p, Vec2::Zero());
    z.lastFrozen = z.last;
    return;
  }
  double mass = 0;
  Vec2 c = Vec2::Zero(), vc = Vec2::Zero();
  forEachMember(zone, [&](int p) {
    const double m = scene.massOf(p);
    mass += m;
    c += m * motion.at(p, T);
    vc += m * projector_.velocity(p);
  });
  c /= mass;
  vc /= mass;
  double angular = 0, inertia = 0;
  forEachMember(zone, [&](int p) {
    const double m = scene.massOf(p);
    const Vec2 r = motion.at(p, T) - c, u = projector_.velocity(p) - vc;
    angular += m * (r.x() * u.y() - r.y() * u.x());
    inertia += m * r.squaredNorm();
  });
  const double w = inertia > 0.0 ? angular / inertia : 0.0;
  forEachMember(zone, [&](int p) { projector_.freeze(p, vc + w * perp(motion.at(p, T) - c)); });
}

// A zone moving rigidly that meets an obstacle goes back to the projection (see the top of the
// header): its members leave the projector's frozen set with the rigid velocities they have, and
// their rows are queued for the zone's next solve. Stopped members (a jam or a hold of the zone
// it merged with) stay stopped; the others are movable already (release() leaves them as they are).
void ContactZones::resumeProjection(const Scene& scene, int zone, int metAgain) {
  record_[zone].rigid = 0;
  record_[zone].metAgain = metAgain;
  forEachMember(zone, [&](int p) {
    if (!stopped_[p]) projector_.release(p, 1.0 / scene.massOf(p), projector_.velocity(p));
  });
}

}  // namespace fosssim
