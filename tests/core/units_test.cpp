// A scene's units do not change its motion (the default mode's promise: "results that do not depend
// on the scene's units"). Every quantity of a scene is given in the same three units of length, mass
// and time; multiplying them by L, M and T, with the scene's numbers converted accordingly, must give
// the same motion expressed in the new units. When L, M and T are powers of two (even ones, so that
// square roots scale exactly too), every floating-point operation of a step is the unit run's scaled
// by a power of two, which rounds identically: so the scaled run must reproduce the unit run bit for
// bit, positions times L and velocities times L/T after every step, the same impulses at the same
// instants, the same zones, jams and sleepers, from the same candidate pairs. Any tolerance,
// cut-off, threshold or margin written in absolute units (a speed below which a particle "rests", a
// gap below which two disks "touch", a Newton tolerance in metres) breaks the equality, whatever
// its size. Half-plane normals are also rescaled (their magnitude is free), by a power of two
// unrelated to the others.
//
// The same holds for the scene's orientation: turned by a quarter turn or mirrored, every vector
// of the scene has its components swapped or negated, every operation of a step is the original's
// with its operands swapped or negated (a dot product a.x b.x + a.y b.y becomes a.y b.y + a.x b.x,
// which rounds alike), so the turned run must be the original turned, bit for bit. Not for the implicit
// integrators under a quarter turn: their linear solve eliminates a particle's x before its y,
// and a spring that is not along an axis couples the two (the solve's rounding then differs in its
// last bits, as for any reordering of the unknowns); a mirror or a half turn keeps that order,
// and they are checked under those.
//
// Not for --compat: the course's formulation keeps absolute cut-offs on purpose (README, "Course
// compatibility"). Gravitational attraction is left out: G m1 m2 / r^2 has units of its own.
#include "contact_physics.h"
#include "fosssim/core/forces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace fosssim::testing {
namespace {

/// The scaled run's units against the unit run's, the half-planes' normal magnitude, and the
/// scene's orientation (the Frame tests turn it and keep the units).
struct Units {
  const char* name = "SI";
  double length = 1.0, mass = 1.0, time = 1.0, normal = 1.0;
  int quarterTurns = 0;  ///< counter-clockwise, after the mirror
  bool mirror = false;   ///< x -> -x first
  /// A vector of the scene in this frame: signs and swaps only, so exact.
  Vec2 orient(Vec2 a) const {
    if (mirror) a.x() = -a.x();
    for (int k = 0; k < quarterTurns; ++k) a = Vec2(-a.y(), a.x());
    return a;
  }
  double velocity() const { return length / time; }
  double acceleration() const { return length / (time * time); }
  double stiffness() const { return mass / (time * time); }  ///< force per length
  double damping() const { return mass / time; }             ///< force per speed
};

struct Method {
  std::string integrator;
  std::string collision;
  Failsafe failsafe = Failsafe::Projection;
};

/// A little of everything the default mode's contacts do, in 80 steps: a heap resting in a V of
/// two half-planes (it sleeps), disks of several sizes and masses raining onto it after some 45
/// steps (zones, jams, wakes), a fixed chain of thin capsules across the V, a damped chain of
/// springs falling on it, and two fast bullets. Every number is a multiple of the units in `u`.
TestScene unitsScene(const Method& method, const Units& u) {
  const double L = u.length, V = u.velocity();
  TestScene s = contactScene(method.collision, 0.5, 0.005 * u.time, method.failsafe);
  s.scene.integrator = method.integrator;
  Rng rng(20261207);
  // The heap: four rows of touching disks in the bottom of the V, already at rest.
  for (int row = 0; row < 4; ++row)
    for (int col = -row; col <= row; ++col)
      addBody(s, 1.0 * u.mass, u.orient(L * Vec2(0.1 * col, 0.075 + 0.1 * row)), Vec2::Zero(), 0.05 * L);
  // The rain, about 0.5 above it.
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 8; ++col) {
      const double m = uniform(rng, 0.5, 2.5);
      const double x = -0.42 + 0.12 * col + uniform(rng, -0.01, 0.01);
      const double r = uniform(rng, 0.03, 0.055);
      const double vx = uniform(rng, -0.5, 0.5);
      addBody(s, m * u.mass, u.orient(L * Vec2(x, 0.95 + 0.12 * row)), u.orient(V * Vec2(vx, -1.0)), r * L);
    }
  const int fixedChain = s.state.numParticles();
  for (int k = 0; k < 5; ++k)
    addBody(s, 1.0 * u.mass, u.orient(L * Vec2(-0.5 + 0.25 * k, 1.5)), Vec2::Zero(), 0.01 * L, /*fixed=*/true);
  for (int k = 0; k + 1 < 5; ++k) s.scene.edges.push_back(Edge{fixedChain + k, fixedChain + k + 1, 0.015 * L});
  const int rope = s.state.numParticles();
  for (int k = 0; k < 6; ++k)
    addBody(s, 0.3 * u.mass, u.orient(L * Vec2(-0.45 + 0.17 * k, 1.7)), u.orient(V * Vec2(0, -2)), 0.03 * L);
  for (int k = 0; k + 1 < 6; ++k) {
    s.scene.edges.push_back(Edge{rope + k, rope + k + 1, 0.02 * L});
    s.scene.forces.push_back(
        std::make_unique<SpringForce>(rope + k, rope + k + 1, 200.0 * u.stiffness(), 0.17 * L, 0.5 * u.damping()));
  }
  addBody(s, 0.1 * u.mass, u.orient(L * Vec2(-0.3, 2.0)), u.orient(V * Vec2(1.5, -40)), 0.015 * L);
  addBody(s, 0.1 * u.mass, u.orient(L * Vec2(0.35, 1.9)), u.orient(V * Vec2(-2.5, -55)), 0.012 * L);
  s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), u.orient(u.normal * Vec2(1, 1))});
  s.scene.halfplanes.push_back(HalfPlane{Vec2::Zero(), u.orient(u.normal * Vec2(-3, 3))});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(u.orient(u.acceleration() * Vec2(0, -9.81))));
  // The penalty layers that hybrid and penalty handling bring (as finalizeScene adds them), in units.
  const double penaltyK = method.collision == "hybrid" ? 10.0 : 300.0;
  if (method.collision == "hybrid" || method.collision == "penalty")
    s.scene.forces.push_back(std::make_unique<PenaltyForce>(penaltyK * u.stiffness(), 0.01 * L));
  return s;
}

