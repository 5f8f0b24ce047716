// Per-step diagnostics against what physics says for small scenes: free fall (momentum grows by
// m g dt per step, energy computed independently), a stretched spring (its potential is
// k/2 (l - l0)^2), a head-on elastic collision (one contact, momentum kept), and the table's
// shape (one value per column, in the documented order).
#include "fosssim/core/diagnostics.h"

#include "contact_physics.h"
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim::testing {
namespace {

TEST(Diagnostics, FreeFallMomentumAndEnergy) {
  const double g = -9.81, m = 2.0, dt = 0.01;
  TestScene s = projectile("symplectic-euler", dt, Vec2(1.5, 0), Vec2(0, g));
  std::unique_ptr<Simulator> sim;
  ASSERT_TRUE(Simulator::create(s.scene, SimulatorOptions{}, sim).isOk());
  StepDiagnostics d;
  for (int k = 1; k <= 50; ++k) {
    ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
    measureStep(s.scene, s.state, sim->log(), sim->stats(), d);
    EXPECT_EQ(d.step, k);
    EXPECT_NEAR(d.time, k * dt, 1e-12);
    // p = m v: horizontal constant, vertical m g t (symplectic Euler's velocity is exact here).
    EXPECT_DOUBLE_EQ(d.momentumX, m * 1.5);
    EXPECT_NEAR(d.momentumY, m * g * k * dt, 1e-10);
    const Vec2 x = s.state.x.segment<2>(0), v = s.state.v.segment<2>(0);
    EXPECT_NEAR(d.kinetic, 0.5 * m * v.squaredNorm(), 1e-12);
    ASSERT_EQ(d.potential.size(), 1u);
    EXPECT_NEAR(d.potential[0], -m * g * x.y(), 1e-12);  // E = -m g . x
    EXPECT_NEAR(d.angularMomentum, m * (x.x() * v.y() - x.y() * v.x()), 1e-12);
    EXPECT_EQ(d.contacts, 0);
  }
}

TEST(Diagnostics, SpringPotentialIsHalfKStretchSquared) {
  const double k = 40.0;
  TestScene s = spring("symplectic-euler", 0.001, k, 1.5);
  StepDiagnostics d;
  measureState(s.scene, s.state, d);
  ASSERT_EQ(d.potential.size(), 1u);
  EXPECT_DOUBLE_EQ(d.potential[0], 0.5 * k * 0.5 * 0.5);
  EXPECT_EQ(d.kinetic, 0.0);
  EXPECT_EQ(d.momentumX, 0.0);
}

TEST(Diagnostics, ElasticHeadOnCollisionCountsOneContactAndKeepsMomentum) {
  for (const char* type : kEventTypes) {
    SCOPED_TRACE(type);
    TestScene s = contactScene(type, 1.0);
    addBody(s, 1.0, Vec2(-0.5, 0), Vec2(2, 0));
    addBody(s, 3.0, Vec2(0.5, 0), Vec2(-1, 0));
    std::unique_ptr<Simulator> sim = defaultModeSimulator(s);
    StepDiagnostics before, d;
    measureState(s.scene, s.state, before);
    long contacts = 0;
    for (int k = 0; k < 60; ++k) {
      ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
      measureStep(s.scene, s.state, sim->log(), sim->stats(), d);
      contacts += d.contacts;
      EXPECT_NEAR(d.momentumX, before.momentumX, 1e-12);
      EXPECT_NEAR(d.kinetic, before.kinetic, 1e-9);  // elastic
    }
    EXPECT_EQ(contacts, 1);  // the disks meet once (they separate afterwards)
  }
}

TEST(Diagnostics, RowMatchesColumns) {
  TestScene s = spring("explicit-euler", 0.01, 10.0);
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -1)));
  const std::vector<std::string> columns = diagnosticColumns(s.scene);
  StepDiagnostics d;
  measureState(s.scene, s.state, d);
  std::vector<double> row;
  diagnosticRow(d, row);
  ASSERT_EQ(row.size(), columns.size());
  auto value = [&](const std::string& name) {
    for (size_t k = 0; k < columns.size(); ++k)
      if (columns[k] == name) return row[k];
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_EQ(columns.front(), "step");
  EXPECT_EQ(columns.back(), "cost_total");
  EXPECT_EQ(value("potential_0_springforce") + value("potential_1_simplegravity"), value("potential"));
  EXPECT_EQ(value("kinetic") + value("potential"), value("energy"));
}

}  // namespace
}  // namespace fosssim::testing
