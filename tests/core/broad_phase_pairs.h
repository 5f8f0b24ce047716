// Shared by the broad phase's tests (broad_phase_test.cpp, broad_phase_lists_test.cpp,
// broad_phase_grazing_test.cpp): a random scene built to be hard for it, a scene
// with its step's start and end positions, the candidate pairs a PairCandidates lists, and the
// ground truth of every pair checked by the reference's sweep.
#pragma once

#include "core/collision/collision_search.h"
#include "core/collision/pair_candidates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

namespace fosssim::testing {

/// A scene and one step of it: positions at its start (qs) and end (qe), 2N each.
struct Motion {
  Scene scene;
  VecX qs, qe;
};

/// Every pair the candidates list, as pair keys (and that each particle's lists are sorted).
inline std::set<uint64_t> candidateKeys(const Scene& scene, const PairCandidates& c) {
  std::set<uint64_t> keys;
  std::vector<int> row;
  for (int i = 0; i < scene.numParticles(); ++i) {
    row.clear();
    c.particlesOf(i, -1, row);
    EXPECT_TRUE(std::is_sorted(row.begin(), row.end()));
    for (int j : row) keys.insert(pairKey(i, PairKind::ParticleParticle, j));
    row.clear();
    c.edgesOf(i, -1, row);
    EXPECT_TRUE(std::is_sorted(row.begin(), row.end()));
    for (int e : row) keys.insert(pairKey(i, PairKind::ParticleEdge, e));
    for (int h = 0; h < static_cast<int>(scene.halfplanes.size()); ++h)
      if (c.nearPlane(i, h)) keys.insert(pairKey(i, PairKind::ParticleHalfPlane, h));
  }
  return keys;
}

/// Every collision, checking every pair (the reference's sweep).
inline std::vector<Collision> allPairs(const Scene& scene, const VecX& qs, const VecX& qe,
                                       const math::DetectionRules& rules) {
  std::vector<Collision> out;
  ContinuousDetector(rules).forEachCollision(scene, qs, qe, nullptr, [&](const Collision& c) { out.push_back(c); });
  return out;
}

/// A random scene and step designed to stress the broad phase's margins.
inline Motion randomMotion(std::mt19937& rng, int n, double offset) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  // x drawn before y, in separate statements: a call's arguments are evaluated in an order the
  // compiler picks (gcc right to left, clang left to right), and both must build the same scenes.
  auto uv = [&](double lo, double hi) {
    const double x = u(lo, hi);
    const double y = u(lo, hi);
    return Vec2(x, y);
  };
  Motion m;
  m.qs.resize(2 * n);
  m.qe.resize(2 * n);
  const double size = u(0.5, 4.0);
  for (int p = 0; p < n; ++p) {
    const int style = static_cast<int>(u(0, 6));
    double r = std::pow(10.0, u(-4, 0));
    if (style == 0) r = std::pow(10.0, u(0, 1.5));  // huge
    Vec2 x = uv(-size, size);
    if (p > 0 && style <= 3) {  // near another particle: just inside or outside reach
      const int q = static_cast<int>(u(0, p));
      const double reach = r + m.scene.radius[q];
      const double angle = u(0, 6.283185307179586);
      const double gap =
          style == 1 ? u(-1e-6, 1e-6) * reach : (style == 2 ? u(0.9, 1.1) * reach : u(1.0, 1.0 + 1e-9) * reach);
      x = at(m.qs, q) + gap * Vec2(std::cos(angle), std::sin(angle));
      if (style == 3) x = at(m.qs, q) + (reach + std::pow(10.0, u(-9, -3))) * Vec2(std::cos(angle), std::sin(angle));
    }
    Vec2 d = uv(-1, 1);
    const int speed = static_cast<int>(u(0, 4));
    d *= speed == 0 ? 1e-8 : (speed == 1 ? 0.01 * size : (speed == 2 ? size : 0.0));  // static, slow, fast, still
    const double mass = std::pow(10.0, u(-2, 2));
    const bool fixed = u(0, 1) < 0.1;
    addParticle(m.scene, mass, fixed, r);
    at(m.qs, p) = x + Vec2(offset, -offset);
    at(m.qe, p) = at(m.qs, p) + d;
  }
  const int edges = static_cast<int>(u(0, n / 2));
  for (int k = 0; k < edges; ++k) {
    const int i = static_cast<int>(u(0, n));
    int j = static_cast<int>(u(0, n));
    if (j == i) j = (i + 1) % n;
    if (u(0, 1) < 0.2) {  // a tiny or collapsing edge
      at(m.qs, j) = at(m.qs, i) + uv(-1e-7, 1e-7);
      at(m.qe, j) = at(m.qe, i) + (u(0, 1) < 0.5 ? uv(-1e-7, 1e-7) : uv(-1, 1));
    }
    m.scene.edges.push_back(Edge{i, j, std::pow(10.0, u(-4, -1))});
  }
  const int planes = static_cast<int>(u(0, 4));
  for (int k = 0; k < planes; ++k) {
    const double length = std::pow(10.0, u(-4, 3));
    const Vec2 normal = length * uv(-1, 1).normalized();
    const int on = static_cast<int>(u(0, n));
    const Vec2 shift = uv(-0.1, 0.1);
    m.scene.halfplanes.push_back(HalfPlane{at(m.qs, on) + shift, normal});
  }
  return m;
}

}  // namespace fosssim::testing