/// b == a in u's frame and scaled by `scale` (a power of two), to the bit: both are exact. Compared
/// as numbers (a zero's sign may differ where an operation's operands were negated: a - b against
/// (-a) - (-b)).
bool sameIn(const Units& u, const VecX& a, const VecX& b, double scale) {
  if (a.size() != b.size()) return false;
  for (long p = 0; p < a.size() / 2; ++p)
    if (u.orient(scale * a.segment<2>(2 * p)) != b.segment<2>(2 * p)) return false;
  return true;
}

void expectUnitsDoNotMatter(const Method& method, const Units& u, int steps = 80) {
  TestScene one = unitsScene(method, Units{});
  TestScene scaled = unitsScene(method, u);
  auto a = defaultModeSimulator(one);
  auto b = defaultModeSimulator(scaled);
  long events = 0, zones = 0, asleep = 0;
  double penalty = 0.0;
  for (int k = 1; k <= steps; ++k) {
    SCOPED_TRACE(method.integrator + ", " + method.collision +
                 (method.failsafe == Failsafe::Rigid ? ", rigid failsafe" : "") + ", units " + u.name + ", step " +
                 std::to_string(k));
    const Status sa = a->step(one.scene, one.state);
    ASSERT_TRUE(sa.isOk()) << sa.message();
    ASSERT_TRUE(b->step(scaled.scene, scaled.state).isOk());
    ASSERT_TRUE(sameIn(u, one.state.x, scaled.state.x, u.length)) << "positions differ";
    ASSERT_TRUE(sameIn(u, one.state.v, scaled.state.v, u.velocity())) << "velocities differ";
    const auto& ia = a->log().impulses;
    const auto& ib = b->log().impulses;
    ASSERT_EQ(ia.size(), ib.size());
    for (size_t m = 0; m < ia.size(); ++m) {
      EXPECT_EQ(ia[m].kind, ib[m].kind);
      EXPECT_EQ(ia[m].i, ib[m].i);
      EXPECT_EQ(ia[m].j, ib[m].j);
      EXPECT_EQ(ia[m].tau, ib[m].tau);
      // Simple handling logs the contact vector, the time-ordered handlers a unit normal.
      EXPECT_EQ(u.orient(method.collision == "simple" ? Vec2(ia[m].n * u.length) : ia[m].n), ib[m].n);
    }
    const StepStats &ta = a->stats(), &tb = b->stats();
    // And the same work: the broad phase's boxes are the scene's, not a unit's or a frame's (a
    // margin of 4e-6 m made every pair of a scene in micrometres a candidate).
    EXPECT_EQ(ta.candidatePairs, tb.candidatePairs);
    for (int kind = 0; kind < 3; ++kind) EXPECT_EQ(ta.queries[kind], tb.queries[kind]);
    EXPECT_EQ(ta.collisions, tb.collisions);
    EXPECT_EQ(ta.zones, tb.zones);
    EXPECT_EQ(ta.zoneParticles, tb.zoneParticles);
    EXPECT_EQ(ta.zoneUpdates, tb.zoneUpdates);
    EXPECT_EQ(ta.rigidZones, tb.rigidZones);
    EXPECT_EQ(ta.jammedParticles, tb.jammedParticles);
    EXPECT_EQ(ta.heldParticles, tb.heldParticles);
    EXPECT_EQ(ta.asleep, tb.asleep);
    EXPECT_EQ(ta.woken, tb.woken);
    EXPECT_EQ(ta.newtonIterations, tb.newtonIterations);
    EXPECT_EQ(ta.energyCaps, tb.energyCaps);
    events += ta.collisions + static_cast<long>(ia.size());
    zones += ta.zones;
    asleep += ta.asleep;
    if (method.collision == "penalty") penalty += one.scene.forces.back()->energy(one.scene, one.state.x, one.state.v);
  }
  // The comparison means something only where the scene did what it is built to do.
  if (method.collision == "penalty") {
    EXPECT_GT(penalty, 0.0) << "the penalty layers must act";
  } else {
    EXPECT_GT(events, 0) << "the scene must collide";
  }
  if (method.collision == "hybrid" || method.collision == "continuous-time") {  // the two with zones and sleepers
    EXPECT_GT(zones, 0) << "the zones must act";
    // Explicit Euler's heap is not still long enough to sleep in these steps.
    if (method.integrator != "explicit-euler") {
      EXPECT_GT(asleep, 0) << "the heap must sleep";
    }
  }
}

