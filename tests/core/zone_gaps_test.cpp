// A zone's rows for neighbours it has not met yet (src/core/collision/zone_rows.cpp, contactRow's
// bias): a pair still apart closes its gap by the step's end instead of stopping where it is.
// Expected positions and velocities come from momentum and the geometry, derived below.
#include "contact_physics.h"

namespace fosssim::testing {
namespace {

// Four disks of radius r and mass 1 in a row along x, without forces: disk 0 at u = 10 m/s
// touches disk 1; disk 2 is g1 = 1 cm further, disk 3 g2 = 2 cm beyond it. At COR 0 the pairs
// meet one after another and move on as one: 0 and 1 at u/2 from t = 0, close g1 by t = 2 ms,
// 0-2 at u/3 close g2 by t = 8 ms, and all four at u/4 from there. With hybrid handling and
// maxiters 1 the second contact (t = 2 ms) goes to the zones, whose solve finds the pair 2-3
// near: a row stopping it there left the four moving together 2 cm apart for ever. Whatever the
// method, momentum fixes the centre of mass, x_c(t) = x_c(0) + (u/4) t, and once the four touch
// they sit at x_c + (2k - 3) r. By the end of the first step (10 ms) they touch; from the second
// on they move at u/4.
TEST(ZoneGaps, AChainPushedThroughAZoneEndsTouchingNotApart) {
  const double r = 0.1, u = 10.0, g1 = 0.01, g2 = 0.02, h = 0.01;
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 0.0, h, Failsafe::Projection, /*maxIterations=*/1);
    const double x[4] = {0.0, 2 * r, 4 * r + g1, 6 * r + g1 + g2};
    for (int k = 0; k < 4; ++k) addBody(s, 1.0, Vec2(x[k], 0.0), Vec2(k == 0 ? u : 0.0, 0.0), r);
    const double centre = (x[0] + x[1] + x[2] + x[3]) / 4;
    auto sim = defaultModeSimulator(s);
    for (int step = 1; step <= 5; ++step) {
      ASSERT_TRUE(stepClean(*sim, s));
      for (int k = 0; k < 4; ++k) {
        const Vec2 want(centre + u / 4 * h * step + (2 * k - 3) * r, 0.0);
        EXPECT_LT((at(s.state.x, k) - want).norm(), 1e-9) << "step " << step << ", disk " << k;
        if (step >= 2) {
          EXPECT_LT((at(s.state.v, k) - Vec2(u / 4, 0.0)).norm(), 1e-9) << "step " << step << ", disk " << k;
        }
      }
    }
  }
}

// The chain above drawn at random: 3 to 6 disks of random sizes and masses in a row along x in
// free space at COR 0, the first at 2-20 m/s into the second it touches, the others up to 0.3 of
// a radius sum apart; both types, hybrid with maxiters 1 so that zones form at once. At no step's
// end does a pair that moves move on together while apart (relative normal velocity within 1e-9
// of the speeds, a gap beyond rounding and within a zone's reach): without forces only a
// contact's row sets two moving disks' normal velocities equal, so such a pair is a contact
// answered at a distance (2,140 pair-steps of these 400 rows when a zone stopped pairs where they
// stood). Momentum is kept and kinetic energy never grows.
TEST(ZoneGaps, RandomRowsLeaveNoPairMovingTogetherApart) {
  for (const char* type : kEventTypes)
    for (int seed = 0; seed < 200; ++seed) {
      SCOPED_TRACE(std::string(type) + " seed " + std::to_string(seed));
      Rng rng(seed);
      TestScene s = contactScene(type, 0.0, 0.01, Failsafe::Projection, /*maxIterations=*/1);
      const int n = uniformInt(rng, 3, 6);
      double x = 0, last = 0;
      for (int i = 0; i < n; ++i) {
        const double radius = uniform(rng, 0.05, 0.1);
        const double gap = i < 2 ? 0.0 : uniform(rng, 0.0, 0.3) * (radius + last);
        x += i == 0 ? 0.0 : last + radius + gap;
        const double speed = i == 0 ? uniform(rng, 2.0, 20.0) : 0.0;
        const double mass = uniform(rng, 0.5, 2.0);
        addBody(s, mass, Vec2(x, 0.0), Vec2(speed, 0.0), radius);
        last = radius;
      }
      const Vec2 p0 = momentum(s);
      auto sim = defaultModeSimulator(s);
      for (int k = 0; k < 10; ++k) {
        const double before = kinetic(s);
        ASSERT_TRUE(stepClean(*sim, s));
        ASSERT_LE(kinetic(s), before * (1 + 1e-12)) << "step " << k + 1;
        double fastest = 0;
        for (int i = 0; i < n; ++i) fastest = std::max(fastest, at(s.state.v, i).norm());
        for (int i = 0; i < n; ++i)
          for (int j = i + 1; j < n; ++j) {
            const Vec2 d = at(s.state.x, j) - at(s.state.x, i);
            const double radii = s.scene.radius[i] + s.scene.radius[j], gap = d.norm() - radii;
            const bool moving = std::min(at(s.state.v, i).norm(), at(s.state.v, j).norm()) > 1e-6 * fastest;
            if (gap <= 1e-6 * radii || gap > 0.5 * radii || !moving) continue;  // not yet hit: at rest
            const double closing = (at(s.state.v, j) - at(s.state.v, i)).dot(d / d.norm());
            EXPECT_GT(std::fabs(closing), 1e-9 * fastest)
                << "step " << k + 1 << ": disks " << i << " and " << j << " move on " << gap << " apart";
          }
      }
      EXPECT_LT((momentum(s) - p0).norm(), 1e-12 * 40);  // momenta up to 2 kg at 20 m/s
    }
}

}  // namespace
}  // namespace fosssim::testing
