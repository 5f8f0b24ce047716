// ContactZones' bookkeeping (src/core/collision/contact_zones.h): zones that merge keep every
// member of both, and a zone that moves rigidly moves all of them and only them. Expected values
// come from mechanics, not from the code: the rigid projection (the velocities closest to the
// zone's in the kinetic-energy norm among rigid motions) keeps the zone's momentum and angular
// momentum, cannot add kinetic energy, and leaves a rigid velocity field, in which no two members
// move along the line between them.
#include "contact_physics.h"
#include "step_zones.h"

namespace fosssim::testing {
namespace {

// Two zones formed apart, then merged: disks 0-1 touching, and 2-3-4 touching in a zig-zag
// (every touching pair at distance 0.1, the radius sum), the two groups 0.2 apart with relative
// rates far too small to close that in a step, so neither zone takes in the other. A contact
// between disks 1 and 2 then merges two zones of several members each. With failsafe="rigid"
// the merged zone moves rigidly at once. A member lost in the merge would keep its own velocity
// and break the rigid field; disk 5, far away, is in no zone and keeps its velocity.
TEST(ContactZones, TwoZonesMergedMoveRigidlyAsOne) {
  TestScene s = contactScene("hybrid", 0.0, 0.01, Failsafe::Rigid, /*maxIterations=*/0);
  const Vec2 x[6] = {{0.0, 0.0}, {0.06, 0.08}, {0.26, 0.08}, {0.32, 0.16}, {0.38, 0.08}, {3.0, 3.0}};
  const Vec2 v0[6] = {{1.0, 0.0}, {0.0, 0.5}, {-0.3, 0.2}, {0.0, -1.0}, {0.7, 0.1}, {0.0, 1.0}};
  const double m[6] = {1.0, 2.0, 1.5, 1.0, 3.0, 1.0};
  for (int k = 0; k < 6; ++k) addBody(s, m[k], x[k], v0[k], 0.05);
  const double h = s.scene.dt;
  StepZones step(s, kZoneUpdatesPerRow, /*hold=*/false);
  ContactZones& zones = step.zones;
  zones.setRigidOnly(true);

  const int left = zones.absorb(s.scene, step.motion, step.candidates, particlePairKey(0, 1), 0.0, h);
  const int right = zones.absorb(s.scene, step.motion, step.candidates, particlePairKey(2, 3), 0.0, h);
  ASSERT_GE(left, 0);
  ASSERT_GE(right, 0);
  EXPECT_EQ(zones.zoneOf(1), zones.zoneOf(0));
  EXPECT_EQ(zones.zoneOf(4), zones.zoneOf(2)) << "disk 4 touches disk 3: near";
  EXPECT_NE(zones.zoneOf(2), zones.zoneOf(0)) << "0.2 apart: not near";
  const int merged = zones.absorb(s.scene, step.motion, step.candidates, particlePairKey(1, 2), 0.0, h);
  for (int k = 0; k < 5; ++k) EXPECT_EQ(zones.zoneOf(k), merged) << "disk " << k;
  EXPECT_EQ(zones.zoneOf(5), -1);

  VecX v = s.state.v;
  std::vector<int> changed;
  StepStats stats;
  zones.resolve(s.scene, step.motion, step.candidates, merged, 0.0, h, v, changed, stats);
  ASSERT_TRUE(zones.isRigid(merged));

  // Over all six disks (disk 5 is checked to keep its velocity below).
  const Vec2 p0 = momentum(s);
  const double l0 = angularMomentum(s), e0 = kinetic(s);
  s.state.v = v;
  EXPECT_NEAR((momentum(s) - p0).norm(), 0.0, 1e-13);
  EXPECT_NEAR(angularMomentum(s), l0, 1e-13);
  EXPECT_LT(kinetic(s), e0) << "the members' motions were not rigid to begin with";
  for (int a = 0; a < 5; ++a)
    for (int b = a + 1; b < 5; ++b)
      EXPECT_NEAR((at(v, a) - at(v, b)).dot(x[a] - x[b]), 0.0, 1e-14) << "disks " << a << ", " << b;
  EXPECT_EQ(at(v, 5), v0[5]);

  StepStats sizes;
  zones.sizes(sizes);
  EXPECT_EQ(sizes.zones, 1);
  EXPECT_EQ(sizes.rigidZones, 1);
  EXPECT_EQ(sizes.zoneParticles, 5);
  EXPECT_EQ(sizes.largestZone, 5);
}

}  // namespace
}  // namespace fosssim::testing
