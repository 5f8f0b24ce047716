// The failsafe's zones keep the scene's coefficient of restitution (contact_zones.h,
// ContactProjector::restitute). Hybrid handling with maxiters 0 sends every contact to the zones,
// so these scenes test the zones alone; expected values are Newton's law for one contact, worked
// by hand:
//   * two equal free disks head on at +-u: they leave at -+e u (momentum 0, kinetic energy e^2
//     of what came in);
//   * a disk onto a half-plane at speed u (no gravity): it leaves at e u, its tangential speed
//     kept;
//   * a disk resting on the floor under gravity (each step's kick closes its contact): resting
//     contact does not bounce, whatever the COR, as with impulses (kRestingBounceKicks).
// Before, the zones were inelastic whatever the COR: every one of these stopped its contact.
#include "contact_physics.h"

#include "fosssim/core/forces.h"

namespace fosssim::testing {
namespace {

constexpr int kZonesOnly = 0;  // hybrid maxiters 0: no impulse events, every contact to a zone

TEST(ZoneRestitution, AHeadOnPairLeavesAtETimesItsSpeed) {
  for (double e : {0.0, 0.5, 1.0}) {
    SCOPED_TRACE("COR " + std::to_string(e));
    TestScene s = contactScene("hybrid", e, 0.01, Failsafe::Projection, kZonesOnly);
    const double u = 2.0;
    addBody(s, 1.0, Vec2(-0.5, 0.0), Vec2(u, 0.0), 0.1);
    addBody(s, 1.0, Vec2(0.5, 0.0), Vec2(-u, 0.0), 0.1);
    auto sim = defaultModeSimulator(s);
    int zoneSteps = 0;
    for (int k = 0; k < 40; ++k) {  // they meet at t = 0.2
      ASSERT_TRUE(stepClean(*sim, s));
      zoneSteps += sim->stats().zones > 0;
    }
    EXPECT_GT(zoneSteps, 0);  // the contact was the zones'
    EXPECT_NEAR(s.state.v[0], -e * u, 1e-9);
    EXPECT_NEAR(s.state.v[2], e * u, 1e-9);
    EXPECT_NEAR(s.state.v[1], 0.0, 1e-12);
    EXPECT_NEAR(kinetic(s), e * e * u * u, 1e-9);
    EXPECT_NEAR(momentum(s).norm(), 0.0, 1e-12);
  }
}

TEST(ZoneRestitution, ADiskLeavesAHalfPlaneAtETimesItsNormalSpeed) {
  for (double e : {0.25, 0.5, 1.0}) {
    SCOPED_TRACE("COR " + std::to_string(e));
    TestScene s = contactScene("hybrid", e, 0.01, Failsafe::Projection, kZonesOnly);
    s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(0, 2)});  // not unit: normals need not be
    addBody(s, 2.0, Vec2(0.0, 1.0), Vec2(1.5, -3.0), 0.1);
    auto sim = defaultModeSimulator(s);
    for (int k = 0; k < 60; ++k) ASSERT_TRUE(stepClean(*sim, s));  // it lands at t = 0.3
    EXPECT_NEAR(s.state.v[0], 1.5, 1e-9);
    EXPECT_NEAR(s.state.v[1], 3.0 * e, 1e-9);
  }
}

// Under gravity a disk dropped onto the floor bounces at e times its landing speed, and the
// bounces die out: no zone re-launches a resting disk, so it comes to rest on the floor
// (its speed below one kick, g h, once its bounces are spent).
TEST(ZoneRestitution, ADroppedDiskBouncesThenRests) {
  const double g = 9.81, h = 0.01;
  TestScene s = contactScene("hybrid", 0.5, h, Failsafe::Projection, kZonesOnly);
  addFloorAndGravity(s, g);
  addBody(s, 1.0, Vec2(0.0, 0.3), Vec2(0.0, 0.0), 0.1);
  auto sim = defaultModeSimulator(s, /*sleep=*/false);
  double highest = 0.0;  // the highest the disk rises after its first landing
  bool landed = false;  // it has been on its way up (the floor is the only thing that can turn it)
  for (int k = 0; k < 300; ++k) {
    ASSERT_TRUE(stepClean(*sim, s));
    landed = landed || s.state.v[1] > 0.0;
    if (landed) highest = std::max(highest, s.state.x[1] - 0.1);
  }
  // It bounced (the zones kept some restitution: at COR 0.5 the first rebound rises to about a
  // quarter of the 0.2 m drop) ...
  EXPECT_GT(highest, 0.02);
  EXPECT_LT(highest, 0.2 * 0.25 * 1.2);
  // ... and rests at the end: on the floor, slower than a kick.
  EXPECT_NEAR(s.state.x[1], 0.1, 1e-6);
  EXPECT_LT(std::abs(s.state.v[1]), g * h);
}

}  // namespace
}  // namespace fosssim::testing
