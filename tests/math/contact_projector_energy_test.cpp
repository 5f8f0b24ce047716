// ContactProjector's energy guard (capEnergy): a warm start can add kinetic energy that only a
// solve takes back, and a solve that spends its budget may not have. The guard moves the
// multipliers and velocities changed since the last takeChanged back along their line until the
// energy is what it was, keeping the two consistent. Expected values are worked by hand on a
// head-on pair of unit masses, where KE along the line is a parabola in the multiplier.
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kExact = 1e-15;

// Bodies 0 and 1 (unit masses) close head on at 1 m/s each along x: KE = 1. With n = (1, 0)
// the row is n.(v1 - v0) >= 0 and an impulse lambda gives v0 = 1 - lambda, v1 = -1 + lambda, so
// KE(lambda) = (1 - lambda)^2: the projection is lambda = 1 (KE 0), and KE <= 1 for lambda in
// [0, 2].
ContactProjector headOnPair(double warmStart) {
  ContactProjector cp;
  cp.reset(2);
  cp.addBody(0, 1.0, Vec2(1, 0));
  cp.addBody(1, 1.0, Vec2(-1, 0));
  cp.addRow(pairRow(0, 1, Vec2(1, 0)), warmStart);
  return cp;
}

double kinetic(const ContactProjector& cp) {
  return 0.5 * (cp.velocity(0).squaredNorm() + cp.velocity(1).squaredNorm());
}

// A warm start of 3 leaves KE(3) = 4. The largest multiplier on the line back to 0 with KE <= 1
// is 2 (f = 2/3): the bodies part at their closing speed, and the row is queued again, so the
// next solve still projects (to lambda = 1, KE 0).
TEST(ContactProjectorEnergy, AWarmStartThatAddsEnergyIsTakenBackToTheStartingEnergy) {
  ContactProjector cp = headOnPair(3.0);
  ASSERT_DOUBLE_EQ(kinetic(cp), 4.0);
  EXPECT_NEAR(cp.capEnergy(), 2.0 / 3.0, kExact);
  EXPECT_NEAR(cp.impulse(0), 2.0, 4 * kExact);
  EXPECT_NEAR(cp.velocity(0).x(), -1.0, 4 * kExact);
  EXPECT_NEAR(cp.velocity(1).x(), 1.0, 4 * kExact);
  EXPECT_NEAR(kinetic(cp), 1.0, 8 * kExact);
  EXPECT_EQ(cp.queuedRows(), 1);
  EXPECT_TRUE(cp.solve(1.0, 1e-12, 100));
  EXPECT_NEAR(cp.impulse(0), 1.0, 1e-12);
  EXPECT_LE(kinetic(cp), 1e-20);
}

// A warm start of 0.5 loses energy (KE 0.25): the guard changes nothing, to the last bit.
TEST(ContactProjectorEnergy, ChangesThatLoseEnergyAreLeftAlone) {
  ContactProjector cp = headOnPair(0.5);
  const Vec2 v0 = cp.velocity(0), v1 = cp.velocity(1);
  EXPECT_EQ(cp.capEnergy(), 1.0);
  EXPECT_EQ(cp.impulse(0), 0.5);
  EXPECT_EQ(cp.velocity(0), v0);
  EXPECT_EQ(cp.velocity(1), v1);
}

// Bodies already parting (v0 = -1, v1 = 1) pushed further apart by a warm start: every change
// adds energy (B > 0), so all of it goes (f = 0), back to the velocities they had, multiplier 0.
TEST(ContactProjectorEnergy, ChangesThatOnlyAddEnergyAreUndone) {
  ContactProjector cp;
  cp.reset(2);
  cp.addBody(0, 1.0, Vec2(-1, 0));
  cp.addBody(1, 1.0, Vec2(1, 0));
  cp.addRow(pairRow(0, 1, Vec2(1, 0)), 3.0);
  EXPECT_EQ(cp.capEnergy(), 0.0);
  EXPECT_EQ(cp.impulse(0), 0.0);
  EXPECT_EQ(cp.velocity(0), Vec2(-1, 0));
  EXPECT_EQ(cp.velocity(1), Vec2(1, 0));
}

