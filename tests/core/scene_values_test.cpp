// The values a scene built in code may hold (include/fosssim/core/scene_values.h): refused at
// Simulator::create, and at a step when changed in place since, with the element, its index and
// the value named, in the loader's words. Each case below was taken before (a mass of -1 and a
// COR of 5 ran on; a zero normal or a NaN COR ran into "overflow" messages steps later).
#include "fosssim/core/scene_values.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

/// Two disks, an edge between them, a floor, gravity: every kind of element, all values valid.
TestScene valid() {
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = 0.01;
  s.scene.duration = 1;
  s.scene.collision.type = CollisionType::Hybrid;
  s.scene.collision.cor = 0.5;
  addBody(s, 1.0, Vec2(0, 0.3), Vec2(0, 0));
  addBody(s, 1.0, Vec2(0.5, 0.3), Vec2(0, 0));
  s.scene.edges.push_back(Edge{0, 1, 0.05});
  testing::addFloorAndGravity(s);
  finalizeScene(s.scene);
  return s;
}

Status created(const TestScene& s) {
  std::unique_ptr<Simulator> sim;
  return Simulator::create(s.scene, {}, sim);
}

struct Case {
  const char* says;
  std::function<void(Scene&)> change;
};

const double nan = std::numeric_limits<double>::quiet_NaN();

const Case kCases[] = {
    {"particle 1's mass: must be > 0, got -1", [](Scene& s) { s.mass[2] = s.mass[3] = -1; }},
    {"particle 0's mass: must be > 0, got 0", [](Scene& s) { s.mass[0] = s.mass[1] = 0; }},
    {"particle 0's mass: must be finite, got nan", [](Scene& s) { s.mass[0] = s.mass[1] = nan; }},
    {"particle 0's mass: too small: 1/m is not finite", [](Scene& s) { s.mass[0] = s.mass[1] = 1e-320; }},
    {"particle 0's radius: must be > 0, got -1", [](Scene& s) { s.radius[0] = -1; }},
    {"particle 1's radius: must be > 0, got 0", [](Scene& s) { s.radius[1] = 0; }},
    {"edge 0's radius: must be > 0, got 0", [](Scene& s) { s.edges[0].radius = 0; }},
    {"edge 0: an edge needs two different particles, got i = j = 0", [](Scene& s) { s.edges[0].j = 0; }},
    {"half-plane 0: the half-plane normal (nx, ny) must not be zero",
     [](Scene& s) { s.halfplanes[0].normal = Vec2::Zero(); }},
    {"half-plane 0: its point and normal must be finite", [](Scene& s) { s.halfplanes[0].point.x() = nan; }},
    {"half-plane 0: the normal (1e+200, 0)'s squared length overflows",
     [](Scene& s) { s.halfplanes[0].normal = Vec2(1e200, 0); }},
    {"the collision's COR: must lie in [0, 1], got 5", [](Scene& s) { s.collision.cor = 5; }},
    {"the collision's COR: must be finite, got nan", [](Scene& s) { s.collision.cor = nan; }},
    {"the collision's maxiters: must be at most 10000, got 10001", [](Scene& s) { s.collision.maxIterations = 10001; }},
    {"the collision's penalty k: must be >= 0, got -1", [](Scene& s) { s.collision.penaltyK = -1; }},
    {"the duration: must be >= 0, got -5", [](Scene& s) { s.duration = -5; }},
    {"duration / dt = 1e+12 / 0.01 asks for 1e+14 steps; at most 1e+12", [](Scene& s) { s.duration = 1e12; }},
};

TEST(SceneValues, AValidSceneIsAccepted) {
  const TestScene s = valid();
  EXPECT_TRUE(checkSceneValues(s.scene).isOk()) << checkSceneValues(s.scene).message();
  EXPECT_TRUE(created(s).isOk());
}

TEST(SceneValues, CreateRefusesEachBadValueNamingItsElementAndField) {
  for (const Case& c : kCases) {
    TestScene s = valid();
    c.change(s.scene);
    const Status status = created(s);
    EXPECT_FALSE(status.isOk()) << c.says;
    EXPECT_NE(status.message().find(c.says), std::string::npos) << status.message();
  }
}

// The settings (COR, maxiters, k) cannot change between steps at all (a new simulator is needed);
// the contents can, and a bad one is the next step's error, the state left as it was.
TEST(SceneValues, AStepRefusesABadValueChangedInPlaceSinceCreation) {
  int checked = 0;
  for (const Case& c : kCases) {
    TestScene s = valid();
    std::unique_ptr<Simulator> sim;
    ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
    ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
    const CollisionSettings settings = s.scene.collision;
    c.change(s.scene);
    const CollisionSettings& now = s.scene.collision;
    if (now.cor != settings.cor || now.maxIterations != settings.maxIterations || now.penaltyK != settings.penaltyK)
      continue;  // "the scene's settings changed" (simulator_settings_test.cpp)
    const State before = s.state;
    const Status status = sim->step(s.scene, s.state);
    EXPECT_FALSE(status.isOk()) << c.says;
    EXPECT_NE(status.message().find("step 2"), std::string::npos) << status.message();
    EXPECT_NE(status.message().find(c.says), std::string::npos) << status.message();
    EXPECT_EQ(s.state.x, before.x) << c.says;
    ++checked;
  }
  EXPECT_EQ(checked, 13);
}

// The loader's rules are these: the same words for the same values.
TEST(SceneValues, TheRulesWordTheirProblemsAsTheLoaderDoes) {
  EXPECT_EQ(valueProblem(ValueRule::Positive, 2, "m"), "");
  EXPECT_EQ(valueProblem(ValueRule::Positive, 0, "m"), "must be > 0");
  EXPECT_EQ(valueProblem(ValueRule::Positive, 1e-320, "dt"), "too small: 1/dt is not finite (at least about 5.6e-309)");
  EXPECT_EQ(valueProblem(ValueRule::NonNegative, 0, "k"), "");
  EXPECT_EQ(valueProblem(ValueRule::NonNegative, -0.5, "k"), "must be >= 0");
  EXPECT_EQ(valueProblem(ValueRule::Fraction, 1, "COR"), "");
  EXPECT_EQ(valueProblem(ValueRule::Fraction, 1.5, "COR"), "must lie in [0, 1]");
  EXPECT_EQ(valueProblem(ValueRule::Fraction, nan, "COR"), "must be finite");
  EXPECT_EQ(stepCountProblem(1, 0.01), "");
  EXPECT_NE(stepCountProblem(1e9, 1e-9).find("asks for 1e+18 steps; at most 1e+12"), std::string::npos);
}

}  // namespace
}  // namespace fosssim
