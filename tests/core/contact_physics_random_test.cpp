// The default mode's contact promises on randomised scenes (seeded std::mt19937, so every run sees
// the same scenes): energy never grows, nothing tunnels out of a thin slot, momentum and angular
// momentum of a free gas are kept, and both failsafes leave every step collision-free. Each step
// of each test must leave nothing unresolved (stepClean). Hand-made scenes:
// contact_physics_test.cpp; a pile poured into a V: contact_physics_pile_test.cpp.
#include "contact_physics.h"

#include "fosssim/core/forces.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace fosssim::testing {
namespace {

// Steps a scene without forces (kinetic energy is its only energy) until `steps` steps or the
// first failure: a step that leaves a pair colliding (stepClean) or raises the kinetic energy.
void stepCleanWithoutEnergyGain(Simulator& sim, TestScene& s, int steps) {
  for (int k = 0; k < steps; ++k) {
    const double before = kinetic(s);
    const ::testing::AssertionResult clean = stepClean(sim, s);
    if (!clean) {
      ADD_FAILURE() << clean.message();
      return;
    }
    if (kinetic(s) > before * (1 + 1e-12)) {
      ADD_FAILURE() << "step " << k + 1 << ": kinetic energy " << before << " -> " << kinetic(s);
      return;
    }
  }
}

const char* failsafeName(Failsafe f) { return f == Failsafe::Rigid ? "rigid" : "projection"; }

// A random collision-free scene in the box [-1, 1]^2: 3-12 disks (some fixed), up to 3 edges
// between them (no springs), up to 4 box walls as half-planes with unnormalised normals, random
// velocities, no forces.
TestScene randomScene(Rng& rng, const char* type, Failsafe failsafe) {
  const double cors[] = {0.0, 0.3, 0.5, 0.8, 1.0};
  TestScene s = contactScene(type, cors[uniformInt(rng, 0, 4)], 0.01, failsafe);
  const int n = uniformInt(rng, 3, 12);
  std::vector<Vec2> x;
  std::vector<double> r;
  while (static_cast<int>(x.size()) < n) {
    const Vec2 p = uniformVec(rng, -0.8, 0.8);
    const double radius = uniform(rng, 0.04, 0.12);
    bool free = true;
    for (size_t k = 0; k < x.size(); ++k) free = free && (x[k] - p).norm() > r[k] + radius + 0.01;
    if (!free) continue;
    x.push_back(p);
    r.push_back(radius);
    const bool fixed = uniform(rng, 0, 1) < 0.15;
    const Vec2 v = fixed ? Vec2::Zero() : uniformVec(rng, -3, 3);
    addBody(s, uniform(rng, 0.5, 2.0), p, v, radius, fixed);
  }
  const int edges = uniformInt(rng, 0, 3);
  for (int tries = 0; tries < 20 && static_cast<int>(s.scene.edges.size()) < edges; ++tries) {
    const int a = uniformInt(rng, 0, n - 1), b = uniformInt(rng, 0, n - 1);
    const double radius = uniform(rng, 0.01, 0.04);
    bool free = a != b;
    for (int k = 0; k < n && free; ++k)
      if (k != a && k != b) free = segmentDistance(x[k], x[a], x[b]) > r[k] + radius + 0.005;
    for (const Edge& e : s.scene.edges) free = free && !((e.i == a && e.j == b) || (e.i == b && e.j == a));
    if (free) s.scene.edges.push_back(Edge{a, b, radius});
  }
  const Vec2 walls[] = {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)};
  for (const Vec2& w : walls)
    if (uniform(rng, 0, 1) < 0.6) s.scene.halfplanes.push_back(HalfPlane{-w, uniform(rng, 0.1, 10) * w});
  return s;
}

