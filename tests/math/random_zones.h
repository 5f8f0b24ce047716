// Test helpers shared by the zone projection and ContactProjector tests: contact rows of the three
// kinds, a random-zone generator, and the per-zone quantities the tests check (row velocity, speed
// scale, kinetic energy, momentum).
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numeric>
#include <random>
#include <vector>

#include "fosssim/math/zone_projection.h"

namespace fosssim::math::testing {

struct Zone {  // v~ per body, body 0 usually fixed at rest
  std::vector<double> invMass;
  std::vector<ConstraintRow> rows;
  std::vector<Vec2> v;
};

inline Vec2 unit(double angle) { return Vec2(std::cos(angle), std::sin(angle)); }

inline ConstraintRow makeRow(std::initializer_list<int> bodies, std::initializer_list<Vec2> coefs) {
  ConstraintRow r;
  for (int b : bodies) r.body[r.count++] = b;
  std::copy(coefs.begin(), coefs.end(), r.coef);
  return r;
}
inline ConstraintRow halfPlaneRow(int p, const Vec2& n) { return makeRow({p}, {n}); }
inline ConstraintRow pairRow(int i, int j, const Vec2& n) {  // n from i to j: n.(v_j - v_i) >= 0
  return makeRow({i, j}, {-n, n});
}
inline ConstraintRow edgeRow(int p, int a, int b, double alpha, const Vec2& n) {
  return makeRow({p, a, b}, {n, -(1.0 - alpha) * n, -alpha * n});
}

// 2-5 bodies, body 0 fixed and at rest; 1-10 rows of the three kinds on distinct bodies. With
// freeOnly, 3-5 bodies all free and only pair/edge rows (coefficients sum to zero, so momentum is
// kept). The draws for freeOnly = false are the ones both tests' seeds were chosen with.
inline Zone randomZone(std::mt19937& rng, bool freeOnly = false) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), angle(0.0, 6.283185307179586);
  std::uniform_real_distribution<double> logMass(std::log(0.1), std::log(10.0));
  Zone z;
  const int bodies = std::uniform_int_distribution<int>(freeOnly ? 3 : 2, 5)(rng);
  const int rows = std::uniform_int_distribution<int>(1, 10)(rng);
  for (int b = 0; b < bodies; ++b) {
    const bool fixed = b == 0 && !freeOnly;
    z.invMass.push_back(fixed ? 0.0 : 1.0 / std::exp(logMass(rng)));
    // Braced, so x is drawn before y under every compiler (a call's arguments come in an order
    // the compiler picks: gcc right to left, clang left to right).
    z.v.push_back(fixed ? Vec2::Zero() : Vec2{u(rng), u(rng)});
  }
  std::vector<int> ids(bodies);
  std::iota(ids.begin(), ids.end(), 0);
  for (int k = 0; k < rows; ++k) {
    std::shuffle(ids.begin(), ids.end(), rng);
    const int count = std::uniform_int_distribution<int>(freeOnly ? 2 : 1, std::min(3, bodies))(rng);
    const Vec2 n = unit(angle(rng));
    if (count == 1) z.rows.push_back(halfPlaneRow(ids[0], n));
    if (count == 2) z.rows.push_back(pairRow(ids[0], ids[1], n));
    if (count == 3) z.rows.push_back(edgeRow(ids[0], ids[1], ids[2], 0.5 * (u(rng) + 1.0), n));
  }
  return z;
}

inline double rowVelocity(const ConstraintRow& r, const std::vector<Vec2>& v) {  // G_k v
  double w = 0.0;
  for (int j = 0; j < r.count; ++j) w += r.coef[j].dot(v[r.body[j]]);
  return w;
}
inline double rowNorm(const ConstraintRow& r) {  // |G_k|
  double n2 = 0.0;
  for (int j = 0; j < r.count; ++j) n2 += r.coef[j].squaredNorm();
  return std::sqrt(n2);
}
inline double speedScale(const std::vector<Vec2>& v) {
  double s = 0.0;
  for (const Vec2& x : v) s = std::max(s, x.norm());
  return s;
}
inline double kineticEnergy(const std::vector<double>& invMass, const std::vector<Vec2>& v) {
  double e = 0.0;
  for (size_t b = 0; b < v.size(); ++b)
    if (invMass[b] > 0.0) e += 0.5 / invMass[b] * v[b].squaredNorm();
  return e;
}
inline Vec2 momentum(const std::vector<double>& invMass, const std::vector<Vec2>& v) {  // free bodies only
  Vec2 p = Vec2::Zero();
  for (size_t b = 0; b < v.size(); ++b) p += v[b] / invMass[b];
  return p;
}

}  // namespace fosssim::math::testing
