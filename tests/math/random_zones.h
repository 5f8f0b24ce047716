// Test helpers shared by the zone projection and ContactProjector tests: contact rows of the three
// kinds, a random-zone generator, the per-zone quantities the tests check (row velocity, speed
// scale, kinetic energy, momentum), and the projection's optimality (KKT) conditions.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

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

// KKT of min 1/2 |v - v~|_M^2 s.t. G v >= 0, recomputed here from the rows: v* - v~ = M^-1 G^T
// lambda, lambda >= 0, every row satisfied to the slack, and complementarity in velocity units
// (a row with an impulse is tight). Immovable bodies keep their velocities.
inline void expectKkt(const Zone& z, const std::vector<Vec2>& v, const std::vector<double>& lambda, double tol) {
  ASSERT_EQ(lambda.size(), z.rows.size());
  const double scale = speedScale(z.v);
  std::vector<Vec2> change(z.v.size(), Vec2::Zero());
  for (size_t k = 0; k < z.rows.size(); ++k)
    for (int j = 0; j < z.rows[k].count; ++j)
      change[z.rows[k].body[j]] += z.invMass[z.rows[k].body[j]] * lambda[k] * z.rows[k].coef[j];
  for (size_t b = 0; b < z.v.size(); ++b) {
    EXPECT_LE((v[b] - z.v[b] - change[b]).norm(), 1e-12 * scale) << "body " << b;
    if (z.invMass[b] == 0.0) {
      EXPECT_EQ(v[b], z.v[b]) << "body " << b;
    }
  }
  for (size_t k = 0; k < z.rows.size(); ++k) {
    const double w = rowVelocity(z.rows[k], v);
    const double rowTol = tol * rowNorm(z.rows[k]) * scale;
    double akk = 0.0;
    for (int j = 0; j < z.rows[k].count; ++j) akk += z.invMass[z.rows[k].body[j]] * z.rows[k].coef[j].squaredNorm();
    EXPECT_GE(lambda[k], 0.0) << "row " << k;
    EXPECT_GE(w, -rowTol) << "row " << k;
    EXPECT_LE(std::min(akk * lambda[k], std::max(w, 0.0)), rowTol) << "row " << k;
  }
}

}  // namespace fosssim::math::testing
