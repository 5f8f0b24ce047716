// The study's closed forms checked against their own equations (never against a simulation):
// a wrong answer here would make every error the study reports wrong.
#include "closed_forms.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::study {
namespace {

// m u'' + b u' + k u = 0 by central differences of velocity(), and velocity() = d displacement/dt,
// for each damping regime.
TEST(StudyClosedForms, OscillatorSolvesItsEquationInEveryRegime) {
  for (double b : {0.0, 1.0, 2 * std::sqrt(10.0), 20.0}) {  // undamped, under, critical, over
    const Oscillator o{1.0, 10.0, b, 0.5, -0.3};
    EXPECT_DOUBLE_EQ(o.displacement(0), 0.5) << b;
    EXPECT_NEAR(o.velocity(0), -0.3, 1e-12) << b;
    const double h = 1e-5;
    for (double t : {0.1, 0.7, 2.3}) {
      const double du = (o.displacement(t + h) - o.displacement(t - h)) / (2 * h);
      const double dv = (o.velocity(t + h) - o.velocity(t - h)) / (2 * h);
      EXPECT_NEAR(du, o.velocity(t), 1e-7) << b << " t=" << t;
      EXPECT_NEAR(o.m * dv + o.b * o.velocity(t) + o.k * o.displacement(t), 0.0, 1e-6) << b << " t=" << t;
    }
  }
}

// The orbit starts where it was given, returns there after one period, keeps the vis-viva energy
// and the angular momentum along the way (velocity from central differences of position()).
TEST(StudyClosedForms, KeplerOrbitKeepsEnergyAndAngularMomentum) {
  const double mu = 1.0;
  const Vec2 r0(1.0, 0.0), v0(0.0, 0.8);
  const KeplerOrbit orbit(mu, r0, v0);
  ASSERT_TRUE(orbit.ok());
  EXPECT_NEAR(orbit.eccentricity(), 0.36, 1e-12);
  EXPECT_NEAR(orbit.semiMajorAxis(), 1 / 1.36, 1e-12);
  EXPECT_NEAR(orbit.period(), 2 * M_PI * std::pow(1 / 1.36, 1.5), 1e-12);
  EXPECT_LT((orbit.position(0) - r0).norm(), 1e-12);
  EXPECT_LT((orbit.position(orbit.period()) - r0).norm(), 1e-10);
  const double h = 1e-6;
  for (double t : {0.3, 1.1, 2.0, 3.5}) {
    const Vec2 r = orbit.position(t), v = (orbit.position(t + h) - orbit.position(t - h)) / (2 * h);
    EXPECT_NEAR(0.5 * v.squaredNorm() - mu / r.norm(), orbit.specificEnergy(), 1e-7) << t;
    EXPECT_NEAR(cross(r, v), orbit.specificAngularMomentum(), 1e-7) << t;
  }
  EXPECT_FALSE(KeplerOrbit(mu, r0, Vec2(0, 1.5)).ok());  // faster than escape speed: unbound
}

TEST(StudyClosedForms, DiskCollisionKeepsMomentumAndScalesNormalSpeedByCor) {
  const Vec2 x1(-0.5, 0), v1(1, 0), x2(0.5, 0.1), v2(-1, 0);
  for (double cor : {0.0, 0.5, 1.0}) {
    const DiskCollision c = diskCollision(x1, v1, 1.0, 0.1, x2, v2, 2.0, 0.1, cor);
    ASSERT_TRUE(c.ok);
    EXPECT_NEAR((x2 + v2 * c.time - x1 - v1 * c.time).norm(), 0.2, 1e-12);
    EXPECT_LT((1.0 * c.v1After + 2.0 * c.v2After - (1.0 * v1 + 2.0 * v2)).norm(), 1e-12);
    EXPECT_NEAR((c.v1After - c.v2After).dot(c.normal), -cor * (v1 - v2).dot(c.normal), 1e-12);
    if (cor == 1.0) {
      EXPECT_NEAR(0.5 * c.v1After.squaredNorm() + c.v2After.squaredNorm(),
                  0.5 * v1.squaredNorm() + v2.squaredNorm(), 1e-12);
    }
  }
  EXPECT_FALSE(diskCollision(x1, v1, 1, 0.1, x2, v1, 1, 0.1, 1).ok);  // same velocity: never meet
}

TEST(StudyClosedForms, FloorBounceTouchesAtTheContactTimeAndLeavesWithMinusCorTimesItsSpeed) {
  for (double cor : {0.0, 0.5, 1.0}) {
    const FloorBounce b{Vec2(0, 1), Vec2(1, 0), 9.81, 0.1, cor};
    const double tc = b.contactTime();
    EXPECT_NEAR(tc, std::sqrt(2 * 0.9 / 9.81), 1e-12);
    EXPECT_NEAR(b.position(tc).y(), 0.1, 1e-12);
    EXPECT_NEAR(b.velocity(tc + 1e-12).y(), -cor * b.velocityBefore().y(), 1e-9);
    if (cor > 0) {
      EXPECT_NEAR(b.position(b.secondContactTime()).y(), 0.1, 1e-12);
    }
  }
}

}  // namespace
}  // namespace fosssim::study
