// Helpers for the property tests of the default mode's contact physics (contact_physics_test.cpp,
// contact_physics_random_test.cpp, contact_physics_pile_test.cpp; the promises: spec "Contact
// physics in the default mode"). Every scene is built inline with the symplectic Euler
// integrator (x += h v_new: free flight is exact).
#pragma once

#include "support/collision_type.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace fosssim::testing {

using Rng = std::mt19937;
/// mt19937's output is fixed by the standard (its distributions are not): the same scenes everywhere.
inline double uniform(Rng& rng, double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); }
inline int uniformInt(Rng& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<uint32_t>(hi - lo + 1));
}
/// A vector of two draws in [lo, hi), x drawn before y: two draws in one call's arguments, as in
/// Vec2(uniform(...), uniform(...)), come in an order the compiler picks (gcc right to left, clang
/// left to right), so every scene draws in separate statements to be the same under both.
inline Vec2 uniformVec(Rng& rng, double lo, double hi) {
  const double x = uniform(rng, lo, hi);
  const double y = uniform(rng, lo, hi);
  return Vec2(x, y);
}

/// The default mode's two time-ordered collision types.
inline const char* const kEventTypes[] = {"continuous-time", "hybrid"};

inline TestScene contactScene(const std::string& type, double cor, double dt = 0.01,
                              Failsafe failsafe = Failsafe::Projection, int maxIterations = 10) {
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = dt;
  s.scene.collision.type = test::collisionType(type);
  s.scene.collision.cor = cor;
  s.scene.collision.maxIterations = maxIterations;
  s.scene.collision.failsafe = failsafe;
  return s;
}

/// sleep: resting particles may sleep (HandlerOptions::sleep); zoneUpdatesPerRow > 0 starves
/// (or feeds) the failsafe's solves (HandlerOptions::zoneUpdatesPerRow); hold: budget-ended
/// solves hold the particles they brought to rest (HandlerOptions::hold).
inline std::unique_ptr<Simulator> defaultModeSimulator(const TestScene& s, bool sleep = true,
                                                       long zoneUpdatesPerRow = 0, bool hold = true) {
  std::unique_ptr<Simulator> sim;
  SimulatorOptions options;
  options.handler.compat = false;
  options.handler.sleep = sleep;
  options.handler.zoneUpdatesPerRow = zoneUpdatesPerRow;
  options.handler.hold = hold;
  const Status status = Simulator::create(s.scene, options, sim);
  EXPECT_TRUE(status.isOk()) << status.message();
  return sim;
}

/// Overlap depth of every pair at positions x (particle-particle, particle-capsule, particle-
/// half-plane), computed here from the geometry alone, independently of the simulator's checks.
/// `names` (optional) receives each pair's description.
inline std::vector<double> overlaps(const Scene& scene, const VecX& x, std::vector<std::string>* names = nullptr) {
  std::vector<double> d;
  const int n = scene.numParticles();
  auto segmentDistance = [](const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const double ee = e.squaredNorm();
    const double t = ee > 0 ? std::clamp((p - a).dot(e) / ee, 0.0, 1.0) : 0.0;
    return (a + t * e - p).norm();
  };
  auto name = [&](const char* kind, int i, int j) {
    if (names) names->push_back(std::string(kind) + " (" + std::to_string(i) + ", " + std::to_string(j) + ")");
  };
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      d.push_back(scene.radius[i] + scene.radius[j] - (at(x, j) - at(x, i)).norm());
      name("particle-particle", i, j);
    }
    for (size_t k = 0; k < scene.edges.size(); ++k) {
      const Edge& e = scene.edges[k];
      d.push_back(
          e.i == i || e.j == i ? -1.0 : scene.radius[i] + e.radius - segmentDistance(at(x, i), at(x, e.i), at(x, e.j)));
      name("particle-edge", i, static_cast<int>(k));
    }
    for (size_t k = 0; k < scene.halfplanes.size(); ++k) {
      const HalfPlane& h = scene.halfplanes[k];
      d.push_back(scene.radius[i] - (at(x, i) - h.point).dot(h.normal) / h.normal.norm());
      name("particle-half-plane", i, static_cast<int>(k));
    }
  }
  return d;
}

/// One step, which must succeed and leave nothing unresolved (promise 1, --verify's check), and
/// must not deepen any pair's overlap at the end of the step beyond rounding (checked here
/// independently of --verify, from positions alone).
inline ::testing::AssertionResult stepClean(Simulator& sim, TestScene& s) {
  const long k = s.state.step + 1;
  const std::vector<double> before = overlaps(s.scene, s.state.x);
  if (Status st = sim.step(s.scene, s.state); !st.isOk())
    return ::testing::AssertionFailure() << "step " << k << " failed: " << st.message();
  std::vector<std::string> names;
  const std::vector<double> after = overlaps(s.scene, s.state.x, &names);
  const double length = 1.0 + s.state.x.cwiseAbs().maxCoeff();
  for (size_t m = 0; m < after.size(); ++m)
    if (after[m] > std::max(before[m], 0.0) + 1e-9 * length)
      return ::testing::AssertionFailure() << "step " << k << ": " << names[m] << " ends " << after[m]
                                           << " deep (was " << before[m] << "); zones " << sim.stats().zones
                                           << ", rigid " << sim.stats().rigidZones;
  const auto left = sim.unresolved(s.scene, s.state, 4);
  if (!left.empty())
    return ::testing::AssertionFailure() << "step " << k << ": " << left.size() << " unresolved, first "
                                         << pairKindName(left[0].kind) << " (" << left[0].i << ", " << left[0].j
                                         << ") at tau " << left[0].tau;
  return ::testing::AssertionSuccess();
}

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Kinetic energy of the movable particles.
inline double kinetic(const TestScene& s, const VecX& v) {
  double e = 0;
  for (int i = 0; i < s.scene.numParticles(); ++i)
    if (!s.scene.isFixed(i)) e += 0.5 * s.scene.massOf(i) * at(v, i).squaredNorm();
  return e;
}
inline double kinetic(const TestScene& s) { return kinetic(s, s.state.v); }

inline Vec2 momentum(const TestScene& s) {
  Vec2 p = Vec2::Zero();
  for (int i = 0; i < s.scene.numParticles(); ++i) p += s.scene.massOf(i) * at(s.state.v, i);
  return p;
}
/// Sum of m |v|: the scale momentum errors are measured against (the total may be near zero).
inline double momentumScale(const TestScene& s) {
  double m = 0;
  for (int i = 0; i < s.scene.numParticles(); ++i) m += s.scene.massOf(i) * at(s.state.v, i).norm();
  return m;
}
/// Angular momentum about the origin.
inline double angularMomentum(const TestScene& s) {
  double l = 0;
  for (int i = 0; i < s.scene.numParticles(); ++i) l += s.scene.massOf(i) * cross(at(s.state.x, i), at(s.state.v, i));
  return l;
}
/// Sum of m |x| |v|: the scale angular momentum errors are measured against.
inline double angularScale(const TestScene& s) {
  double l = 0;
  for (int i = 0; i < s.scene.numParticles(); ++i)
    l += s.scene.massOf(i) * at(s.state.x, i).norm() * at(s.state.v, i).norm();
  return l;
}

/// Distance from point p to segment a-b.
inline double segmentDistance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * d)).norm();
}

}  // namespace fosssim::testing