// 1d. Over 200 random scenes, both types and both failsafes: with no forces kinetic energy is the
// only energy, and no impulse (COR <= 1) or failsafe may raise it, so it never grows over a step.
TEST(ContactPhysicsRandom, KineticEnergyNeverGrows) {
  for (const char* type : kEventTypes)
    for (Failsafe failsafe : {Failsafe::Projection, Failsafe::Rigid}) {
      Rng rng(20240611);
      for (int scene = 0; scene < 200; ++scene) {
        TestScene s = randomScene(rng, type, failsafe);
        SCOPED_TRACE(std::string(type) + " failsafe " + failsafeName(failsafe) + " scene " + std::to_string(scene) +
                     " COR " + std::to_string(s.scene.collision.cor));
        auto sim = defaultModeSimulator(s);
        // On a failure, go on with the next scene (so that a run lists every failing scene).
        stepCleanWithoutEnergyGain(*sim, s, 25);
      }
    }
}

// 1e. Dense packs: 96 hexagonal packs of 16-144 disks (gaps 0.5-10 mm, a few fixed at rest) in a
// box of four half-planes, 30% of them fast (up to 28 m/s, three radii a step), both types, COR
// 0, 0.5 and 1, over 80 steps, with the failsafe's default budget and starved ones (20, 2 and 1
// updates per row) and with holding on and off. Contacts persist from step to step, so zones
// start warm (each contact's last impulse applied before any solve), which is where a solve
// that ends on its budget used to leave energy behind: 4 of these 96 packs gained (up to 2% in a
// step at COR 0) before the zones' energy guard (ContactProjector::capEnergy). No forces: kinetic
// energy must never grow, and every step must end collision-free.
TEST(ContactPhysicsRandom, DensePacksNeverGainKineticEnergy) {
  const long budgets[] = {0, 20, 2, 1};  // 0: the default
  const double cors[] = {0.0, 0.5, 1.0};
  for (int pack = 0; pack < 96; ++pack) {
    Rng rng(1000 + pack);
    const char* type = kEventTypes[pack % 2];
    TestScene s = contactScene(type, cors[(pack / 2) % 3]);
    const int side = 4 + pack % 9;
    const double r = 0.05, gap = uniform(rng, 0.0005, 0.01);
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const Vec2 p(-0.8 + (2 * r + gap) * i + (j % 2) * (r + gap / 2), -0.8 + (2 * r + gap) * 0.87 * j);
        if (p.x() > 0.85 || p.y() > 0.85) continue;
        const double radius = r * uniform(rng, 0.9, 1.0);
        Vec2 v = uniformVec(rng, -1, 1);
        v *= uniform(rng, 0, 1) < 0.3 ? 20.0 : 2.0;
        const double m = uniform(rng, 0.5, 2.0);
        const bool fixed = uniform(rng, 0, 1) < 0.03;
        addBody(s, m, p, fixed ? Vec2(Vec2::Zero()) : v, radius, fixed);
      }
    const Vec2 walls[] = {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)};
    for (const Vec2& w : walls) s.scene.halfplanes.push_back(HalfPlane{-0.95 * w, uniform(rng, 0.1, 10) * w});
    const long budget = budgets[(pack / 6) % 4];
    const bool hold = (pack / 24) % 2 == 0;
    SCOPED_TRACE(std::string(type) + " pack " + std::to_string(pack) + " of " + std::to_string(s.state.numParticles()) +
                 " disks, COR " + std::to_string(s.scene.collision.cor) + ", budget " + std::to_string(budget) +
                 (hold ? ", holding" : ", no holding"));
    auto sim = defaultModeSimulator(s, true, budget, hold);
    stepCleanWithoutEnergyGain(*sim, s, 80);
  }
}

