// The default mode's failsafe on a pile poured under gravity: the pile flows into its V instead of
// freezing above it (the projection failsafe), and the rigid failsafe, asked for, still leaves
// every step collision-free. Each step must leave nothing unresolved (stepClean).
#include "contact_physics.h"

#include "fosssim/core/forces.h"

#include <cmath>
#include <cstdio>

namespace fosssim::testing {
namespace {

// 6b / 8. A pile of 60 disks (radius 0.05) poured from a column into a V of two half-planes
// (walls y = |x|) under gravity, COR 0.5.
struct PileResult {
  double frozenCom = 0;     // centre-of-mass height had the column frozen at its first contact
  double finalCom = 0;      // centre-of-mass height after the last step
  double comAt100 = 0;      // ... after 100 steps
  double movingLanded = 1;  // least fraction of landed disks moving > 0.05 m/s while half to all
                            // of the disks have landed (the others still falling)
  int failsafeSteps = 0;
  int rigidZoneSteps = 0;   // steps in which some zone fell back to rigid motion
};

PileResult pourPile(const char* type, Failsafe failsafe, int steps) {
  constexpr int kRows = 10, kCols = 6;
  const double r = 0.05, h = 0.01;
  const Vec2 g(0, -9.81);
  TestScene s = contactScene(type, 0.5, h, failsafe);
  for (int row = 0; row < kRows; ++row)
    for (int col = 0; col < kCols; ++col)
      addBody(s, 1.0, Vec2(-0.3 + 0.12 * col + (row % 2 ? 0.007 : -0.004), 0.6 + 0.15 * row), Vec2::Zero(), r);
  const Vec2 normals[] = {Vec2(1, 1), Vec2(-1, 1)};
  for (const Vec2& n : normals) s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), n});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(g));
  const int n = s.state.numParticles();
  auto sim = defaultModeSimulator(s);
  auto com = [&] {
    double y = 0;
    for (int i = 0; i < n; ++i) y += s.state.x[2 * i + 1];
    return y / n;
  };
  PileResult out;
  // Frozen at first contact: the whole column dropped rigidly until its first disk meets a wall.
  double drop = 1e300;
  for (int i = 0; i < n; ++i)
    for (const Vec2& w : normals)
      drop = std::min(drop, (w.normalized().dot(at(s.state.x, i)) - r) / w.normalized().y());
  out.frozenCom = com() - drop;
  std::vector<char> landed(n, 0);
  for (int k = 0; k < steps; ++k) {
    VecX predicted = s.state.v;
    for (int i = 0; i < n; ++i) at(predicted, i) += h * g;
    EXPECT_TRUE(stepClean(*sim, s));
    if (::testing::Test::HasFatalFailure() || ::testing::Test::HasNonfatalFailure()) return out;
    // Energy: no response raises the kinetic energy of the integrator's prediction v + h g.
    EXPECT_LE(kinetic(s), kinetic(s, predicted) * (1 + 1e-12)) << "step " << k + 1;
    const StepStats& st = sim->stats();
    out.failsafeSteps += st.failsafeUsed;
    out.rigidZoneSteps += st.rigidZones > 0;
    if (st.failsafeUsed) {
      EXPECT_TRUE(st.zones >= 1 && st.largestZone >= 1) << "step " << k + 1;
    }
    for (const Impulse& im : sim->log().impulses) {
      landed[im.i] = 1;
      if (im.kind == PairKind::ParticleParticle) landed[im.j] = 1;
    }
    // Landed: took an impulse, or touches a wall or another disk (a disk that settles on the pile
    // inside a failsafe zone may never take an impulse of its own), to within 1% of its radius: a
    // disk the zones held at rest may stay a few 10^-3 of its radius off its supports (one came to
    // rest, and slept, 2 10^-3 r off a wall and a disk, and so never counted as landed at 10^-3 r).
    auto touching = [&](int i) {
      for (const Vec2& w : normals)
        if (w.normalized().dot(at(s.state.x, i)) - r <= 1e-2 * r) return true;
      for (int j = 0; j < n; ++j)
        if (j != i && (at(s.state.x, j) - at(s.state.x, i)).norm() - 2 * r <= 1e-2 * r) return true;
      return false;
    };
    for (int i = 0; i < n; ++i) {
      landed[i] = landed[i] || sim->zoneOf(i) >= 0 || touching(i);
      for (const Vec2& w : normals)
        EXPECT_GE(w.normalized().dot(at(s.state.x, i)), r - 1e-9) << "disk " << i << " step " << k + 1;
    }
    int count = 0, moving = 0;
    for (int i = 0; i < n; ++i)
      if (landed[i]) ++count, moving += at(s.state.v, i).norm() > 0.05;
    if (2 * count >= n && count < n) out.movingLanded = std::min(out.movingLanded, double(moving) / count);
    if (k + 1 == 100) out.comAt100 = com();
  }
  out.finalCom = com();
  return out;
}

// "Flows" is measured three ways: (1) at every step from when half of the disks have landed (taken
// an impulse or joined a rigid zone) until the last one lands, some landed disks still move faster
// than 0.05 m/s (a failsafe that freezes zones touching a wall stops them); (2) the centre of mass keeps descending
// (lower at step 300 than at step 100); (3) it ends below a geometric bound: the 60 disks (area 60 pi r^2) filling the
// V (area H^2 up to height H) at a packing fraction of only 0.5 have centres no higher than r sqrt(2) + 2H/3 on
// average, far below 'frozenCom', the column stopped rigidly at its first contact (the old failsafe's rigid block
// standing above the V).
TEST(ContactPhysicsPile, PileFlowsIntoTheV) {
  const double H = std::sqrt(60 * std::acos(-1.0) * 0.05 * 0.05 / 0.5), packedBound = 0.05 * std::sqrt(2.0) + 2 * H / 3;
  for (const char* type : {"hybrid"}) {
    SCOPED_TRACE(type);
    const PileResult p = pourPile(type, Failsafe::Projection, 300);
    ASSERT_FALSE(HasFailure());
    EXPECT_GT(p.movingLanded, 0.0);
    EXPECT_LT(p.finalCom, p.comAt100);
    EXPECT_LT(packedBound, p.frozenCom);
    EXPECT_LT(p.finalCom, packedBound) << "frozen-at-contact height " << p.frozenCom;
    std::printf(
        "[ pile     ] %s: failsafe in %d steps, rigid zones in %d, landed moving %.2f, COM %.3f (step 100 %.3f, bound "
        "%.3f, frozen %.3f)\n",
        type, p.failsafeSteps, p.rigidZoneSteps, p.movingLanded, p.finalCom, p.comAt100, packedBound, p.frozenCom);
  }
}

// 8. The rigid failsafe (rigid impact zones at once) must keep the same pile collision-free at
// every step too (pourPile checks stepClean, the walls and the energy of every step); 150 steps.
TEST(ContactPhysicsPile, RigidFailsafeKeepsPileCollisionFree) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    const PileResult p = pourPile(type, Failsafe::Rigid, 150);
    std::printf("[ pile     ] %s rigid: failsafe in %d steps, COM %.3f\n", type, p.failsafeSteps, p.finalCom);
  }
}

}  // namespace
}  // namespace fosssim::testing
