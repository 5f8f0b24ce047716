// ContactProjector's welds and locks, the failsafe's answer to a jammed contact
// (core/collision/zone_stops.cpp): a weld makes two bodies one, a lock takes a body's freedom
// along one direction. Both are checked against the exact projection (projectByEnumeration) of a
// system built independently: the welded bodies as one body of both masses at their momentum's
// velocity, the locked body's coefficients and velocity cut to its free direction.
#include "fosssim/math/contact_projector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>
#include <vector>

#include "projector_helpers.h"
#include "random_zones.h"

namespace fosssim::math {
namespace {

using namespace testing;  // random_zones.h, projector_helpers.h

constexpr double kTol = 1e-12;
constexpr long kBudget = 1000000;

Vec2 perp(const Vec2& a) { return Vec2(-a.y(), a.x()); }

// Two distinct movable bodies of zone z, or false if it has fewer.
bool pickTwoMovable(std::mt19937& rng, const Zone& z, int& a, int& b) {
  std::vector<int> movable;
  for (size_t k = 0; k < z.v.size(); ++k)
    if (z.invMass[k] != 0.0) movable.push_back(static_cast<int>(k));
  if (movable.size() < 2) return false;
  std::shuffle(movable.begin(), movable.end(), rng);
  a = movable[0], b = movable[1];
  return true;
}

// Zone z with body a merged into body b: b has both masses and their momentum's velocity, a has
// no freedom and no row (its entries are b's).
Zone merged(const Zone& z, int a, int b) {
  Zone m = z;
  const double ma = 1.0 / z.invMass[a], mb = 1.0 / z.invMass[b];
  m.v[b] = (ma * z.v[a] + mb * z.v[b]) / (ma + mb);
  m.invMass[b] = 1.0 / (ma + mb);
  m.invMass[a] = 0.0;
  for (ConstraintRow& r : m.rows)
    for (int j = 0; j < r.count; ++j)
      if (r.body[j] == a) r.body[j] = b;
  m.v[a] = m.v[b];
  return m;
}

// The random-zone tests' count: zones compared with the enumeration, and zones whose solve stalled
// (like any random zone, a few are over-constrained where Gauss-Seidel stalls: zone_projection.h).
struct Tally {
  int compared = 0, stalled = 0;
  ~Tally() {
    EXPECT_GE(compared, 150);
    EXPECT_LE(stalled, 12) << "of 400";
    std::printf("[ zones    ] %d compared with the enumeration, %d stalled\n", compared, stalled);
  }
};

// The projector's velocities against the exact projection of `reference` (if the enumeration
// finds it); body `alias`, if any, is one body with body `of` (a weld).
void expectProjection(const ContactProjector& cp, const Zone& reference, double scale, int trial, Tally& tally,
                      int alias = -1, int of = -1) {
  std::vector<Vec2> want = reference.v;
  if (!projectByEnumeration(reference.invMass, reference.rows, want)) return;
  if (alias >= 0) want[alias] = want[of];
  ++tally.compared;
  const std::vector<Vec2> got = velocities(cp, want.size());
  for (size_t k = 0; k < want.size(); ++k)
    EXPECT_LE((got[k] - want[k]).norm(), 1e-7 * std::max(scale, 1e-300)) << "trial " << trial << " body " << k;
}

// Welded before the rows come, or after they were added and solved (their multipliers then carry
// the velocities the weld merges): either way the solve ends at the projection of the merged
// system, which the enumeration computes from scratch.
TEST(ContactProjectorWelds, AWeldedPairSolvesAsOneBodyOfBothMasses) {
  std::mt19937 rng(4242);
  ContactProjector cp;
  Tally tally;
  for (int trial = 0; trial < 400; ++trial) {
    const Zone z = randomZone(rng);
    int a = 0, b = 0;
    if (!pickTwoMovable(rng, z, a, b)) continue;
    const bool late = trial % 2 == 1;
    addBodies(cp, z);
    if (!late) cp.weld(a, b);
    for (const ConstraintRow& r : z.rows) cp.addRow(r);
    const double scale = speedScale(z.v);
    if (late) {
      cp.solve(scale, kTol, kBudget);
      cp.weld(a, b);
    }
    if (cp.solve(scale, kTol, kBudget)) expectProjection(cp, merged(z, a, b), scale, trial, tally, a, b);
    else ++tally.stalled;
  }
}

// The weld alone: the pair's momentum is kept, its kinetic energy does not grow, their own contact
// (a pair row, or an edge row whose three bodies are all welded, whose coefficients cancel only to
// rounding) has no coefficient left, and both bodies are listed as changed.
TEST(ContactProjectorWelds, AWeldKeepsMomentumAndItsOwnContactCannotClose) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-1.0, 1.0), mass(0.1, 10.0), alpha(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<double> invMass = {1.0 / mass(rng), 1.0 / mass(rng), 1.0 / mass(rng)};
    // Braced Vec2s: x is drawn before y under every compiler (a call's arguments come in an order
    // the compiler picks: gcc right to left, clang left to right).
    const std::vector<Vec2> v = {Vec2{u(rng), u(rng)}, Vec2{u(rng), u(rng)}, Vec2{u(rng), u(rng)}};
    ContactProjector cp;
    cp.reset(3);
    for (int k = 0; k < 3; ++k) cp.addBody(k, invMass[k], v[k]);
    const Vec2 n = unit(6.283185307179586 * alpha(rng));
    const int pair = cp.addRow(pairRow(0, 1, n));
    const int edge = cp.addRow(edgeRow(2, 0, 1, alpha(rng), n));
    std::vector<int> changed;
    cp.takeChanged(changed);
    const Vec2 p0 = v[0] / invMass[0] + v[1] / invMass[1] + v[2] / invMass[2];
    const double e0 = kineticEnergy(invMass, v);
    cp.weld(0, 1);
    cp.weld(2, 1);
    const std::vector<Vec2> after = velocities(cp, 3);
    const Vec2 p1 = (after[0] / invMass[0] + after[1] / invMass[1] + after[2] / invMass[2]);
    EXPECT_LE((p1 - p0).norm(), 1e-14 * (p0.norm() + 1.0)) << "trial " << trial;
    EXPECT_LE(kineticEnergy(invMass, after), e0 * (1.0 + 1e-14)) << "trial " << trial;
    EXPECT_EQ(after[0], after[1]);
    EXPECT_EQ(after[2], after[1]);
    EXPECT_EQ(cp.coefficientOn(pair, 0), Vec2::Zero()) << "trial " << trial;
    EXPECT_EQ(cp.coefficientOn(edge, 2), Vec2::Zero()) << "trial " << trial;
    changed.clear();
    cp.takeChanged(changed);
    EXPECT_EQ(std::set<int>(changed.begin(), changed.end()), (std::set<int>{0, 1, 2})) << "trial " << trial;
    EXPECT_TRUE(cp.solve(speedScale(v), kTol, kBudget));
    EXPECT_EQ(cp.velocity(0), after[0]) << "nothing left to solve: the rows are the pair's own";
  }
}

