// What a simulator reads from its scene and what it owns (include/fosssim/core/simulator.h):
// settings once at creation, a scene finalised once, nothing shared between simulators.
#include "support/collision_type.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

/// Disks dropped onto a floor in a block, touching from the start: the penalty force has many
/// pairs within reach in every step.
TestScene penaltyPile(int side) {
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.dt = 0.001;
  s.scene.collision.type = CollisionType::Penalty;
  s.scene.collision.penaltyK = 1000.0;
  s.scene.collision.penaltyThickness = 0.01;
  for (int row = 0; row < side; ++row)
    for (int col = 0; col < side; ++col)
      addBody(s, 1.0, Vec2(0.19 * col + 0.01 * (row % 2), 0.1 + 0.19 * row), Vec2(0.1 * (col % 3) - 0.1, 0), 0.1);
  addFloorAndGravity(s);
  finalizeScene(s.scene);
  return s;
}

int penaltyForces(const Scene& scene) {
  int count = 0;
  for (const auto& f : scene.forces) count += dynamic_cast<const PenaltyForce*>(f.get()) != nullptr;
  return count;
}

TEST(SimulatorSettings, FinalizeSceneAddsTheImpliedPenaltyForceOnceAndLast) {
  TestScene s = penaltyPile(2);  // finalised once already
  finalizeScene(s.scene);
  ASSERT_EQ(penaltyForces(s.scene), 1);
  const auto* penalty = dynamic_cast<const PenaltyForce*>(s.scene.forces.back().get());
  ASSERT_NE(penalty, nullptr) << "the penalty force is summed last, as in the reference";
  EXPECT_EQ(penalty->stiffness(), 1000.0);
  EXPECT_EQ(penalty->thickness(), 0.01);

  for (const char* type : {"none", "simple", "continuous-time"}) {
    TestScene other = testing::spring("symplectic-euler", 0.01, 1.0);
    other.scene.collision.type = test::collisionType(type);
    finalizeScene(other.scene);
    EXPECT_EQ(penaltyForces(other.scene), 0) << type;
  }
  TestScene hybrid = testing::spring("symplectic-euler", 0.01, 1.0);
  hybrid.scene.collision.type = CollisionType::Hybrid;
  finalizeScene(hybrid.scene);
  EXPECT_EQ(penaltyForces(hybrid.scene), 1);
}

TEST(SimulatorSettings, AStepRefusesSettingsChangedAfterCreation) {
  auto changed = [](auto&& change) {
    TestScene s = testing::spring("symplectic-euler", 0.01, 1.0);
    std::unique_ptr<Simulator> sim;
    EXPECT_TRUE(Simulator::create(s.scene, SimulatorOptions{}, sim).isOk());
    EXPECT_TRUE(sim->step(s.scene, s.state).isOk());
    change(s.scene);
    const State before = s.state;
    const Status st = sim->step(s.scene, s.state);
    if (!st.isOk()) {
      EXPECT_EQ(s.state.x, before.x) << "nothing moves on a refused step";
      EXPECT_EQ(s.state.step, before.step);
    }
    return st;
  };
  for (const Status& st : {changed([](Scene& sc) { sc.dt = 0.02; }),
                           changed([](Scene& sc) { sc.integrator = "explicit-euler"; }),
                           changed([](Scene& sc) { sc.collision.cor = 0.5; }),
                           changed([](Scene& sc) { sc.collision.maxIterations = 3; })}) {
    EXPECT_FALSE(st.isOk());
    EXPECT_NE(st.message().find("settings"), std::string::npos) << st.message();
    EXPECT_NE(st.message().find("create a new simulator"), std::string::npos) << st.message();
  }
  EXPECT_TRUE(changed([](Scene&) {}).isOk()) << "an unchanged scene steps on";
}

/// Runs `steps` steps of a fresh pile with the given options; the end state.
State run(int steps, const HandlerOptions& handler) {
  TestScene s = penaltyPile(12);
  SimulatorOptions options;
  options.handler = handler;
  std::unique_ptr<Simulator> sim;
  EXPECT_TRUE(Simulator::create(s.scene, options, sim).isOk());
  for (int k = 0; k < steps; ++k) EXPECT_TRUE(sim->step(s.scene, s.state).isOk());
  return s.state;
}

// Each simulator owns the penalty force's pair search (its ForceContext): simulators with
// different options stepping at the same time on different threads, one of them forcing every
// pair, get exactly what each gets alone.
TEST(SimulatorSettings, SimulatorsOnDifferentThreadsShareNothing) {
  HandlerOptions grid, every;
  every.allPairs = true;
  const State alone = run(40, grid);
  State first, second;
  std::thread a([&] { first = run(40, grid); });
  std::thread b([&] { second = run(40, every); });
  a.join();
  b.join();
  EXPECT_EQ(first.x, alone.x);
  EXPECT_EQ(first.v, alone.v);
  EXPECT_EQ(second.x, alone.x) << "all pairs and the broad phase find the same pairs";
  EXPECT_EQ(second.v, alone.v);
  EXPECT_NE(alone.x, penaltyPile(12).state.x) << "the pile moved";
}

