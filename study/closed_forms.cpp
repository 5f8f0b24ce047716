#include "closed_forms.h"

#include <cmath>
#include <limits>

namespace fosssim::study {

// ---- Oscillator ------------------------------------------------------------------------------
// Characteristic equation m s^2 + b s + k = 0, gamma = b/(2m), omega0^2 = k/m.
//   under-damped (gamma < omega0): u = e^{-gamma t} (u0 cos wd t + (v0 + gamma u0)/wd sin wd t),
//                                   wd = sqrt(omega0^2 - gamma^2)
//   critical (gamma = omega0):      u = e^{-gamma t} (u0 + (v0 + gamma u0) t)
//   over-damped:                    u = c1 e^{s1 t} + c2 e^{s2 t}, s = -gamma -+ sqrt(gamma^2 - omega0^2),
//                                   c1 + c2 = u0, s1 c1 + s2 c2 = v0
// The velocity is the exact derivative of each form.

double Oscillator::omega() const { return std::sqrt(k / m); }

double Oscillator::displacement(double t) const {
  const double gamma = b / (2 * m), w0 = omega();
  if (gamma < w0) {
    const double wd = std::sqrt(w0 * w0 - gamma * gamma);
    return std::exp(-gamma * t) * (u0 * std::cos(wd * t) + (v0 + gamma * u0) / wd * std::sin(wd * t));
  }
  if (gamma == w0) return std::exp(-gamma * t) * (u0 + (v0 + gamma * u0) * t);
  const double root = std::sqrt(gamma * gamma - w0 * w0), s1 = -gamma - root, s2 = -gamma + root;
  const double c1 = (v0 - s2 * u0) / (s1 - s2), c2 = u0 - c1;
  return c1 * std::exp(s1 * t) + c2 * std::exp(s2 * t);
}

double Oscillator::velocity(double t) const {
  const double gamma = b / (2 * m), w0 = omega();
  if (gamma < w0) {
    const double wd = std::sqrt(w0 * w0 - gamma * gamma);
    const double A = u0, B = (v0 + gamma * u0) / wd;
    const double c = std::cos(wd * t), s = std::sin(wd * t);
    return std::exp(-gamma * t) * (-gamma * (A * c + B * s) + wd * (-A * s + B * c));
  }
  if (gamma == w0) {
    const double C = v0 + gamma * u0;
    return std::exp(-gamma * t) * (C - gamma * (u0 + C * t));
  }
  const double root = std::sqrt(gamma * gamma - w0 * w0), s1 = -gamma - root, s2 = -gamma + root;
  const double c1 = (v0 - s2 * u0) / (s1 - s2), c2 = u0 - c1;
  return c1 * s1 * std::exp(s1 * t) + c2 * s2 * std::exp(s2 * t);
}

double Oscillator::energy(double t) const {
  const double u = displacement(t), v = velocity(t);
  return 0.5 * m * v * v + 0.5 * k * u * u;
}

// ---- Kepler ----------------------------------------------------------------------------------
// eps = v^2/2 - mu/r (vis-viva), a = -mu/(2 eps), h = r x v, e = sqrt(1 + 2 eps h^2/mu^2).
// The eccentricity vector ((v^2 - mu/r) r - (r.v) v)/mu points to periapsis. With the eccentric
// anomaly E: r = a (cos E - e) p + b sin E q (b = a sqrt(1 - e^2), q = p rotated 90 degrees in
// the direction of motion), and the mean anomaly M = E - e sin E grows as n t, n = sqrt(mu/a^3).

KeplerOrbit::KeplerOrbit(double mu, const Vec2& r0, const Vec2& v0) {
  const double r = r0.norm();
  eps_ = 0.5 * v0.squaredNorm() - mu / r;
  h_ = cross(r0, v0);
  if (!(eps_ < 0) || h_ == 0) return;
  a_ = -mu / (2 * eps_);
  period_ = 2 * M_PI * std::sqrt(a_ * a_ * a_ / mu);
  const Vec2 eVec = ((v0.squaredNorm() - mu / r) * r0 - r0.dot(v0) * v0) / mu;
  e_ = eVec.norm();
  periapsis_ = e_ > 1e-12 ? Vec2(eVec / e_) : Vec2(r0 / r);
  const double sense = h_ > 0 ? 1.0 : -1.0;
  across_ = sense * Vec2(-periapsis_.y(), periapsis_.x());
  // Eccentric anomaly of r0 from its components along p and q.
  const double b = a_ * std::sqrt(1 - e_ * e_);
  const double E0 = std::atan2(r0.dot(across_) / b, r0.dot(periapsis_) / a_ + e_);
  meanAnomaly0_ = E0 - e_ * std::sin(E0);
  ok_ = true;
}

Vec2 KeplerOrbit::position(double t) const {
  if (!ok_) return Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  const double n = 2 * M_PI / period_;
  const double M = std::remainder(meanAnomaly0_ + n * t, 2 * M_PI);
  double E = e_ < 0.8 ? M : (M < 0 ? -M_PI : M_PI);  // a start from which Newton converges
  for (int k = 0; k < 60; ++k) {
    const double step = (E - e_ * std::sin(E) - M) / (1 - e_ * std::cos(E));
    E -= step;
    if (std::abs(step) < 1e-15) break;
  }
  const double b = a_ * std::sqrt(1 - e_ * e_);
  return a_ * (std::cos(E) - e_) * periapsis_ + b * std::sin(E) * across_;
}

// ---- Disks -----------------------------------------------------------------------------------
// Contact: |d + w t| = R with d = x2 - x1, w = v2 - v1, R = r1 + r2, the smaller root of
// |w|^2 t^2 + 2 (d.w) t + |d|^2 - R^2 = 0. Along the unit normal n, the approach speed
// u = (v1 - v2).n becomes -cor u: the impulse J = (1 + cor) u / (1/m1 + 1/m2) changes
// v1 by -J/m1 n and v2 by +J/m2 n (momentum kept; kinetic energy kept when cor = 1).

DiskCollision diskCollision(const Vec2& x1, const Vec2& v1, double m1, double r1, const Vec2& x2, const Vec2& v2,
                            double m2, double r2, double cor) {
  DiskCollision c;
  const Vec2 d = x2 - x1, w = v2 - v1;
  const double R = r1 + r2, A = w.squaredNorm(), B = d.dot(w), C = d.squaredNorm() - R * R;
  const double disc = B * B - A * C;
  if (A == 0 || disc < 0) return c;
  const double t = (-B - std::sqrt(disc)) / A;
  if (t < 0) return c;
  c.ok = true;
  c.time = t;
  c.normal = (d + w * t) / R;
  const double u = (v1 - v2).dot(c.normal);
  const double J = (1 + cor) * u / (1 / m1 + 1 / m2);
  c.v1After = v1 - J / m1 * c.normal;
  c.v2After = v2 + J / m2 * c.normal;
  return c;
}

// ---- Floor bounce ----------------------------------------------------------------------------
// Before contact y = y0 + vy0 t - g t^2/2; contact at y = r, the later root
// t_c = (vy0 + sqrt(vy0^2 + 2 g (y0 - r))) / g. After it: vy = -cor vy(t_c) - g (t - t_c), and
// y = r + (-cor vy(t_c)) (t - t_c) - g (t - t_c)^2/2, up to the second contact
// t_c + 2 cor |vy(t_c)| / g. With cor = 0 the disk rests on the floor (y = r, vy = 0).

double FloorBounce::contactTime() const {
  return (v0.y() + std::sqrt(v0.y() * v0.y() + 2 * g * (x0.y() - r))) / g;
}

double FloorBounce::secondContactTime() const {
  return contactTime() + 2 * cor * std::abs(velocityBefore().y()) / g;
}

Vec2 FloorBounce::velocityBefore() const { return Vec2(v0.x(), v0.y() - g * contactTime()); }

Vec2 FloorBounce::position(double t) const {
  const double tc = contactTime();
  if (t <= tc) return Vec2(x0.x() + v0.x() * t, x0.y() + v0.y() * t - 0.5 * g * t * t);
  const double s = t - tc, up = -cor * velocityBefore().y();
  if (cor == 0) return Vec2(x0.x() + v0.x() * t, r);
  return Vec2(x0.x() + v0.x() * t, r + up * s - 0.5 * g * s * s);
}

Vec2 FloorBounce::velocity(double t) const {
  const double tc = contactTime();
  if (t <= tc) return Vec2(v0.x(), v0.y() - g * t);
  if (cor == 0) return Vec2(v0.x(), 0.0);
  return Vec2(v0.x(), -cor * velocityBefore().y() - g * (t - tc));
}

}  // namespace fosssim::study