// The guard starts over at each takeChanged: energy added before it is not looked at again.
TEST(ContactProjectorEnergy, TheGuardLooksOnlyAtChangesSinceTheLastTakeChanged) {
  ContactProjector cp = headOnPair(3.0);
  std::vector<int> changed;
  cp.takeChanged(changed);
  EXPECT_EQ(changed.size(), 2u);
  EXPECT_EQ(cp.capEnergy(), 1.0);
  EXPECT_EQ(cp.impulse(0), 3.0);
}

// A row replaced after its warm start (setRow) keeps that impulse applied outside its multiplier:
// the guard scales it there, so the contact's total impulse (the next step's warm start) is
// still what the velocities carry: 2, with the multiplier of the new normal left at 0.
TEST(ContactProjectorEnergy, AReplacedRowsImpulseIsScaledInItsTotal) {
  ContactProjector cp = headOnPair(3.0);
  cp.setRow(0, pairRow(0, 1, Vec2(1, 0)));
  EXPECT_NEAR(cp.capEnergy(), 2.0 / 3.0, kExact);
  EXPECT_EQ(cp.impulse(0), 0.0);
  EXPECT_NEAR(cp.totalImpulse(0), 2.0, 4 * kExact);
  EXPECT_NEAR(cp.velocity(0).x(), -1.0, 4 * kExact);
}

// A body frozen after the warm start keeps the velocity freeze gave it; the guard weighs only the
// movable bodies: body 0 alone went from KE 1/2 (v = 1) to 2 (v = -2), and is brought back to
// v = -1 (multiplier 2), its starting energy.
TEST(ContactProjectorEnergy, AFrozenBodyKeepsTheVelocityFreezeGaveIt) {
  ContactProjector cp = headOnPair(3.0);
  cp.freeze(1, Vec2(0.25, 0));
  EXPECT_NEAR(cp.capEnergy(), 2.0 / 3.0, kExact);
  EXPECT_EQ(cp.velocity(1), Vec2(0.25, 0));
  EXPECT_NEAR(cp.velocity(0).x(), -1.0, 4 * kExact);
  EXPECT_NEAR(cp.impulse(0), 2.0, 4 * kExact);
}

// Random zones warm-started with random impulses (half of them far too large) and solved on a
// starved budget: before the guard many end above their starting energy; after it none does,
// and the velocities are still the starting ones plus what the multipliers apply (the guard moved
// both together), to rounding.
TEST(ContactProjectorEnergy, StarvedWarmStartedSolvesEndWithoutEnergyGain) {
  std::mt19937 rng(8675309);
  std::uniform_real_distribution<double> impulse(0.0, 4.0);
  int gained = 0, capped = 0;
  const int trials = 400;
  for (int trial = 0; trial < trials; ++trial) {
    const Zone z = randomZone(rng);
    ContactProjector cp;
    addBodies(cp, z);
    for (const ConstraintRow& r : z.rows) cp.addRow(r, impulse(rng));
    cp.solve(speedScale(z.v), 1e-12, 2);
    const double start = kineticEnergy(z.invMass, z.v);
    gained += kineticEnergy(z.invMass, velocities(cp, z.v.size())) > start * (1 + 1e-13);
    capped += cp.capEnergy() < 1.0;
    const std::vector<Vec2> v = velocities(cp, z.v.size());
    EXPECT_LE(kineticEnergy(z.invMass, v), start * (1 + 1e-12)) << "trial " << trial;
    std::vector<Vec2> carried = z.v;
    for (int k = 0; k < cp.rows(); ++k) {
      const ConstraintRow& r = z.rows[k];
      for (int m = 0; m < r.count; ++m) carried[r.body[m]] += z.invMass[r.body[m]] * cp.impulse(k) * r.coef[m];
    }
    double scale = 1.0;
    for (const Vec2& u : carried) scale = std::max(scale, u.norm());
    for (size_t b = 0; b < v.size(); ++b) EXPECT_LE((v[b] - carried[b]).norm(), 1e-12 * scale) << "trial " << trial;
  }
  EXPECT_GT(gained, trials / 10);  // the guard had work to do
  EXPECT_GE(capped, gained * 9 / 10);
}

}  // namespace
}  // namespace fosssim::math
