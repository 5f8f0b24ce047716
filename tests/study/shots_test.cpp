// The random shots of the energy-classified robustness chart: fair draws, and outcomes judged by
// energy against the closed form of a bounce off a flat face.
#include "shots.h"

#include "problems.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

Method method(const std::string& label) {
  for (const Method& m : collisionMethods())
    if (m.label == label) return m;
  ADD_FAILURE() << label;
  return {};
}

TEST(StudyShots, DrawsAreRepeatableAndStartClearOfTheEdges) {
  for (ShotTarget t : {ShotTarget::EdgeFace, ShotTarget::EdgeEnd, ShotTarget::Joint, ShotTarget::Slot}) {
    for (int i = 0; i < 50; ++i) {
      const Shot a = randomShot(t, i), b = randomShot(t, i);
      EXPECT_EQ(a.speed, b.speed);
      EXPECT_EQ(a.angle, b.angle);
      EXPECT_GE(a.cor, 0.5);
      EXPECT_LE(a.cor, 1.0);
      SceneFile file;
      ASSERT_TRUE(shotScene(a, method("simple")).build("shot.xml", file).isOk());
      const Vec2 start = at(file.initial.x, file.scene.numParticles() - 1);
      EXPECT_GT(shotClearance(a, start), t == ShotTarget::Slot ? 0.0 : 0.15) << shotTargetName(t) << " " << i;
    }
  }
}

// A flat face keeps the tangential velocity and scales the normal one by COR: at 30 degrees from
// head-on with COR 0.5 the energy ratio is sin^2 30 + 0.25 cos^2 30 = 0.4375.
TEST(StudyShots, ContinuousTimeBouncesOffAFaceWithTheClosedFormsEnergy) {
  Shot s;
  s.target = ShotTarget::EdgeFace;
  s.speed = 3;
  s.dt = 0.01;
  s.angle = -M_PI / 2 + M_PI / 6;
  s.cor = 0.5;
  const ShotResult r = fireShot(s, method("continuous-time"), false);
  EXPECT_EQ(r.outcome, ShotOutcome::Bounced) << shotOutcomeName(r.outcome);
  EXPECT_NEAR(r.energyRatio, 0.25 + 0.75 * 0.25, 1e-9);
  EXPECT_GT(r.clearance, 0);
}

// One step of simple's carries the disk 0.5 m, far across the 0.06 m it could be caught in.
TEST(StudyShots, SimpleTunnelsWhenAStepCrossesTheContactBand) {
  Shot s;
  s.target = ShotTarget::EdgeFace;
  s.speed = 50;
  s.dt = 0.01;
  s.angle = -M_PI / 2;
  const ShotResult r = fireShot(s, method("simple"), false);
  EXPECT_EQ(r.outcome, ShotOutcome::Tunnelled) << shotOutcomeName(r.outcome);
  EXPECT_NEAR(r.energyRatio, 1.0, 1e-12);  // it never knew
}

}  // namespace
}  // namespace fosssim::study
