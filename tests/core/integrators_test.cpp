// Properties of the four integrators that follow from their definitions, not from our output:
// order of accuracy on a projectile, energy behaviour on an undamped spring, momentum kept by
// internal forces, fixed particles staying put.
#include "fosssim/core/simulator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace fosssim {
namespace {

using testing::TestScene;

const char* const kAll[] = {"explicit-euler", "symplectic-euler", "forward-backward-euler", "implicit-euler",
                            "linearized-implicit-euler"};

void run(TestScene& s, long steps) {
  std::unique_ptr<Simulator> sim;
  ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
  for (long k = 0; k < steps; ++k) ASSERT_TRUE(sim->step(s.scene, s.state).isOk());
}

TEST(Integrators, TableHasEveryKeywordOnce) {
  for (const char* keyword : kAll) EXPECT_NE(findIntegrator(keyword), nullptr) << keyword;
  EXPECT_EQ(findIntegrator("runge-kutta"), nullptr);
}

// Under constant gravity every one of these methods has a closed-form discrete solution. With
// t = n h, the exact answer is x(t) = v0 t + g t^2/2; explicit Euler lags it by g h t/2, the
// others (velocity updated first, or backward Euler, which is the same for a constant force) lead
// it by g h t/2. So the error is first order with a known constant.
TEST(Integrators, ProjectileErrorIsFirstOrderWithTheKnownConstant) {
  const Vec2 g(0, -9.81), v0(1.5, 4.0);
  const double T = 1.0;
  for (const char* keyword : kAll) {
    for (double h : {0.01, 0.005}) {
      TestScene s = testing::projectile(keyword, h, v0, g);
      run(s, std::lround(T / h));
      const Vec2 exact = v0 * T + 0.5 * g * T * T;
      const double sign = std::string(keyword) == "explicit-euler" ? -1.0 : 1.0;
      const Vec2 expectedError = sign * 0.5 * g * h * T;
      EXPECT_LT((s.state.x.head<2>() - exact - expectedError).norm(), 1e-9) << keyword << " h=" << h;
      EXPECT_LT((s.state.v.head<2>() - (v0 + g * T)).norm(), 1e-9) << keyword;  // velocities are exact
    }
  }
}

double springEnergy(const TestScene& s) {
  return kineticEnergy(s.scene, s.state.v) + potentialEnergy(s.scene, s.state.x, s.state.v);
}

// Undamped spring, omega h = 0.1, ten periods: explicit Euler gains energy, implicit Euler loses
// it, symplectic Euler keeps it within O(omega h) without drift.
TEST(Integrators, EnergyDriftIsOrderedOnAnUndampedSpring) {
  const double k = 1.0, h = 0.1 / std::sqrt(2 * k);  // two unit masses: omega^2 = 2k
  const long steps = std::lround(10 * 2 * M_PI / 0.1);
  double drift[5];
  for (int m = 0; m < 5; ++m) {
    TestScene s = testing::spring(kAll[m], h, k);
    const double e0 = springEnergy(s);
    run(s, steps);
    drift[m] = (springEnergy(s) - e0) / e0;
  }
  EXPECT_GT(drift[0], 0.5);               // explicit: grows by (1 + (omega h)^2)^n
  EXPECT_LT(std::fabs(drift[1]), 0.06);   // symplectic: bounded oscillation
  EXPECT_EQ(drift[1], drift[2]);          // the two names are the same method
  EXPECT_LT(drift[3], -0.5);              // implicit: decays
  EXPECT_LT(drift[4], -0.5);              // linearized implicit: the same for a linear spring
  EXPECT_NEAR(drift[3], drift[4], 1e-6);
}

TEST(Integrators, InternalForcesKeepMomentum) {
  for (const char* keyword : kAll) {
    TestScene s = testing::spring(keyword, 0.01, 50.0);
    s.state.v << 1.0, 2.0, -0.5, 0.25;
    s.scene.mass[2] = s.scene.mass[3] = 3.0;
    s.scene.forces.push_back(std::make_unique<GravitationalForce>(0, 1, 0.7));
    auto momentum = [&] { return (s.scene.mass.cwiseProduct(s.state.v)).reshaped(2, 2).rowwise().sum().eval(); };
    const Vec2 p0 = momentum();
    run(s, 200);
    EXPECT_LT((momentum() - p0).norm(), 1e-9) << keyword;
  }
}

TEST(Integrators, FixedParticlesNeverMove) {
  for (const char* keyword : kAll) {
    TestScene s = testing::spring(keyword, 0.01, 20.0);
    s.scene.fixed[0] = 1;
    s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
    const Vec2 x0 = s.state.x.head<2>();
    run(s, 100);
    EXPECT_EQ(s.state.x.head<2>(), x0) << keyword;
    EXPECT_EQ(s.state.v.head<2>(), Vec2::Zero()) << keyword;
    EXPECT_NE(s.state.x.tail<2>(), Vec2(1.5, 0)) << keyword;  // the free end does move
  }
}

// Implicit Euler's result satisfies its defining equation M (v' - v) = h F(x + h v', v').
TEST(Integrators, ImplicitEulerSolvesItsEquation) {
  TestScene s = testing::spring("implicit-euler", 0.05, 100.0, 1.7);
  s.scene.forces.push_back(std::make_unique<GravitationalForce>(0, 1, 2.0));
  s.scene.forces.push_back(std::make_unique<DragDampingForce>(0.3));
  const State before = s.state;
  run(s, 1);
  VecX grad = VecX::Zero(4);
  accumulateGradient(s.scene, s.state.x, s.state.v, grad);
  const VecX residual = s.scene.mass.cwiseProduct(s.state.v - before.v) + 0.05 * grad;
  EXPECT_LT(residual.norm(), 1e-8);
  EXPECT_LT((s.state.x - before.x - 0.05 * s.state.v).norm(), 1e-14);
}

/// A particle pulled toward x = 0 by F = -k L atan(x / L) (a spring that softens with its
/// stretch): potential k L (x atan(x/L) - L/2 ln(1 + x^2/L^2)), stiffness k / (1 + x^2/L^2).
class AtanSpring final : public Force {
 public:
  AtanSpring(double k, double length) : k_(k), length_(length) {}
  const char* keyword() const override { return "atan spring"; }
  void addGradient(const Scene&, const VecX& x, const VecX&, VecX& gradE) const override {
    gradE[0] += k_ * length_ * std::atan(x[0] / length_);
  }
  void addJacobianX(const Scene&, const VecX& x, const VecX&, Triplets& out) const override {
    const double r = x[0] / length_;
    out.emplace_back(0, 0, k_ / (1 + r * r));
  }