// A pack of 16-100 disks for the two tests below (DensePacksWithShortEdgesStayApart says what is
// in it), every length and speed multiplied by `scale`.
TestScene packWithShortEdges(int pack, double scale = 1.0) {
  const double cors[] = {0.0, 0.5, 1.0};
  Rng rng(5000 + pack);
  TestScene s = contactScene(kEventTypes[pack % 2], cors[(pack / 2) % 3]);
  const int side = 4 + pack % 7;
  const double r = 0.05, gap = uniform(rng, 0.0005, 0.01);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const Vec2 p(-0.8 + (2 * r + gap) * i + (j % 2) * (r + gap / 2), -0.8 + (2 * r + gap) * 0.87 * j);
      const double radius = r * uniform(rng, 0.9, 1.0);
      Vec2 v = uniformVec(rng, -1, 1);
      v *= uniform(rng, 0, 1) < 0.3 ? 20.0 : 2.0;
      const double m = uniform(rng, 0.5, 2.0);
      if (p.x() > 0.85 || p.y() > 0.85) continue;
      addBody(s, m, scale * p, scale * v, scale * radius);
    }
  for (int k = 0; k + 1 < s.state.numParticles(); k += 3) s.scene.edges.push_back(Edge{k, k + 1, scale * 0.01});
  const Vec2 walls[] = {Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1)};
  for (const Vec2& w : walls) s.scene.halfplanes.push_back(HalfPlane{-0.95 * scale * w, uniform(rng, 0.1, 10) * w});
  return s;
}

// 1f. Dense packs threaded with short edges: 60 packs of 16-100 disks as above (none fixed), every
// third disk joined to the next by an edge of radius 0.01 (a capsule between neighbours), over 60
// steps with the default budget. Edges rotate, so a contact can deepen without closing. Before
// two mends 8 of these packs ended a step with a particle-edge pair colliding: a contact that a
// zone's budget-ended solve brought forward to its instant (ContactZones::solvesNow) was dropped
// there as not closing, though the rotating edge met the particle later in the step (7 packs);
// and a curving contact's row, with its normal where the overlap is deepest, held with nothing
// changed while the pair still overlapped (1 pack, 1e-7 deep). Kinetic energy must not grow
// either.
TEST(ContactPhysicsRandom, DensePacksWithShortEdgesStayApart) {
  for (int pack = 0; pack < 60; ++pack) {
    TestScene s = packWithShortEdges(pack);
    SCOPED_TRACE(std::string(kEventTypes[pack % 2]) + " pack " + std::to_string(pack) + " of " +
                 std::to_string(s.state.numParticles()) + " disks, COR " + std::to_string(s.scene.collision.cor));
    auto sim = defaultModeSimulator(s);
    stepCleanWithoutEnergyGain(*sim, s, 60);
  }
}

// 5c. Units, where they matter most: 20 of those packs with every length and speed multiplied
// by 2^30 and by 2^-30 (exact in binary) run bit for bit as the unscaled ones over 40 steps,
// zones, holds, jams and energy caps included. Any absolute tolerance would break this.
TEST(ContactPhysicsRandom, DensePacksScaledByPowersOfTwoRunTheSame) {
  for (int pack = 0; pack < 20; ++pack)
    for (int exponent : {-30, 30}) {
      const double scale = std::ldexp(1.0, exponent);
      TestScene a = packWithShortEdges(pack), b = packWithShortEdges(pack, scale);
      auto simA = defaultModeSimulator(a), simB = defaultModeSimulator(b);
      for (int k = 0; k < 40; ++k) {
        ASSERT_TRUE(simA->step(a.scene, a.state).isOk());
        ASSERT_TRUE(simB->step(b.scene, b.state).isOk());
        ASSERT_EQ(a.state.x, b.state.x / scale) << "pack " << pack << " at 2^" << exponent << ", step " << k + 1;
        ASSERT_EQ(a.state.v, b.state.v / scale) << "pack " << pack << " at 2^" << exponent << ", step " << k + 1;
      }
    }
}

