// Fast disks in a small box at COR 1 keep their kinetic energy (default mode: "no freezing";
// the promise is the energy's, since nothing else acts: no gravity, no penalty layer). An
// independent check found two disks crossing a 1.4 m box five times a step losing 94% of their
// energy in one step (continuous-time) and all of it (hybrid), in these ways:
//   * a particle's quota of events counted every event, however spread over the step, and sent
//     its contacts to the zones (kContinuousEventsPerParticle now counts only close ones);
//   * a zone took rows for walls a disk was far from, and a row forbids any approach: the disk
//     stopped across the box (kZoneReach);
//   * a light disk squeezed between a heavy one and a wall stalled Gauss-Seidel, the zone's solves
//     ended on their budgets and its jam stopped both (ContactProjector::solveCluster), and a
//     bounce that rounding or a partial solve made add energy was taken back whole instead of
//     shortened (ContactProjector::restitute).
// Random boxes found three more: two light disks wedged in a corner by two heavy ones (masses
// alike among the cluster's movable bodies, so not solved exactly) ran every solve out of its
// budget until a jam stopped them (87% lost: a small cluster is now solved exactly when its solve
// is about to end on its budget); a wall that a hit pushed a light disk into, without the disk
// closing on it, stayed inelastic (10% lost: at COR 1 every row restitutes, ContactZones::setRow);
// and a zone's rows for pairs within kZoneReach missed a disk that eased out of an edge it
// overlapped and sank back into it later in the step (pairDeepening now measures that). Run to
// 3,000 trials, the random boxes found a cluster of 13 rows, one more than the exact rescue's
// enumeration took (now an active-set solve of up to 16), and light disks rattling between a wall
// and a disk the walls hold, past the zone's 64 bounces (a small zone now takes up to 4,096).
#include "contact_physics.h"

#include <cmath>

namespace fosssim::testing {
namespace {

TestScene box(const std::string& type, double half, double dt) {
  TestScene s = contactScene(type, 1.0, dt);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(-half, 0), Vec2(1, 0)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(half, 0), Vec2(-1, 0)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, -half), Vec2(0, 1)});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, half), Vec2(0, -1)});
  return s;
}

// Five steps of box s at COR 1: no jam, and the kinetic energy kept (to 1e-7) after each.
void keepsItsEnergyWithoutJams(TestScene& s) {
  auto sim = defaultModeSimulator(s);
  const double start = kinetic(s);
  for (int k = 0; k < 5; ++k) {
    ASSERT_TRUE(stepClean(*sim, s));
    EXPECT_EQ(sim->stats().jammedParticles, 0) << "step " << k + 1;
    EXPECT_NEAR(kinetic(s), start, 1e-7 * start) << "step " << k + 1;
  }
}

// The check's scene: a disk of 93.8 kg at (88, -63) m/s and one of 0.76 kg at (246, -14) m/s in a
// box of 1.4 m, dt 0.03 (the light one moves 7.4 m a step). Three steps, 24 to 37 contacts each.
TEST(FastBox, TwoFastDisksInASmallBoxKeepTheirEnergy) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = box(type, 0.7, 0.03);
    addBody(s, 93.81961729578565, Vec2(0.2966701948025767, 0.34206586757630886),
            Vec2(87.66417191013102, -63.37120115197769), 0.11339968170712446);
    addBody(s, 0.7629865629391726, Vec2(0.4346421662649822, 0.052191070822261154),
            Vec2(245.91447951689122, -13.706159513776129), 0.07987745509536874);
    auto sim = defaultModeSimulator(s);
    const double start = kinetic(s);
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(stepClean(*sim, s));
      // Events keep it to rounding; a zone's solve to its tolerance (1e-10 of the speeds).
      EXPECT_NEAR(kinetic(s), start, 1e-7 * start) << "step " << k + 1;
    }
  }
}

// A box found among 600 random ones (the test below, its trial 129): a disk of 18.9 kg among
// three of 0.05-0.39 kg at 60-120 m/s in a 2 m box, COR 1, dt 0.03. A light disk driven into a
// wall by one some 380 times heavier bounces between them about pi sqrt(380) = 61 times before
// the heavy one turns (Galperin's count of elastic collisions, exact in one dimension), and the
// zone spent its 64 bounces of the step within a few of those episodes, jammed, and the jam took
// 55% of the kinetic energy in step 3. The limit now grows with the zone's mass ratio
// (ContactZones::bounceLimit).
TEST(FastBox, ALightDiskRattlingBetweenAHeavyOneAndAWallDoesNotJam) {
  TestScene s = box("hybrid", 1.0, 0.03);
  addBody(s, 0.39491296222962868, Vec2(-0.37856172733008864, 0.53780704438686366),
          Vec2(28.141792071983218, 64.063508482649922), 0.054697898784652352);
  addBody(s, 0.33876187083711728, Vec2(-0.50988955758512022, 0.15498513504862788),
          Vec2(60.20216504111886, -65.151509270071983), 0.10080924625741318);
  addBody(s, 0.050004454018673553, Vec2(0.69627230055630207, -0.29775360301136977),
          Vec2(82.891505677253008, -88.420256366953254), 0.11784083720995113);
  addBody(s, 18.911932131492787, Vec2(-0.79926443286240101, 0.18725953586399557),
          Vec2(77.205683058127761, 63.486871961504221), 0.078394932178780435);
  keepsItsEnergyWithoutJams(s);
}

