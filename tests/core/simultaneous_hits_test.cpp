// Hits of one instant answered together (src/core/collision/simultaneous_hits.cpp): what comes
// out does not depend on how the particles are numbered, symmetric scenes stay symmetric, and
// Moreau's law keeps momenta and never gains energy. Expected values come from the hand
// derivation below, not from the simulator.
#include "contact_physics.h"

#include <array>
#include <numeric>

namespace fosssim::testing {
namespace {

/// The scene with its particles numbered in `order` (order[k]: the original index of the new
/// particle k). Scenes here have no edges, so nothing else names a particle.
TestScene renumbered(const TestScene& s, const std::vector<int>& order, const std::string& type, double cor) {
  TestScene r = contactScene(type, cor);
  for (int i : order)
    addBody(r, s.scene.massOf(i), at(s.state.x, i), at(s.state.v, i), s.scene.radius[i], s.scene.isFixed(i));
  return r;
}

// A disk falling at u onto two touching disks of its size, straight onto the gap between them,
// without gravity: it meets both at once, where the three centres make an equilateral triangle.
// From the falling disk c to the disks a (left) and b (right) the normals are
//   n_a = (-1/2, -s), n_b = (1/2, -s), s = sqrt(3)/2, with n_a . n_b = 1/2.
// Rows n . (v_other - v_c) >= 0, unit masses: the Delassus matrix is [[2, 1/2], [1/2, 2]], and
// each row starts at -n . v_c = -s u. By symmetry both multipliers are equal, (2 + 1/2) l = s u,
// l = 2 s u / 5, and the inelastic projection moves c by -l (n_a + n_b) = (0, 2 s l) = (0, 3u/5)
// and a by l n_a. Moreau's law multiplies these changes by 1 + e:
//   v_c = (0, -u + (1 + e) 3u/5),   v_a = (1 + e) (2 s u / 5) n_a,   v_b its mirror image.
// At e = 1: |v_c|^2 + 2 |v_a|^2 = u^2/25 + 2 (12/25) u^2 = u^2, kinetic energy kept. In pair
// order the first disk met took the first impulse alone, and c left sideways (0.88 m/s from a
// 3.9 m/s fall on a floor, COR 0.5), on the side the numbering chose.
TEST(SimultaneousHits, ADiskDroppedOntoTwoLeavesThemMirroredWhateverTheNumbering) {
  const double r = 0.1, u = 4.0, s = std::sqrt(3.0) / 2;
  for (const char* type : kEventTypes)
    for (double cor : {0.0, 0.5, 1.0}) {
      TestScene base = contactScene(type, cor);
      addBody(base, 1.0, Vec2(-r, 0), Vec2::Zero(), r);                  // a
      addBody(base, 1.0, Vec2(r, 0), Vec2::Zero(), r);                   // b
      addBody(base, 1.0, Vec2(0, 2 * s * r + 0.3 * u * 0.01), Vec2(0, -u), r);  // c: the hit at 0.3 of step 1
      const Vec2 na(-0.5, -s), nb(0.5, -s);
      const std::array<Vec2, 3> want = {(1 + cor) * (2 * s * u / 5) * na, (1 + cor) * (2 * s * u / 5) * nb,
                                        Vec2(0, -u + (1 + cor) * 3 * u / 5)};
      std::vector<int> order = {0, 1, 2};
      do {
        SCOPED_TRACE(std::string(type) + " COR " + std::to_string(cor) + " order " + std::to_string(order[0]) +
                     std::to_string(order[1]) + std::to_string(order[2]));
        TestScene t = renumbered(base, order, type, cor);
        auto sim = defaultModeSimulator(t);
        ASSERT_TRUE(stepClean(*sim, t));
        for (int k = 0; k < 3; ++k)
          EXPECT_LT((at(t.state.v, k) - want[order[k]]).norm(), 1e-12 * u) << "disk " << order[k];
      } while (std::next_permutation(order.begin(), order.end()));
    }
}

// The touching rack of contact_physics_test.cpp (a cue disk on the axis into 15 disks whose rows
// are centred on it) is symmetric about the x axis, so its break must be too: every disk moves as
// its mirror image moves, at every step.
TEST(SimultaneousHits, TheTouchingRackBreaksSymmetricAboutItsAxis) {
  const double r = 0.1, d = 2 * r + 1e-12;
  for (const char* type : kEventTypes)
    for (double cor : {0.5, 1.0}) {
      SCOPED_TRACE(std::string(type) + " COR " + std::to_string(cor));
      TestScene s = contactScene(type, cor);
      std::vector<int> mirror = {0};  // the cue is its own image
      addBody(s, 1.0, Vec2(-1, 0), Vec2(5, 0), r);
      for (int row = 0, first = 1; row < 5; first += ++row)
        for (int j = 0; j <= row; ++j) {
          addBody(s, 1.0, Vec2(row * d * std::sqrt(3.0) / 2, (j - row / 2.0) * d), Vec2::Zero(), r);
          mirror.push_back(first + row - j);
        }
      auto sim = defaultModeSimulator(s);
      double moved = 0;  // the largest speed of the rack's last row
      for (int k = 0; k < 60; ++k) {
        ASSERT_TRUE(stepClean(*sim, s));
        for (int i = 0; i < s.scene.numParticles(); ++i) {
          const Vec2 v = at(s.state.v, i), image = at(s.state.v, mirror[i]);
          ASSERT_LT((v - Vec2(image.x(), -image.y())).norm(), 1e-9 * 5) << "step " << k + 1 << " disk " << i;
          const Vec2 x = at(s.state.x, i), xImage = at(s.state.x, mirror[i]);
          ASSERT_LT((x - Vec2(xImage.x(), -xImage.y())).norm(), 1e-9) << "step " << k + 1 << " disk " << i;
        }
      }
      for (int i = 11; i < 16; ++i) moved = std::max(moved, at(s.state.v, i).norm());
      EXPECT_GT(moved, 0.1) << "the cue's momentum should reach the rack's last row";
    }
}

// Random disks hit at one instant: a disk falling on pairs of disks placed as mirror images about
// its path (so it meets both of a pair at the same instant, whatever their masses), of random
// sizes, masses and CORs, some of them fixed. The run must not depend on the numbering (three
// random orders each), must keep momentum (no fixed disk) and angular momentum, and must never
// gain kinetic energy (COR <= 1); at COR 1 with no fixed disk it keeps it (Moreau's law:
// |v+|^2 = |P v|^2 + e^2 |v - P v|^2).
TEST(SimultaneousHits, RandomSimultaneousHitsDoNotDependOnTheNumberingAndGainNoEnergy) {
  Rng rng(20261207);
  int runs = 0, tied = 0;  // tied: runs whose first step answered two contacts or more
  for (int trial = 0; trial < 120; ++trial) {
    const char* type = kEventTypes[trial % 2];
    const double cor = std::array<double, 4>{0.0, 0.3, 0.7, 1.0}[uniformInt(rng, 0, 3)];
    const double r0 = 0.1, u = uniform(rng, 1.0, 10.0), dt = 0.01;
    const Vec2 hit(0, 1);  // the falling disk's centre at the instant it meets the pairs
    const double tau = uniform(rng, 0.2, 0.8);
    const double m0 = uniform(rng, 0.5, 3.0);
    TestScene base = contactScene(type, cor);  // the scene as drawn, never stepped
    addBody(base, m0, hit + Vec2(0, tau * u * dt), Vec2(0, -u), r0);
    const int pairs = uniformInt(rng, 1, 2);
    bool anyFixed = false;
    for (int p = 0; p < pairs; ++p) {
      const double rp = uniform(rng, 0.5, 1.5) * r0;
      const double angle = uniform(rng, 0.3, 1.3);
      const Vec2 c = hit + (r0 + rp) * Vec2(std::sin(angle), -std::cos(angle));
      bool clear = c.x() >= rp * (1 + 1e-9);  // the pair's two disks apart
      for (int q = 1; q < base.scene.numParticles(); ++q) {
        const Vec2 xq = at(base.state.x, q);
        const double reach = (rp + base.scene.radius[q]) * (1 + 1e-9);
        clear = clear && (c - xq).norm() > reach && (Vec2(-c.x(), c.y()) - xq).norm() > reach;
      }
      if (!clear) continue;
      for (double side : {1.0, -1.0}) {
        const bool fixed = uniformInt(rng, 0, 5) == 0;
        const double m = uniform(rng, 0.5, 3.0);
        anyFixed = anyFixed || fixed;
        addBody(base, m, Vec2(side * c.x(), c.y()), Vec2::Zero(), rp, fixed);
      }
    }
    const int n = base.scene.numParticles();
    if (n == 1) continue;
    SCOPED_TRACE("trial " + std::to_string(trial) + " " + type + " COR " + std::to_string(cor));
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    TestScene s = renumbered(base, order, type, cor);
    auto sim = defaultModeSimulator(s);
    const Vec2 p0 = momentum(s);
    const double l0 = angularMomentum(s), e0 = kinetic(s), pScale = momentumScale(s);
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      if (k == 0) tied += sim->stats().collisions >= 2;
    }
    ++runs;
    EXPECT_LE(kinetic(s), e0 * (1 + 1e-12));
    if (!anyFixed) {
      EXPECT_LE((momentum(s) - p0).norm(), 1e-12 * pScale);
      EXPECT_LE(std::abs(angularMomentum(s) - l0), 1e-9 * angularScale(s));
      if (cor == 1.0) {
        EXPECT_NEAR(kinetic(s), e0, 1e-12 * e0);
      }
    }
    for (int shuffle = 0; shuffle < 3; ++shuffle) {
      for (int k = n - 1; k > 0; --k) {
        const int other = uniformInt(rng, 0, k);
        std::swap(order[k], order[other]);
      }
      TestScene t = renumbered(base, order, type, cor);
      auto other = defaultModeSimulator(t);
      for (int k = 0; k < 3; ++k) ASSERT_TRUE(stepClean(*other, t));
      for (int k = 0; k < n; ++k) {
        EXPECT_LT((at(t.state.v, k) - at(s.state.v, order[k])).norm(), 1e-9 * u) << "disk " << order[k];
        EXPECT_LT((at(t.state.x, k) - at(s.state.x, order[k])).norm(), 1e-9) << "disk " << order[k];
      }
    }
  }
  EXPECT_GT(runs, 80);
  EXPECT_GT(2 * tied, runs) << "most runs should meet two disks at one instant";
}

}  // namespace
}  // namespace fosssim::testing