// A pile of 40 disks (radii 0.02-0.15, log-uniform; masses e^-spread .. e^spread, log-uniform)
// thrown into a box of a floor and two walls (unnormalised normals) under gravity, with up to 8
// edges of radius 0.005-0.03 between nearby disks, each held at its length by a spring of
// stiffness 2000 times its lighter end's mass, under `integrator`. Every length, speed and the
// gravity are multiplied by `scale` (the springs' stiffness per mass needs no change).
TestScene pileUnderForces(int seed, const char* type, double cor, const char* integrator, double spread,
                          double scale = 1.0) {
  Rng rng(seed);
  TestScene s = contactScene(type, cor);
  s.scene.integrator = integrator;
  addFloorAndGravity(s, 9.81 * scale);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(-scale, 0), Vec2(1, 0)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(scale, 0), Vec2(-3, 0)});
  std::vector<Vec2> x;
  std::vector<double> r;
  for (int tries = 0; x.size() < 40 && tries < 5000; ++tries) {
    const double radius = std::exp(uniform(rng, std::log(0.02), std::log(0.15)));
    const double px = uniform(rng, -1 + radius, 1 - radius);
    const double py = uniform(rng, radius, 2.0);
    const Vec2 p(px, py);
    bool free = true;
    for (size_t k = 0; k < x.size(); ++k) free = free && (x[k] - p).norm() > r[k] + radius + 0.002;
    if (!free) continue;
    x.push_back(p);
    r.push_back(radius);
    const double m = std::exp(uniform(rng, -spread, spread));
    addBody(s, m, scale * p, scale * uniformVec(rng, -2, 2), scale * radius);
  }
  const int n = s.state.numParticles();
  for (int tries = 0; tries < 60 && s.scene.edges.size() < 8; ++tries) {
    const int a = uniformInt(rng, 0, n - 1), b = uniformInt(rng, 0, n - 1);
    if (a == b || (x[a] - x[b]).norm() > 0.5) continue;
    const double radius = uniform(rng, 0.005, 0.03);
    bool free = true;
    for (int k = 0; k < n && free; ++k)
      if (k != a && k != b) free = segmentDistance(x[k], x[a], x[b]) > r[k] + radius + 0.002;
    for (const Edge& e : s.scene.edges) free = free && !((e.i == a && e.j == b) || (e.i == b && e.j == a));
    if (!free) continue;
    s.scene.edges.push_back(Edge{a, b, scale * radius});
    const double k = 2000.0 * std::min(s.scene.massOf(a), s.scene.massOf(b));
    s.scene.forces.push_back(std::make_unique<SpringForce>(a, b, k, scale * (x[a] - x[b]).norm(), 0.0));
  }
  return s;
}

// Steps pileUnderForces(seed, ...) for `steps` steps against its twin without collision handling
// (1g below): every step ends collision-free, and the kinetic energy after it does not exceed
// the twin's. Returns the collisions and the failsafe's energy caps over the run.
struct PileRun {
  long contacts = 0, energyCaps = 0;
};
PileRun runAgainstTwin(int seed, const char* type, double cor, const char* integrator, double spread, int steps) {
  TestScene s = pileUnderForces(seed, type, cor, integrator, spread);
  TestScene twin = pileUnderForces(seed, type, cor, integrator, spread);
  twin.scene.collision.type = test::collisionType("none");
  auto sim = defaultModeSimulator(s, /*sleep=*/false), free = defaultModeSimulator(twin, false);
  PileRun run;
  for (int k = 0; k < steps; ++k) {
    twin.state = s.state;
    const Status twinStep = free->step(twin.scene, twin.state);
    EXPECT_TRUE(twinStep.isOk()) << "step " << k + 1 << ": " << twinStep.message();
    const ::testing::AssertionResult clean = stepClean(*sim, s);
    EXPECT_TRUE(clean);
    if (!twinStep.isOk() || !clean) break;
    run.contacts += sim->stats().collisions;
    run.energyCaps += sim->stats().energyCaps;
    EXPECT_LE(kinetic(s), kinetic(twin) * (1 + 1e-10)) << "step " << k + 1;
    if (kinetic(s) > kinetic(twin) * (1 + 1e-10)) break;
  }
  return run;
}