 private:
  double k_, length_;
};

// Implicit Euler on that spring from x = 10 L at rest, with h^2 k / m = 1000: the step's end u
// solves u - x + (h^2 k / m) atan(u / L) = 0, a root near 0.01 L where the function is steep and
// flat far from it. Newton's full steps from u = x overshoot to about -125 L and on outwards (the
// --compat iteration, the reference's, fails); the default mode's line search converges. Expected
// u from bisection of that equation, independent of the integrator.
TEST(Integrators, ImplicitEulerConvergesWhereFullNewtonStepsOvershoot) {
  const double m = 1.0, h = 0.1, k = 1e5, length = 1.0, x0 = 10.0;
  TestScene s;
  testing::addBody(s, m, Vec2(x0, 0), Vec2::Zero(), 0.1);
  s.scene.forces.push_back(std::make_unique<AtanSpring>(k, length));
  s.scene.integrator = "implicit-euler";
  s.scene.dt = h;
  double lo = -x0, hi = x0;  // g(lo) < 0 < g(hi), g increasing
  const auto g = [&](double u) { return u - x0 + h * h * k / m * std::atan(u / length); };
  for (int i = 0; i < 200; ++i) (g(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  const double u = 0.5 * (lo + hi);
  for (bool course : {false, true}) {
    std::unique_ptr<Integrator> integrator = findIntegrator("implicit-euler")->make();
    integrator->setCourseForm(course);
    State state = s.state;
    ForceContext context;
    const Status status = integrator->step(s.scene, state, h, context);
    if (course) {
      EXPECT_FALSE(status.isOk() && std::abs(state.x[0] - u) < 1e-9) << "plain Newton should not find the root";
      continue;
    }
    ASSERT_TRUE(status.isOk()) << status.message();
    EXPECT_NEAR(state.x[0], u, 1e-9 * x0);
    EXPECT_NEAR(state.v[0], (u - x0) / h, 1e-9 * x0 / h);
  }
}

// Three disks (m = 1, r = 0.1) resting on a floor in a penalty layer (k = 1e4, thickness 0.01)
// under gravity, implicit Euler at dt = 0.01. The penalty force has no Jacobian (it is treated
// explicitly), so Newton's direction is only approximate, and its full steps cycled from the first
// step on ("did not converge"; the reference's iteration, --compat, still does). The default
// mode's line search settles them where the layer carries their weight: k (r + thickness - y) =
// m g, y = 0.10902, at rest.
TEST(Integrators, ImplicitEulerSettlesDisksOnAPenaltyFloor) {
  const double h = 0.01, k = 1e4, thickness = 0.01, r = 0.1, g = 9.81;
  TestScene s;
  for (double x : {-0.3, 0.0, 0.3}) testing::addBody(s, 1.0, Vec2(x, r), Vec2::Zero(), r);
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, 0), Vec2(0, 1)});
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -g)));
  s.scene.forces.push_back(std::make_unique<PenaltyForce>(k, thickness));
  s.scene.dt = h;
  for (bool course : {false, true}) {
    std::unique_ptr<Integrator> integrator = findIntegrator("implicit-euler")->make();
    integrator->setCourseForm(course);
    State state = s.state;
    ForceContext context;
    Status status = Status::ok();
    for (int step = 0; step < 300 && status.isOk(); ++step) status = integrator->step(s.scene, state, h, context);
    if (course) {
      EXPECT_FALSE(status.isOk()) << "the reference's full Newton steps should not converge here";
      continue;
    }
    ASSERT_TRUE(status.isOk()) << status.message();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(state.x[2 * i + 1], r + thickness - g / k, 1e-6) << "disk " << i;
      EXPECT_LT(at(state.v, i).norm(), 1e-6) << "disk " << i;
    }
  }
}