// Length, mass and time scaled at once, two ways (about micrometres, gigagrams and 1/64 s; and
// 16,000 km, a picogram and 16 s).
const Units kSmall{"2^-20 m, 2^30 kg, 2^-6 s, normals 2^14", std::ldexp(1.0, -20), std::ldexp(1.0, 30),
                   std::ldexp(1.0, -6), std::ldexp(1.0, 14)};
const Units kLarge{"2^24 m, 2^-40 kg, 2^4 s, normals 2^-30", std::ldexp(1.0, 24), std::ldexp(1.0, -40),
                   std::ldexp(1.0, 4), std::ldexp(1.0, -30)};

const char* const kIntegrators[] = {"symplectic-euler", "implicit-euler", "linearized-implicit-euler"};

void expectForEveryIntegrator(const std::string& collision, Failsafe failsafe = Failsafe::Projection) {
  for (const char* integrator : kIntegrators)
    for (const Units& u : {kSmall, kLarge}) expectUnitsDoNotMatter(Method{integrator, collision, failsafe}, u);
}

TEST(Units, HybridHandlingDoesNotDependOnThem) { expectForEveryIntegrator("hybrid"); }
TEST(Units, ContinuousTimeHandlingDoesNotDependOnThem) { expectForEveryIntegrator("continuous-time"); }
TEST(Units, RigidZonesDoNotDependOnThem) { expectForEveryIntegrator("hybrid", Failsafe::Rigid); }
TEST(Units, SimpleHandlingDoesNotDependOnThem) { expectForEveryIntegrator("simple"); }
TEST(Units, PenaltyHandlingDoesNotDependOnThem) { expectForEveryIntegrator("penalty"); }

// Explicit Euler adds energy to every oscillation: a shorter run, before the rope's springs grow.
TEST(Units, ExplicitEulerDoesNotDependOnThem) {
  for (const char* collision : {"hybrid", "continuous-time"})
    for (const Units& u : {kSmall, kLarge}) expectUnitsDoNotMatter(Method{"explicit-euler", collision}, u);
}

// A quarter turn, a half turn and two mirrors (about the y axis, and about the diagonal y = -x: a
// mirror and a quarter turn), with no change of units. Every handler under symplectic Euler, and
// the implicit integrators under the frames that keep x before y (see the top: under a quarter
// turn they part in the last bits once the rope's springs bend, some 40 steps in).
const Units kQuarterTurn{"a quarter turn", 1.0, 1.0, 1.0, 1.0, 1, false};
const Units kHalfTurn{"a half turn", 1.0, 1.0, 1.0, 1.0, 2, false};
const Units kMirror{"a mirror", 1.0, 1.0, 1.0, 1.0, 0, true};
const Units kDiagonalMirror{"a mirror about y = -x", 1.0, 1.0, 1.0, 1.0, 1, true};

TEST(Frame, TurningOrMirroringASceneTurnsOrMirrorsItsMotion) {
  for (const char* collision : {"hybrid", "continuous-time", "simple", "penalty"})
    for (const Units& u : {kQuarterTurn, kHalfTurn, kMirror, kDiagonalMirror})
      expectUnitsDoNotMatter(Method{"symplectic-euler", collision}, u);
  for (const Units& u : {kQuarterTurn, kMirror})
    expectUnitsDoNotMatter(Method{"symplectic-euler", "hybrid", Failsafe::Rigid}, u);
}

TEST(Frame, AMirroredOrHalfTurnedSceneMovesAlikeUnderTheImplicitIntegrators) {
  for (const char* integrator : {"implicit-euler", "linearized-implicit-euler"})
    for (const char* collision : {"hybrid", "continuous-time"})
      for (const Units& u : {kMirror, kHalfTurn}) expectUnitsDoNotMatter(Method{integrator, collision}, u);
}

}  // namespace
}  // namespace fosssim::testing