// 1g. Responses under forces: piles of disks and sprung edges falling into a box under gravity,
// masses spread over e^-14 .. e^14 (or all 1), with the symplectic and both implicit integrators,
// COR 0, 0.5 and 1, both types, 150 steps (they land, pile up and mostly come to rest). With
// forces kinetic energy is not conserved by the step, so each step's collision handling is
// measured against the integrator's own prediction: a twin without collision handling steps from
// the same state, and the kinetic energy after the step may not exceed the twin's (impulses and
// the failsafe only take energy away). Sleeping is off (a sleeper is not integrated, so the twin
// would not be its prediction). Each step must also end collision-free. (The explicit method's
// responses act on the step's start velocities, not on the prediction: README.)
TEST(ContactPhysicsRandom, PilesUnderForcesGainNoKineticEnergyFromTheirContacts) {
  const char* integrators[] = {"symplectic-euler", "implicit-euler", "linearized-implicit-euler"};
  for (const char* type : kEventTypes)
    for (const char* integrator : integrators)
      for (double spread : {0.0, 14.0})
        for (double cor : {0.0, 0.5, 1.0}) {
          const int seed = 7 + static_cast<int>(spread) + static_cast<int>(10 * cor);
          SCOPED_TRACE(std::string(type) + " " + integrator + " mass spread e^" + std::to_string(spread) + " COR " +
                       std::to_string(cor) + " seed " + std::to_string(seed));
          EXPECT_GT(runAgainstTwin(seed, type, cor, integrator, spread, 150).contacts, 200)
              << "the pile should have landed";
        }
}

// 1h. Such a pile (seed 15021: hybrid, symplectic Euler, masses e^-14 .. e^14, COR 0), found by
// running 1g's piles from 40 more seeds each: in its step 117 the energy guard took a zone's
// solve back whole at one instant, again and again. Its contacts came back marked as back for that
// solve (not counted as met again), and the cap itself did not count toward the jam limit either,
// so they were solved and capped again without end, until the event budget's internal error.
// Every step must end, and 1g's checks hold; the guard must have capped solves here, or the pile
// no longer tests what it is for.
TEST(ContactPhysicsRandom, ZoneSolvesTakenBackWholeStillEndTheStep) {
  const PileRun run = runAgainstTwin(15021, "hybrid", 0.0, "symplectic-euler", 14.0, 150);
  EXPECT_GT(run.energyCaps, 0);
}

// 5d. Units with forces and sleeping: those piles (masses e^-7 .. e^7) with every length, speed
// and the gravity multiplied by 2^30 and 2^-30 run bit for bit as the unscaled ones over 300
// steps, with the symplectic and both implicit integrators (Newton's tolerance included), COR 0
// and 0.5, where the piles come to rest and fall asleep (the sleep thresholds, kicks and wakes
// included).
TEST(ContactPhysicsRandom, PilesUnderForcesScaledByPowersOfTwoRunTheSame) {
  const char* integrators[] = {"symplectic-euler", "implicit-euler", "linearized-implicit-euler"};
  for (const char* type : kEventTypes)
    for (const char* integrator : integrators)
      for (double cor : {0.0, 0.5})
        for (int exponent : {-30, 30}) {
          SCOPED_TRACE(std::string(type) + " " + integrator + " COR " + std::to_string(cor) + " at 2^" +
                       std::to_string(exponent));
          const double scale = std::ldexp(1.0, exponent);
          TestScene a = pileUnderForces(3, type, cor, integrator, 7.0);
          TestScene b = pileUnderForces(3, type, cor, integrator, 7.0, scale);
          auto simA = defaultModeSimulator(a), simB = defaultModeSimulator(b);
          int asleep = 0;
          for (int k = 0; k < 300; ++k) {
            ASSERT_TRUE(simA->step(a.scene, a.state).isOk());
            ASSERT_TRUE(simB->step(b.scene, b.state).isOk());
            ASSERT_EQ(a.state.x, b.state.x / scale) << "step " << k + 1;
            ASSERT_EQ(a.state.v, b.state.v / scale) << "step " << k + 1;
            ASSERT_EQ(simA->stats().asleep, simB->stats().asleep) << "step " << k + 1;
            asleep = std::max(asleep, simA->stats().asleep);
          }
          EXPECT_GT(asleep, 0) << "the pile should have fallen asleep";
        }
}