// Locked along g, a body moves only across g from then on, whatever the rows push, and the solve
// ends at the projection of the system whose body has only that freedom: its velocity and its
// coefficients cut to the free direction (the enumeration's system, built here).
TEST(ContactProjectorWelds, ALockedBodyMovesOnlyAcrossItsLock) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
  ContactProjector cp;
  Tally tally;
  for (int trial = 0; trial < 400; ++trial) {
    const Zone z = randomZone(rng);
    int b = 0, other = 0;
    if (!pickTwoMovable(rng, z, b, other)) continue;
    const Vec2 g = 3.0 * unit(angle(rng)), t = perp(g).normalized();
    addBodies(cp, z);
    for (const ConstraintRow& r : z.rows) cp.addRow(r);
    const double scale = speedScale(z.v);
    if (trial % 2 == 1) cp.solve(scale, kTol, 3);  // locked in the middle of a solve
    const double before = kineticEnergy(z.invMass, velocities(cp, z.v.size()));
    EXPECT_EQ(cp.lock(b, g), ContactProjector::Lock::Added);
    EXPECT_LE(std::abs(cp.velocity(b).dot(g)), 1e-14 * g.norm() * (scale + 1e-300)) << "trial " << trial;
    EXPECT_LE(kineticEnergy(z.invMass, velocities(cp, z.v.size())), before * (1.0 + 1e-14)) << "trial " << trial;
    const bool solved = cp.solve(scale, kTol, kBudget);
    EXPECT_LE(std::abs(cp.velocity(b).dot(g)), 1e-12 * g.norm() * (scale + 1e-300)) << "trial " << trial;
    if (!solved) {
      ++tally.stalled;
      continue;
    }
    Zone cut = z;
    cut.v[b] = t.dot(z.v[b]) * t;
    for (ConstraintRow& r : cut.rows)
      for (int j = 0; j < r.count; ++j)
        if (r.body[j] == b) r.coef[j] = t.dot(r.coef[j]) * t;
    expectProjection(cp, cut, scale, trial, tally);
  }
}

