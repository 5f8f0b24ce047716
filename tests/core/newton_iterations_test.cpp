// StepStats::newtonIterations, checked against what Newton's method must do, not against our output:
// for forces linear in (x, v) the implicit equation is linear, so Newton's first update solves it
// exactly and the second is round-off (within the tolerance): exactly 2 iterations, or 1 when
// the first update is itself below the tolerance (the motion has died out). Linearized implicit
// Euler is one Newton step by definition; the explicit methods solve nothing. A particle between
// two stiff springs whose directions turn within the step is nonlinear and needs more, the more
// the larger the step, since the step's start is a worse first guess. (One spring alone is not
// enough: every iterate stays on the ray from the anchor through x + h v, along which the spring's
// force is affine.)
#include "fosssim/core/integrator.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace fosssim {
namespace {

using testing::TestScene;

/// The iteration counts of `steps` steps of `s` (--compat: the reference's tolerances); each
/// step's |v' - v| goes to `changes` and the tolerance Newton stops on to `tolerances`, if given.
std::vector<int> iterations(TestScene& s, int steps, std::vector<double>* changes = nullptr,
                            std::vector<double>* tolerances = nullptr, bool compat = false) {
  SimulatorOptions options;
  options.handler.compat = compat;
  std::unique_ptr<Simulator> sim;
  EXPECT_TRUE(Simulator::create(s.scene, options, sim).isOk());
  std::vector<int> counts;
  for (int k = 0; k < steps; ++k) {
    const VecX before = s.state.v;
    const double resting = kNewtonRestingFraction * s.state.x.norm() / s.scene.dt;
    EXPECT_TRUE(sim->step(s.scene, s.state).isOk());
    counts.push_back(sim->stats().newtonIterations);
    if (changes) changes->push_back((s.state.v - before).norm());
    if (tolerances)
      tolerances->push_back(compat ? kNewtonTolerance
                                   : kNewtonRelativeTolerance * std::max(s.state.v.norm(), resting));
  }
  return counts;
}

/// Linear forces: a zero-rest-length spring (F = -k (x_i - x_j)), drag and constant gravity, in 2D
/// with a velocity across the spring so that nothing stays on one line.
TestScene linearScene(const std::string& integrator, double dt) {
  TestScene s;
  testing::addBody(s, 1.0, Vec2(0, 0), Vec2(0, 0), 0.1, true);
  testing::addBody(s, 2.0, Vec2(1.2, 0.4), Vec2(-3, 5));
  s.scene.edges.push_back(Edge{0, 1, 0.01});
  s.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 500.0, 0.0, 0.0));
  s.scene.forces.push_back(std::make_unique<DragDampingForce>(0.4));
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  s.scene.integrator = integrator;
  s.scene.dt = dt;
  return s;
}

// Newton's first update is the step's whole velocity change (the second is round-off): 2
// iterations, or 1 where that change is already within the tolerance (the large steps damp the
// spring to rest within a few steps). The same under --compat's absolute tolerance and the
// default mode's relative one.
TEST(NewtonIterations, ImplicitEulerTakesTwoOnLinearForces) {
  for (bool compat : {true, false}) {
    for (double dt : {1e-3, 1e-2, 0.1}) {
      TestScene s = linearScene("implicit-euler", dt);
      std::vector<double> changes, tolerances;
      const std::vector<int> counts = iterations(s, 50, &changes, &tolerances, compat);
      for (size_t k = 0; k < counts.size(); ++k)
        EXPECT_EQ(counts[k], changes[k] <= tolerances[k] ? 1 : 2)
            << (compat ? "--compat" : "default") << " dt " << dt << " step " << k + 1;
      EXPECT_EQ(counts.front(), 2) << "dt " << dt;  // the first step does move
    }
  }
}

// The default mode's tolerance follows the scene's units: a light bob swinging fast on a damped
// spring from a fixed anchor (a nonlinear force), its lengths and gravity scaled by s (masses,
// stiffness, damping and times kept, so the motion is the same in units of s), takes the same
// positions over s at every scale. Under the reference's absolute 1e-9 m/s the run scaled by 10^6
// stops at its 9th step: its updates stall at 2.4e-9 m/s, rounding for speeds of 10^6 m/s.
TEST(NewtonIterations, TheDefaultModesToleranceFollowsTheScenesUnits) {
  const auto pendulum = [](double scale) {
    TestScene s;
    testing::addBody(s, 0.0014165, Vec2(0.20774, 6.14163) * scale, Vec2(4.53196, 3.67819) * scale, 0.058 * scale);
    testing::addBody(s, 1.0, Vec2(1.46897, 11.097467) * scale, Vec2::Zero(), 0.034 * scale, true);
    s.scene.edges.push_back(Edge{0, 1, 0.097 * scale});
    s.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, 10.0, 5.345 * scale, 0.1));
    s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -98.1 * scale)));
    s.scene.integrator = "implicit-euler";
    s.scene.dt = 0.005;
    return s;
  };
  TestScene unit = pendulum(1.0);
  iterations(unit, 100);
  for (double scale : {1e-6, 1e6}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    TestScene scaled = pendulum(scale);
    iterations(scaled, 100);
    EXPECT_LE((scaled.state.x / scale - unit.state.x).norm(), 1e-7 * unit.state.x.norm());
  }
}

TEST(NewtonIterations, LinearizedImplicitTakesOneAndExplicitNone) {
  for (const char* keyword : {"linearized-implicit-euler", "explicit-euler", "symplectic-euler"}) {
    TestScene s = linearScene(keyword, 0.01);
    const int expected = std::string(keyword) == "linearized-implicit-euler" ? 1 : 0;
    for (int count : iterations(s, 20)) EXPECT_EQ(count, expected) << keyword;
  }
}

// A particle between two fixed anchors on stiff springs of rest length 1, off the line between
// them and moving along it: the springs turn within the step.
TEST(NewtonIterations, StiffNonlinearSpringsNeedMoreTheLargerTheStep) {
  std::vector<int> firstStep;
  for (double dt : {1e-4, 1e-3, 1e-2}) {
    TestScene s;
    testing::addBody(s, 1.0, Vec2(0.3, 0.8), Vec2(2, 0));
    testing::addBody(s, 1.0, Vec2(-1, 0), Vec2(0, 0), 0.1, true);
    testing::addBody(s, 1.0, Vec2(1, 0), Vec2(0, 0), 0.1, true);
    for (int anchor : {1, 2}) {
      s.scene.edges.push_back(Edge{0, anchor, 0.01});
      s.scene.forces.push_back(std::make_unique<SpringForce>(0, anchor, 1e5, 1.0, 0.0));
    }
    s.scene.integrator = "implicit-euler";
    s.scene.dt = dt;
    firstStep.push_back(iterations(s, 1).front());
  }
  EXPECT_GT(firstStep.back(), 2);
  for (size_t k = 1; k < firstStep.size(); ++k) EXPECT_LE(firstStep[k - 1], firstStep[k]) << "dt index " << k;
  EXPECT_LT(firstStep.front(), firstStep.back());
}

TEST(NewtonIterations, EmptySceneSolvesNothing) {
  for (const char* keyword : {"implicit-euler", "linearized-implicit-euler"}) {
    TestScene s;
    s.scene.integrator = keyword;
    s.scene.dt = 0.01;
    s.state.x.resize(0);
    s.state.v.resize(0);
    for (int count : iterations(s, 1)) EXPECT_EQ(count, 0) << keyword;
  }
}

}  // namespace
}  // namespace fosssim