// A scene built in code that does not hold together is refused with a message, at creation or at
// the step that finds it, instead of a step that reads out of bounds (each case below crashed or
// ran on garbage before: an edge to particle 7 of one, a state of the wrong size, an empty mass).
TEST(SimulatorSettings, AMisshapenSceneOrStateIsAnErrorNotACrash) {
  const auto base = [] {
    TestScene s;
    s.scene.integrator = "symplectic-euler";
    s.scene.dt = 0.01;
    s.scene.collision.type = CollisionType::ContinuousTime;
    addBody(s, 1.0, Vec2(0, 0), Vec2(1, 0));
    addBody(s, 1.0, Vec2(1, 0), Vec2(0, 0));
    return s;
  };
  const auto refusedAtCreate = [](TestScene& s, const SimulatorOptions& options, const std::string& says) {
    std::unique_ptr<Simulator> sim;
    const Status status = Simulator::create(s.scene, options, sim);
    EXPECT_FALSE(status.isOk());
    EXPECT_NE(status.message().find(says), std::string::npos) << status.message();
  };
  {
    TestScene s = base();
    s.scene.edges.push_back(Edge{0, 7, 0.01});
    refusedAtCreate(s, {}, "edge 0 joins particles 0 and 7");
  }
  {
    TestScene s = base();
    s.scene.forces.push_back(std::make_unique<SpringForce>(0, 5, 1.0, 1.0, 0.0));
    refusedAtCreate(s, {}, "acts on particles 0 and 5");
  }
  {
    TestScene s = base();
    s.scene.mass.resize(0);
    refusedAtCreate(s, {}, "particle arrays disagree");
  }
  for (double dt : {-1.0, 0.0, std::nan("")}) {
    TestScene s = base();
    s.scene.dt = dt;
    refusedAtCreate(s, {}, "time step must be positive");
  }
  {
    TestScene s = base();
    SimulatorOptions options;
    options.handler.threads = -3;
    refusedAtCreate(s, options, "threads must be at least 1");
  }
  // At the step: a state that does not fit, and an edge added after creation.
  TestScene s = base();
  std::unique_ptr<Simulator> sim;
  ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
  ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
  State empty;
  const Status wrongState = sim->step(s.scene, empty);
  EXPECT_FALSE(wrongState.isOk());
  EXPECT_NE(wrongState.message().find("the state has 0 position"), std::string::npos) << wrongState.message();
  s.scene.edges.push_back(Edge{1, 2, 0.01});
  const Status badEdge = sim->step(s.scene, s.state);
  EXPECT_FALSE(badEdge.isOk());
  EXPECT_NE(badEdge.message().find("step 2"), std::string::npos) << badEdge.message();
  s.scene.edges.back().j = 0;
  EXPECT_TRUE(sim->step(s.scene, s.state).isOk()) << "a mended scene steps on";
}

// An index changed in place between steps (no count changes) is found at the next step, as one
// added: a step once checked the shape only when a count changed, and read out of bounds here.
TEST(SimulatorSettings, AnIndexChangedInPlaceBetweenStepsIsAnError) {
  TestScene s = testing::spring("symplectic-euler", 0.01, 1.0);  // edge 0 and its spring, force 0
  s.scene.collision.type = CollisionType::ContinuousTime;
  std::unique_ptr<Simulator> sim;
  ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
  ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
  s.scene.edges[0].j = 100000000;
  const State before = s.state;
  const Status badEdge = sim->step(s.scene, s.state);
  EXPECT_FALSE(badEdge.isOk());
  EXPECT_NE(badEdge.message().find("step 2"), std::string::npos) << badEdge.message();
  EXPECT_NE(badEdge.message().find("edge 0 joins particles 0 and 100000000"), std::string::npos) << badEdge.message();
  EXPECT_EQ(s.state.x, before.x) << "nothing moves on a refused step";
  s.scene.edges[0].j = 1;
  ASSERT_TRUE(sim->step(s.scene, s.state).isOk()) << "a mended scene steps on";

  // The spring's particles, changed in place: a force of the same count.
  s.scene.forces[0] = std::make_unique<SpringForce>(0, 9, 1.0, 1.0, 0.0);
  const Status badForce = sim->step(s.scene, s.state);
  EXPECT_FALSE(badForce.isOk());
  EXPECT_NE(badForce.message().find("force 0 ('springforce') acts on particles 0 and 9"), std::string::npos)
      << badForce.message();
}

// Before its first step a simulator has no step's motion to check: no pairs (it read an empty
// start state, out of bounds, before).
TEST(SimulatorSettings, UnresolvedBeforeTheFirstStepIsEmpty) {
  TestScene s;
  s.scene.integrator = "symplectic-euler";
  s.scene.collision.type = CollisionType::ContinuousTime;
  addBody(s, 1.0, Vec2(0, 0), Vec2(10, 0));  // closing at 20 m/s: they meet within the first step
  addBody(s, 1.0, Vec2(0.25, 0), Vec2(-10, 0));
  for (const CollisionType type : {CollisionType::ContinuousTime, CollisionType::None}) {
    s.scene.collision.type = type;
    std::unique_ptr<Simulator> sim;
    ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
    EXPECT_TRUE(sim->unresolved(s.scene, s.state).empty());
    State state = s.state;
    ASSERT_TRUE(sim->step(s.scene, state).isOk());
    if (type == CollisionType::None) {  // after a step without collision handling they are found
      EXPECT_FALSE(sim->unresolved(s.scene, state).empty());
    }
  }
}

}  // namespace
}  // namespace fosssim
