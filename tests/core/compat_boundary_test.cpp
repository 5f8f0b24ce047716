// A contact exactly at the end of a step (tracker: two disks of radius 0.1 at x = -0.5 and 0, the
// left one at 5 m/s, dt = 0.01): the step in which each mode responds.
//
// The disks touch when the left one has travelled 0.3, after 6 steps of 0.05. In step 6 the
// particle-particle polynomials are [-0.0024999999999999988, 0.025, -0.02250000000000002] and
// [-0.0024999999999999988, 0.0125] (from the start position -0.25000000000000006): the exact
// root of the first is 1.00000000000000087, just past the end of the step, and p(1) is within
// Horner's rounding error of 0.
//  * The default mode's closed-form query (math::exactPP) takes the exact root of the motion as
//    represented, 1 + 8.7e-16: a miss in step 6 too, and a hit just after the start of step 7.
//    (The solver's own rule for polynomials, which snaps a root within Horner's error of the
//    end onto it, would hit at tau = 1 in step 6: math.IntervalSolverReference tests that.)
//  * The reference's rule (--compat) takes rpoly's root, 1.000000000000001, as it is: a miss;
//    in step 7 the disks overlap by an ulp at the start and the root 1.0408340855860843e-15
//    is the hit. These values come from an independent emulation of the reference's arithmetic
//    (rpoly's Quad and the closed-interval logic of its ContinuousTimeUtilities, in Python, not
//    from FOSSSim's code), which also reproduces every particle-particle and half-plane
//    collision of the conformance suite's continuous-time references bit for bit.
#include "support/collision_type.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <string>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

struct Bounce {
  int step = 0;         ///< the step whose end state has the left disk stopped (elastic, equal masses)
  double tau = -1.0;    ///< the impulse's time within that step, as a fraction of it (continuous-time only)
};

Bounce firstBounce(const std::string& type, const std::string& integrator, bool compat) {
  TestScene s;
  s.scene.integrator = integrator;
  s.scene.dt = 0.01;
  s.scene.collision.type = test::collisionType(type);
  s.scene.collision.cor = 1.0;
  addBody(s, 1.0, Vec2(-0.5, 0), Vec2(5, 0), 0.1);
  addBody(s, 1.0, Vec2(0, 0), Vec2(0, 0), 0.1);
  SimulatorOptions options;
  options.handler.compat = compat;
  std::unique_ptr<Simulator> sim;
  EXPECT_TRUE(Simulator::create(s.scene, options, sim).isOk());
  for (int step = 1; step <= 20; ++step) {
    EXPECT_TRUE(sim->step(s.scene, s.state).isOk());
    if (s.state.v[0] < 2.5) {
      Bounce b{step, -1.0};
      if (!sim->log().impulses.empty()) b.tau = sim->log().impulses[0].tau;
      // Elastic and equal masses: the velocities are exchanged whichever step it is.
      EXPECT_NEAR(s.state.v[0], 0.0, 1e-12);
      EXPECT_NEAR(s.state.v[2], 5.0, 1e-12);
      return b;
    }
  }
  ADD_FAILURE() << "no bounce in 20 steps";
  return {};
}

TEST(CompatBoundary, ContactAtTheEndOfAStep) {
  for (const char* integrator : {"symplectic-euler", "explicit-euler"}) {
    for (const char* type : {"continuous-time", "hybrid"}) {
      SCOPED_TRACE(std::string(type) + " " + integrator);
      const Bounce own = firstBounce(type, integrator, false);
      const Bounce reference = firstBounce(type, integrator, true);
      EXPECT_EQ(own.step, 7);        // the exact root lies past 1 as well
      EXPECT_EQ(reference.step, 7);  // rpoly's root lies past 1: the reference waits a step
      EXPECT_LT(own.tau, 1e-12);     // an ulp of overlap at the start of step 7
      if (std::string(type) == "continuous-time") {  // the reference's hybrid impulse list stays empty
        EXPECT_EQ(reference.tau, 1.0408340855860843e-15);
      }
    }
  }
}

}  // namespace
}  // namespace fosssim
