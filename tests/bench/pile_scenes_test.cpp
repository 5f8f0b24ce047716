// The dense-pile family (bench_scenes.h): every scene is fixed by its seed (same seed,
// same scene; another seed, other starts), starts with no particle overlapping another or a wall,
// is what its name says (COR, poured from low or high), and the pile that comes to rest does so
// in the simulator, by the benchmark's own measure of rest (block_table.h's atRestShare).
#include "bench_scenes.h"
#include "block_table.h"

#include "fosssim/core/simulator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

bench::BenchScene make(const std::string& kind, int n, unsigned seed) {
  bench::BenchScene s;
  EXPECT_TRUE(bench::makeScene(kind, n, "hybrid", seed, s)) << kind;
  return s;
}

double lowest(const bench::BenchScene& s) {
  double y = INFINITY;
  for (int i = 0; i < s.scene.numParticles(); ++i) y = std::min(y, s.state.x[2 * i + 1]);
  return y;
}

TEST(PileScenes, SameSeedSameSceneOtherSeedOtherStarts) {
  for (const std::string& kind : bench::pileKinds()) {
    SCOPED_TRACE(kind);
    const bench::BenchScene a = make(kind, 300, 3), b = make(kind, 300, 3), c = make(kind, 300, 4);
    ASSERT_EQ(a.scene.numParticles(), 300);
    ASSERT_EQ(b.scene.numParticles(), 300);
    ASSERT_EQ(c.scene.numParticles(), 300);
    EXPECT_EQ(a.state.x, b.state.x);
    EXPECT_EQ(a.state.v, b.state.v);
    EXPECT_EQ(a.scene.radius, b.scene.radius);
    EXPECT_EQ(a.scene.mass, b.scene.mass);
    ASSERT_EQ(a.scene.halfplanes.size(), b.scene.halfplanes.size());
    for (size_t h = 0; h < a.scene.halfplanes.size(); ++h) {
      EXPECT_EQ(a.scene.halfplanes[h].point, b.scene.halfplanes[h].point);
      EXPECT_EQ(a.scene.halfplanes[h].normal, b.scene.halfplanes[h].normal);
    }
    EXPECT_EQ(a.scene.collision.cor, b.scene.collision.cor);
    // Another seed moves every particle (jitter in both coordinates), not just a few.
    int moved = 0;
    for (int i = 0; i < 300; ++i) moved += a.state.x.segment<2>(2 * i) != c.state.x.segment<2>(2 * i);
    EXPECT_EQ(moved, 300);
  }
}

TEST(PileScenes, NoParticleStartsInsideAnotherOrAWall) {
  for (const std::string& kind : bench::pileKinds())
    for (int n : {1, 7, 500, 2500})
      for (unsigned seed : {1u, 2u, 99u}) {
        SCOPED_TRACE(kind + " N=" + std::to_string(n) + " seed " + std::to_string(seed));
        const bench::BenchScene s = make(kind, n, seed);
        const Scene& scene = s.scene;
        ASSERT_EQ(scene.numParticles(), n);
        long overlaps = 0;
        for (int i = 0; i < n; ++i) {
          const Vec2 xi = s.state.x.segment<2>(2 * i);
          for (int j = i + 1; j < n; ++j)
            overlaps += (xi - s.state.x.segment<2>(2 * j)).norm() <= scene.radius[i] + scene.radius[j];
          for (const HalfPlane& h : scene.halfplanes)
            overlaps += (xi - h.point).dot(h.normal.normalized()) <= scene.radius[i];
        }
        EXPECT_EQ(overlaps, 0);
      }
}

TEST(PileScenes, NamesSayCorAndHeightAndRunsAreLong) {
  for (const std::string& kind : bench::pileKinds()) {
    const bench::BenchScene s = make(kind, 400, 1);
    EXPECT_EQ(s.scene.collision.cor, kind.find("cor0.5") != std::string::npos ? 0.5 : 0.0) << kind;
    EXPECT_GE(s.scene.numSteps(), 1000) << kind << ": the family's runs are reported per block of 100 steps";
    EXPECT_LT(s.gravity, 0) << kind;
  }
  // From high: the block lands at speed (lifted by at least a few radii more than from low).
  for (const char* cor : {"cor0", "cor0.5"}) {
    const bench::BenchScene low = make(std::string("pile-low-") + cor, 400, 1),
                            high = make(std::string("pile-high-") + cor, 400, 1);
    EXPECT_GT(lowest(high), lowest(low) + 10 * high.scene.radius[0]) << cor;
  }
}

TEST(PileScenes, AtRestShareCountsSpeedsBelowTheThreshold) {
  bench::BenchScene s = make("pile-rest", 10, 1);
  const double limit = bench::restSpeed(s.scene.radius[0], s.scene.dt);
  VecX v = VecX::Zero(20);
  EXPECT_EQ(bench::atRestShare(s.scene, v), 1.0);
  v[0] = 1.01 * limit;             // particle 0 just faster than rest
  v[3] = -0.7 * limit;             // particle 1 just slower
  v.segment<2>(4) = Vec2(0.8, 0.8) * limit;  // particle 2: each component below, the speed above
  EXPECT_DOUBLE_EQ(bench::atRestShare(s.scene, v), 0.8);
}

/// The share at rest after `steps` steps of the default mode (or --compat).
double restShareAfter(const std::string& kind, int n, unsigned seed, long steps, bool compat) {
  bench::BenchScene s = make(kind, n, seed);
  SimulatorOptions options;
  options.handler.compat = compat;
  std::unique_ptr<Simulator> sim;
  EXPECT_TRUE(Simulator::create(s.scene, options, sim).isOk());
  if (!sim) return -1;
  for (long k = 0; k < steps; ++k) {
    const Status stepped = sim->step(s.scene, s.state);
    EXPECT_TRUE(stepped.isOk()) << stepped.message();
    if (!stepped) return -1;
  }
  return bench::atRestShare(s.scene, s.state.v);
}

TEST(PileScenes, RestingPileComesToRestAndPouredPileDoesNot) {
  for (unsigned seed : {1u, 2u}) {
    for (bool compat : {false, true}) {
      const double rest = restShareAfter("pile-rest", 120, seed, 200, compat);
      std::printf("pile-rest N=120 seed %u%s: %.1f%% at rest after 200 steps\n", seed, compat ? " --compat" : "",
                  100 * rest);
      EXPECT_GE(rest, 0.95) << "seed " << seed << (compat ? " --compat" : "");
    }
    // The measure can say no: a bouncy pile poured from high is still falling after 100 steps.
    EXPECT_LE(restShareAfter("pile-high-cor0.5", 120, seed, 100, false), 0.2) << "seed " << seed;
  }
}

}  // namespace
}  // namespace fosssim