// 2b. Thirty shots of three fast disks (20-200 m/s across a slot, so up to 40 bounces per step)
// inside a 0.1 m slot between two thin fixed edges 100 m long: none crosses an edge (while within
// the slot's length, centres stay within [0.025, 0.075]: edge radius 0.005 plus disk radius 0.02)
// and no two overlap, at every step.
TEST(ContactPhysicsRandom, FastDisksStayInThinSlot) {
  Rng rng(777);
  for (int shot = 0; shot < 30; ++shot) {
    const char* type = kEventTypes[shot % 2];
    SCOPED_TRACE(std::string(type) + " shot " + std::to_string(shot));
    TestScene s = contactScene(type, shot % 3 == 0 ? 0.5 : 1.0);
    for (double y : {0.0, 0.1}) {
      addBody(s, 1.0, Vec2(-50, y), Vec2::Zero(), 0.005, true);
      addBody(s, 1.0, Vec2(50, y), Vec2::Zero(), 0.005, true);
      s.scene.edges.push_back(Edge{s.state.numParticles() - 2, s.state.numParticles() - 1, 0.005});
    }
    for (int k = 0; k < 3; ++k) {
      const double speed = uniform(rng, 20, 200);
      const double vy = speed * (uniform(rng, 0, 1) < 0.5 ? -1 : 1);
      const double m = uniform(rng, 0.5, 2);
      const double px = -0.5 + 0.5 * k + uniform(rng, -0.1, 0.1);
      const double py = uniform(rng, 0.03, 0.07);
      const double vx = uniform(rng, -2, 2);
      addBody(s, m, Vec2(px, py), Vec2(vx, vy), 0.02);
    }
    auto sim = defaultModeSimulator(s);
    for (int k = 0; k < 50; ++k) {
      const double before = kinetic(s);
      ASSERT_TRUE(stepClean(*sim, s));
      ASSERT_LE(kinetic(s), before * (1 + 1e-12)) << "step " << k + 1;
      for (int i = 4; i < 7; ++i) {
        if (std::abs(s.state.x[2 * i]) > 49) continue;  // out of the slot's end
        ASSERT_GE(s.state.x[2 * i + 1], 0.025 - 1e-9) << "disk " << i << " step " << k + 1;
        ASSERT_LE(s.state.x[2 * i + 1], 0.075 + 1e-9) << "disk " << i << " step " << k + 1;
        for (int j = i + 1; j < 7; ++j)
          ASSERT_GE((at(s.state.x, i) - at(s.state.x, j)).norm(), 0.04 - 1e-9) << i << "-" << j << " step " << k + 1;
      }
    }
  }
}

// 3b. A gas of 30 free disks (no walls, no fixed particles, COR 1): every impulse acts along the
// line of centres between free particles and free flight is exact, so total momentum and angular
// momentum about the origin are kept (1e-9 of sum m|v| and sum m|x||v|) over 100 steps.
TEST(ContactPhysicsRandom, FreeGasKeepsMomentumAndAngularMomentum) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    Rng rng(31337);
    TestScene s = contactScene(type, 1.0);
    std::vector<Vec2> x;
    while (x.size() < 30) {
      const Vec2 p = uniformVec(rng, -1, 1);
      bool free = true;
      for (const Vec2& q : x) free = free && (q - p).norm() > 0.17;
      if (!free) continue;
      x.push_back(p);
      const double m = uniform(rng, 0.5, 2);
      addBody(s, m, p, uniformVec(rng, -2, 2), 0.08);
    }
    auto sim = defaultModeSimulator(s);
    const Vec2 p0 = momentum(s);
    const double l0 = angularMomentum(s), pScale = momentumScale(s);
    long impulses = 0;
    for (int k = 0; k < 100; ++k) {
      const double before = kinetic(s);
      ASSERT_TRUE(stepClean(*sim, s));
      impulses += static_cast<long>(sim->log().impulses.size());
      ASSERT_LE(kinetic(s), before * (1 + 1e-12)) << "step " << k + 1;
      ASSERT_LE((momentum(s) - p0).norm(), 1e-9 * pScale) << "step " << k + 1;
      ASSERT_LE(std::abs(angularMomentum(s) - l0), 1e-9 * angularScale(s)) << "step " << k + 1;
    }
    EXPECT_GE(impulses, 10) << "too few collisions to test anything";
    std::printf("[ gas      ] %s: %ld impulses\n", type, impulses);
  }
}

}  // namespace
}  // namespace fosssim::testing