// Trial 1049 of the random boxes below, run to 3,000 trials: two light disks (0.044 and 0.050 kg)
// and one of 0.32 kg with a heavy one of 28 kg, COR 1. In step 4 a light disk rattled between a
// wall and a disk the walls held, bouncing every 0.00023 of a step (some 1,500 times to the step's
// end); at the zone's 64 bounces the jam took 38% of the box's kinetic energy. A zone of up to
// kSmallZoneMembers may now take kMaxZoneBouncesCap bounces.
TEST(FastBox, ALightDiskRattlingAgainstADiskTheWallsHoldDoesNotJam) {
  TestScene s = box("hybrid", 1.0, 0.03);
  addBody(s, 0.04363171607816671, Vec2(-0.43986334279179573, 0.1229951851069927),
          Vec2(-51.641060877591372, -67.090507410466671), 0.10336625007679685);
  addBody(s, 28.373025455152913, Vec2(0.24543302208185191, 0.46599755473434934),
          Vec2(97.870590584352612, -81.108498852699995), 0.1100384995038621);
  addBody(s, 0.31894398775066435, Vec2(-0.69132493659853944, 0.24276320859789857),
          Vec2(22.210014471784234, -12.36636065877974), 0.080011183449532841);
  addBody(s, 0.050063756429931272, Vec2(0.72185303941369061, -0.21282799430191524),
          Vec2(0.67192339338362217, 84.974805125966668), 0.101004530582577);
  keepsItsEnergyWithoutJams(s);
}

// Random boxes: `disks` (a range) of 0.03 to 30 kg and radius 0.05-0.12 at up to 100 m/s in a box
// of 2 m, dt 0.03 (up to 1.5 crossings a step), five steps each, the scene type alternating
// between continuous-time and hybrid. check(sim, scene, start energy, step) after each step.
template <class Check>
int randomBoxes(unsigned seed, int trials, int fewest, int most, const Check& check) {
  Rng rng(seed);
  int runs = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const char* type = kEventTypes[trial % 2];
    SCOPED_TRACE(std::string(type) + " trial " + std::to_string(trial));
    TestScene s = box(type, 1.0, 0.03);
    const int n = uniformInt(rng, fewest, most);
    for (int p = 0; p < n; ++p) {
      const double r = uniform(rng, 0.05, 0.12);
      const Vec2 x = uniformVec(rng, -0.8, 0.8);
      bool apart = true;
      for (int q = 0; q < s.scene.numParticles(); ++q)  // the disks placed so far
        apart = apart && (at(s.state.x, q) - x).norm() > s.scene.radius[q] + r;
      if (!apart) continue;  // the draw overlaps one placed already: one disk fewer
      const double m = std::pow(10.0, uniform(rng, -1.5, 1.5));
      addBody(s, m, x, uniformVec(rng, -100, 100), r);
    }
    if (s.scene.numParticles() < 2) continue;
    auto sim = defaultModeSimulator(s);
    const double start = kinetic(s);
    for (int k = 0; k < 5; ++k) {
      if (!stepClean(*sim, s)) {
        ADD_FAILURE() << "step " << k + 1 << " failed";
        break;
      }
      if (!check(*sim, s, start, k + 1)) break;
    }
    ++runs;
  }
  return runs;
}

// 2-4 disks, 600 boxes (3,000 took 0.6 s here and kept their energy too): the kinetic energy never
// falls (nor grows).
TEST(FastBox, RandomFastDisksInABoxKeepTheirEnergy) {
  const int runs = randomBoxes(2026, 600, 2, 4, [](const Simulator&, const TestScene& s, double start, int step) {
    EXPECT_NEAR(kinetic(s), start, 1e-7 * start) << "step " << step;
    return true;
  });
  EXPECT_GT(runs, 500);
}

// 5-8 disks: the kinetic energy never grows, and it falls only in a step with a jam, which only a
// rattle faster than the bounce cap makes (a disk between a wall and disks the walls hold,
// bouncing every 2.5e-5 of a step; of 600 boxes from this seed 7 lose 37-79% of their energy).
// Before small clusters were solved exactly up to 8 disks and 32 rows, with as many bounces, 125
// of 600 boxes (another seed) lost energy, most of them without a jam.
TEST(FastBox, RandomCrowdedBoxesLoseEnergyOnlyInJams) {
  int lossy = 0;
  const int runs = randomBoxes(2027, 200, 5, 8, [&](const Simulator& sim, const TestScene& s, double start, int step) {
    EXPECT_LE(kinetic(s), start * (1 + 1e-7)) << "step " << step;
    if (kinetic(s) >= start * (1 - 1e-7)) return true;
    EXPECT_GT(sim.stats().jammedParticles, 0) << "step " << step << ": energy lost without a jam";
    ++lossy;
    return false;  // the rest of the run starts from less
  });
  EXPECT_GT(runs, 150);
  EXPECT_LE(lossy, runs / 50);
}

}  // namespace
}  // namespace fosssim::testing
