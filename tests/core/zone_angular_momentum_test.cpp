// Momentum and angular momentum through the failsafe's zones (contact_zones.h;
// ContactProjector::RowSource).
//
// A zone's contacts are rows n · (relative velocity) >= 0, each set at the instant its contact
// joined. An impulse keeps angular momentum only along the line through the contact at the
// instant it acts: for a disk pair, J n at x_i and -J n at x_j change L by (x_i - x_j) × J n,
// zero exactly when n is along x_i - x_j then. A later solve of the zone, at a later instant of
// the step, that changed an older row's multiplier pushed along the line of that older instant,
// which the disks had left. Rows are now made again at the instant of the solve that changes
// them, so every impulse acts along the line of its own instant.
//
// Momentum: a rigid zone's members are frozen in the projector (immovable, at their rigid
// velocities); a row set inside it with a warm start pushed the pair's other particle alone, and
// the next rigid move carried that push into the zone's momentum.
#include "contact_physics.h"

#include "fosssim/core/forces.h"

namespace fosssim::testing {
namespace {

// A pack of side x side disks of radius about 0.05 on a hexagonal grid with gaps of 0.5-10 mm,
// masses 0.5-2, velocities of 1 m/s in random directions plus a squeeze toward the pack's centre
// (2 /s), held together by their mutual gravitation (G = 0.05, every pair): no walls, no fixed
// particle, only forces between pairs, so momentum and angular momentum are the system's own and
// symplectic Euler keeps both (central pair forces, exact free flight). The pack collapses and
// stays a jostling clump: its contacts come at many instants of a step, and its zones are solved
// at each, merged, and (in some packs) moved rigidly. With `edges`, every third disk is joined to
// the next by an edge of radius 0.01.
TestScene freePack(int pack, bool edges) {
  const double speed = 1.0, squeeze = 2.0, G = 0.05, cors[] = {0.0, 0.5};
  const int side = 4 + pack % 8;
  Rng rng(9000 + pack);
  TestScene s = contactScene(kEventTypes[pack % 2], cors[(pack / 2) % 2]);
  const double r = 0.05, gap = uniform(rng, 0.0005, 0.01);
  const Vec2 centre((side - 1) * (r + gap / 2), (side - 1) * (r + gap / 2) * 0.87);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const Vec2 p((2 * r + gap) * i + (j % 2) * (r + gap / 2), (2 * r + gap) * 0.87 * j);
      const Vec2 v = uniformVec(rng, -1, 1);
      const double m = uniform(rng, 0.5, 2.0);
      addBody(s, m, p - centre, speed * v - squeeze * (p - centre), r * uniform(rng, 0.9, 1.0));
    }
  const int n = s.state.numParticles();
  if (edges)
    for (int k = 0; k + 1 < n; k += 3) s.scene.edges.push_back(Edge{k, k + 1, 0.01});
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) s.scene.forces.push_back(std::make_unique<GravitationalForce>(i, j, G));
  return s;
}

/// A pack's 60 steps: the largest drifts of momentum and angular momentum from their starts, over
/// their scales (sum m|v| and sum m|x||v| at the start), and the steps with zones, with rigid ones.
struct PackRun {
  double momentum = 0, angular = 0;
  int zoneSteps = 0, rigidSteps = 0;
};

PackRun runPack(int pack, bool edges) {
  TestScene s = freePack(pack, edges);
  SCOPED_TRACE(std::string(kEventTypes[pack % 2]) + " pack " + std::to_string(pack) + " of " +
               std::to_string(s.state.numParticles()) + " disks, COR " + std::to_string(s.scene.collision.cor));
  auto sim = defaultModeSimulator(s);
  const Vec2 p0 = momentum(s);
  const double l0 = angularMomentum(s), pScale = momentumScale(s), lScale = angularScale(s);
  PackRun run;
  for (int k = 0; k < 60; ++k) {
    EXPECT_TRUE(sim->step(s.scene, s.state).isOk()) << "step " << k + 1;
    run.zoneSteps += sim->stats().failsafeUsed;
    run.rigidSteps += sim->stats().rigidZones > 0;
    run.momentum = std::max(run.momentum, (momentum(s) - p0).norm() / pScale);
    run.angular = std::max(run.angular, std::abs(angularMomentum(s) - l0) / lScale);
  }
  return run;
}

// 40 free packs of 16 to 121 disks, COR 0 and 0.5 (at COR 1 impulses settle them and zones are
// rare), both time-ordered types, 60 steps: the zones run in at least 10 steps of every pack
// (checked), and momentum and angular momentum stay within 1e-12 and 1e-9 of their scales over
// the run (9.3e-16 measured). Each of the two mends fails it alone: with rows kept at the instant
// they were set, L moved by more than 1e-9 of its scale in 31 of the packs (up to 1.0e-4); with
// warm starts inside rigid zones, momentum moved in 17 packs (up to 15% of its scale).
TEST(ZoneAngularMomentum, FreePacksKeepMomentumAndAngularMomentum) {
  double worst = 0;
  int packsWithRigidZones = 0;
  for (int pack = 0; pack < 40; ++pack) {
    const PackRun run = runPack(pack, false);
    EXPECT_LE(run.momentum, 1e-12) << "pack " << pack;
    EXPECT_LE(run.angular, 1e-9) << "pack " << pack;
    EXPECT_GE(run.zoneSteps, 10) << "pack " << pack << ": the zones ran too seldom to test them";
    worst = std::max(worst, run.angular);
    packsWithRigidZones += run.rigidSteps > 0;
  }
  EXPECT_GE(packsWithRigidZones, 5) << "too few rigid zones to test their momentum";
  std::printf("[ packs    ] largest |dL| / scale %.3g; packs with rigid zones: %d\n", worst, packsWithRigidZones);
}

// The same packs threaded with short edges: momentum is kept as well (1e-12), angular momentum is
// not. A contact that does not close at its instant but deepens later (an edge rotating into a
// disk) has its row's normal where the overlap would be deepest (ContactZones::setRow): only that
// normal sees the approach, and it need not pass through the contact of now. Measured when this
// was written: L moved by more than 1e-9 of its scale in 30 of the 40 packs (up to 6.6e-3), and
// by 1.1e-15 at most with those rows given the normal of now instead (which lets such pairs
// overlap: ContactPhysicsRandom's packs with short edges).
TEST(ZoneAngularMomentum, FreePacksWithEdgesKeepMomentum) {
  for (int pack = 0; pack < 40; ++pack) {
    const PackRun run = runPack(pack, true);
    EXPECT_LE(run.momentum, 1e-12) << "pack " << pack;
    EXPECT_GE(run.zoneSteps, 10) << "pack " << pack << ": the zones ran too seldom to test them";
  }
}

}  // namespace
}  // namespace fosssim::testing
