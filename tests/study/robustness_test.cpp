// Collision outcomes against a thin edge on the cases whose answer is certain: a disk that moves
// 1 m per step past a 0.06 m thick contact band skips it with discrete detection and is caught by
// continuous-time detection.
#include "experiments.h"
#include "interpenetration.h"
#include "robustness.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

Method collisionMethod(const std::string& label) {
  for (const Method& m : collisionMethods())
    if (m.label == label) return m;
  ADD_FAILURE() << "no method " << label;
  return Method{};
}

TEST(StudyRobustness, FastDiskTunnelsWithSimpleAndBouncesWithContinuousTimeAndHybrid) {
  const double speed = 100, dt = 0.01;
  const EdgeThrow simple = throwAtEdge(collisionMethod("simple"), speed, dt);
  ASSERT_TRUE(simple.run.ok()) << simple.run.message;
  EXPECT_EQ(simple.outcome, EdgeOutcome::Tunnelled);
  for (const char* label : {"continuous-time", "hybrid"}) {
    const EdgeThrow t = throwAtEdge(collisionMethod(label), speed, dt);
    ASSERT_TRUE(t.run.ok()) << label << ": " << t.run.message;
    EXPECT_EQ(t.outcome, EdgeOutcome::Bounced) << label;
  }
}

TEST(StudyRobustness, SlowDiskBouncesWithEveryImpulseMethod) {
  for (const char* label : {"simple", "continuous-time", "hybrid"}) {
    const EdgeThrow t = throwAtEdge(collisionMethod(label), 1.0, 1e-3);
    EXPECT_EQ(t.outcome, EdgeOutcome::Bounced) << label;
  }
}

// A soft penalty cannot stop a fast disk: it passes through.
TEST(StudyRobustness, SoftPenaltyLetsAFastDiskThrough) {
  const EdgeThrow t = throwAtEdge(collisionMethod("penalty k=1e2"), 10.0, 1e-4);
  ASSERT_TRUE(t.run.ok()) << t.run.message;
  EXPECT_EQ(t.outcome, EdgeOutcome::Tunnelled);
  EXPECT_GT(t.run.overlap.deepest, 0.02);
}

// The tunnelling speed docs/study.md states, from energy balance: the penalty spring (acting from
// `thickness` before contact) stops a unit-mass disk after compressing by v sqrt(m/k), so the disk's
// centre reaches the edge's line once v sqrt(m/k) > r_disk + r_edge + thickness = 0.04 m: 4 m/s at
// k = 1e4. Below it the disk bounces, above it it goes through (a fine step: the spring resolved).
TEST(StudyRobustness, PenaltyTunnelsAboveTheEnergyBalanceSpeed) {
  const double vThrough = 0.04 * std::sqrt(1e4);
  const EdgeThrow below = throwAtEdge(collisionMethod("penalty k=1e4"), 0.8 * vThrough, 1e-5);
  ASSERT_TRUE(below.run.ok()) << below.run.message;
  EXPECT_EQ(below.outcome, EdgeOutcome::Bounced) << edgeOutcomeName(below.outcome);
  const EdgeThrow above = throwAtEdge(collisionMethod("penalty k=1e4"), 1.25 * vThrough, 1e-5);
  ASSERT_TRUE(above.run.ok()) << above.run.message;
  EXPECT_EQ(above.outcome, EdgeOutcome::Tunnelled) << edgeOutcomeName(above.outcome);
}

TEST(StudyInterpenetration, MeasuresEveryPairKindAndSkipsWhatCannotSeparate) {
  SceneFile file;
  SceneBuilder x;
  x.duration(1).integrator("symplectic-euler", 0.01);
  x.particle(Vec2(0, 0.05), Vec2(0, 0), 1, false, 0.1);     // 0.05 into the floor
  x.particle(Vec2(0.15, 0.05), Vec2(0, 0), 1, false, 0.1);  // 0.05 into particle 0, 0.05 into the floor
  const int a = x.particle(Vec2(-1, 0.5), Vec2(0, 0), 1, true, 0.1);
  const int b = x.particle(Vec2(-0.95, 0.5), Vec2(0, 0), 1, true, 0.1);  // fixed pair: skipped
  x.edge(a, b, 0.01);  // its own ends are not counted against it
  x.halfplane(Vec2(0, 0), Vec2(0, 2));  // unnormalised normal
  ASSERT_TRUE(x.build("overlap.xml", file).isOk());
  const Overlap o = measureOverlap(file.scene, file.initial.x);
  EXPECT_EQ(o.pairs, 3);
  EXPECT_NEAR(o.deepest, 0.05, 1e-12);
}

}  // namespace
}  // namespace fosssim::study
