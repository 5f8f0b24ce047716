// The independently known answers the study measures against. Each is derived from the physics,
// not from the simulator (docs/study.md states every formula); tests/study checks them against
// their own differential equations or conservation laws, never against a simulation.
#pragma once

#include "fosssim/core/types.h"

namespace fosssim::study {

/// Constant acceleration g: x(t) = x0 + v0 t + g t^2/2, v(t) = v0 + g t.
struct Projectile {
  Vec2 x0, v0, g;
  Vec2 position(double t) const { return x0 + v0 * t + 0.5 * g * t * t; }
  Vec2 velocity(double t) const { return v0 + g * t; }
};

/// m u'' + b u' + k u = 0 with u(0) = u0, u'(0) = v0: the displacement u of a spring from its rest
/// length, with every damping regime (under-, critically and over-damped) solved in closed form.
struct Oscillator {
  double m, k, b, u0, v0;
  double displacement(double t) const;
  double velocity(double t) const;
  /// Mechanical energy m u'^2/2 + k u^2/2 at time t.
  double energy(double t) const;
  double omega() const;  ///< undamped angular frequency sqrt(k/m)
};

/// The Kepler problem of two bodies under G m1 m2 / r^2, in relative coordinates r = x2 - x1 with
/// mu = G (m1 + m2). Bound (elliptic) orbits only.
class KeplerOrbit {
 public:
  /// From the relative position and velocity at t = 0. ok() is false for unbound orbits.
  KeplerOrbit(double mu, const Vec2& r0, const Vec2& v0);
  bool ok() const { return ok_; }
  double semiMajorAxis() const { return a_; }    ///< a = -mu / (2 eps), eps = v^2/2 - mu/r (vis-viva)
  double eccentricity() const { return e_; }
  double period() const { return period_; }       ///< 2 pi sqrt(a^3 / mu)
  double specificEnergy() const { return eps_; }  ///< eps, conserved
  double specificAngularMomentum() const { return h_; }  ///< r x v, conserved
  /// Relative position at time t, from Kepler's equation M = E - e sin E solved by Newton's method.
  Vec2 position(double t) const;

 private:
  bool ok_ = false;
  double a_ = 0, e_ = 0, period_ = 0, eps_ = 0, h_ = 0, meanAnomaly0_ = 0;
  Vec2 periapsis_ = Vec2::UnitX();  ///< unit vector towards periapsis
  Vec2 across_ = Vec2::UnitY();     ///< unit vector 90 degrees ahead in the direction of motion
};

/// Two disks in free flight that meet once, with restitution `cor` along the contact normal.
struct DiskCollision {
  bool ok = false;      ///< false if they never touch
  double time = 0;      ///< first contact: |x2 - x1 + (v2 - v1) t| = r1 + r2
  Vec2 normal;          ///< unit vector from disk 1 to disk 2 at contact
  Vec2 v1After, v2After;
};
DiskCollision diskCollision(const Vec2& x1, const Vec2& v1, double m1, double r1, const Vec2& x2, const Vec2& v2,
                            double m2, double r2, double cor);

/// A disk of radius r thrown under gravity g = (0, -g) at the floor y = 0: contact when its centre
/// reaches y = r, the normal velocity becomes -cor times itself, then free flight again (cor = 0:
/// it stays on the floor, sliding with its horizontal velocity). Valid up to the second contact.
struct FloorBounce {
  Vec2 x0, v0;
  double g, r, cor;
  double contactTime() const;   ///< the larger root of r = y0 + vy0 t - g t^2/2
  double secondContactTime() const;  ///< when the answers below stop holding
  Vec2 velocityBefore() const;  ///< velocity at the contact time, before the bounce
  Vec2 position(double t) const;
  Vec2 velocity(double t) const;
};

}  // namespace fosssim::study