TEST(Simulator, NonFiniteStateIsReportedWithStepAndParticle) {
  TestScene s = testing::spring("explicit-euler", 0.01, 1.0);
  s.state.x[2] = s.state.x[0];  // coincident spring ends: the direction is 0/0
  std::unique_ptr<Simulator> sim;
  ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
  const Status status = sim->step(s.scene, s.state);
  ASSERT_FALSE(status.isOk());
  EXPECT_NE(status.message().find("step 1"), std::string::npos) << status.message();
  EXPECT_NE(status.message().find("particle 0"), std::string::npos) << status.message();
}

// The implicit methods fail inside their solve (a non-finite Newton update, a singular system)
// before any state exists to check; the message still names the force and the particle, as the
// explicit methods' non-finite check does (it named neither).
TEST(Simulator, AnImplicitSolvesFailureNamesTheForceAndParticle) {
  for (const char* integrator : {"implicit-euler", "linearized-implicit-euler"}) {
    TestScene s = testing::spring(integrator, 0.01, 1.0);
    s.state.x[2] = s.state.x[0];
    std::unique_ptr<Simulator> sim;
    ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
    const Status status = sim->step(s.scene, s.state);
    ASSERT_FALSE(status.isOk());
    EXPECT_NE(status.message().find("the force 'springforce' #1 on particle 0 is non-finite"), std::string::npos)
        << integrator << ": " << status.message();
  }
}

// A spring so stiff that dt^2 k swamps the masses (k = 1e300: 1e296 times them) leaves the
// implicit system singular in floating point. The message said "singular" and nothing else; it
// names the force, the particle and what to change.
TEST(Simulator, ASingularImplicitSystemNamesTheStiffestForce) {
  for (const char* integrator : {"implicit-euler", "linearized-implicit-euler"}) {
    TestScene s = testing::spring(integrator, 0.01, 1e300);
    std::unique_ptr<Simulator> sim;
    ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
    const Status status = sim->step(s.scene, s.state);
    ASSERT_FALSE(status.isOk()) << integrator;
    const std::string& m = status.message();
    EXPECT_NE(m.find("step 1 (t = 0 to 0.01): the implicit system"), std::string::npos) << integrator << ": " << m;
    EXPECT_NE(m.find("singular; the stiffest force is 'springforce' #1 on particle 0: dt^2 times its stiffness is "
                     "1e+296 times the particle's mass"),
              std::string::npos)
        << integrator << ": " << m;
    EXPECT_NE(m.find("(its k) or dt smaller"), std::string::npos) << integrator << ": " << m;
  }
  // A stiff spring that the solve handles says nothing of the kind.
  TestScene s = testing::spring("implicit-euler", 0.01, 1e6);
  std::unique_ptr<Simulator> sim;
  ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
  EXPECT_TRUE(sim->step(s.scene, s.state).isOk());
}

}  // namespace
}  // namespace fosssim

namespace fosssim {
namespace {

// A scene without particles is nothing to integrate, not a division by zero.
TEST(Integrators, EmptySceneStepsWithoutError) {
  for (const char* keyword : kAll) {
    testing::TestScene s;
    s.scene.integrator = keyword;
    s.state.x.resize(0);
    s.state.v.resize(0);
    std::unique_ptr<Simulator> sim;
    ASSERT_TRUE(Simulator::create(s.scene, {}, sim).isOk());
    EXPECT_TRUE(sim->step(s.scene, s.state).isOk()) << keyword;
  }
}

}  // namespace
}  // namespace fosssim