// A second lock along the first changes nothing; one across it leaves no freedom: the body is
// frozen at rest (an obstacle, immovable) and lock says so.
TEST(ContactProjectorWelds, ASecondLockAcrossTheFirstStopsTheBody) {
  ContactProjector cp;
  cp.reset(2);
  cp.addBody(0, 1.0, Vec2(1.0, -0.5));
  cp.addBody(1, 0.5, Vec2(0.0, 0.0));
  using Lock = ContactProjector::Lock;
  EXPECT_EQ(cp.lock(0, Vec2(0.0, 2.0)), Lock::Added);  // a floor: it slides along x
  EXPECT_EQ(cp.velocity(0), Vec2(1.0, 0.0));
  EXPECT_EQ(cp.lock(0, Vec2(0.0, -1.0)), Lock::Unchanged);  // the same line: nothing more
  EXPECT_EQ(cp.lock(0, Vec2::Zero()), Lock::Unchanged);
  EXPECT_EQ(cp.velocity(0), Vec2(1.0, 0.0));
  EXPECT_TRUE(cp.movable(0));
  EXPECT_EQ(cp.lock(0, Vec2(1.0, 1.0)), Lock::Frozen);  // a wall across it
  EXPECT_FALSE(cp.movable(0));
  EXPECT_EQ(cp.velocity(0), Vec2::Zero());
  EXPECT_TRUE(cp.movable(1));
  EXPECT_EQ(cp.lock(0, Vec2(0.0, 1.0)), Lock::Unchanged) << "frozen: nothing left to lock";
}

// A weld keeps the locks of both sides: welded to a body locked along a floor's normal, a free
// body slides with it; welded to a body locked across, the pair has no freedom left.
TEST(ContactProjectorWelds, AWeldKeepsTheLocksOfBothSides) {
  for (const bool lockedIsFirst : {true, false}) {
    ContactProjector cp;
    cp.reset(3);
    cp.addBody(0, 1.0, Vec2(1.0, -1.0));
    cp.addBody(1, 1.0, Vec2(3.0, 1.0));
    cp.addBody(2, 1.0, Vec2(0.0, 0.0));
    EXPECT_EQ(cp.lock(0, Vec2(0.0, 1.0)), ContactProjector::Lock::Added);
    if (lockedIsFirst) cp.weld(0, 1);
    else cp.weld(1, 0);
    EXPECT_EQ(cp.velocity(0), cp.velocity(1));
    EXPECT_NEAR(cp.velocity(1).x(), 2.0, 1e-15) << "their momentum along the free direction: (1 + 3) / 2";
    EXPECT_EQ(cp.velocity(1).y(), 0.0);
    EXPECT_TRUE(cp.movable(1));
    EXPECT_EQ(cp.lock(2, Vec2(1.0, 0.0)), ContactProjector::Lock::Added);
    EXPECT_FALSE(cp.sameBody(2, 1));
    cp.weld(2, 1);
    EXPECT_TRUE(cp.sameBody(2, 0));  // locked along y and along x: at rest
    EXPECT_FALSE(cp.movable(0));
    EXPECT_EQ(cp.velocity(2), Vec2::Zero());
  }
}

}  // namespace
}  // namespace fosssim::math
