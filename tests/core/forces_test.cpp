// Every analytic gradient and Jacobian against central finite differences, and every gradient
// against the energy it derives from, on random configurations.
#include "fosssim/core/forces.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

namespace fosssim {
namespace {

using testing::addBody;
using testing::TestScene;

/// Central-difference step: balances truncation (h^2) against rounding (eps/h) for O(1) inputs.
constexpr double kStep = 1e-6;
/// Agreement required between analytic and finite-difference values, relative to their size.
constexpr double kTolerance = 1e-6;

VecX gradient(const TestScene& s, const Force& f, const VecX& x, const VecX& v) {
  VecX g = VecX::Zero(x.size());
  f.addGradient(s.scene, x, v, g);
  return g;
}

Eigen::MatrixXd dense(const Triplets& t, Eigen::Index n) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (const Triplet& e : t) m(e.row(), e.col()) += e.value();
  return m;
}

/// Finite-difference Jacobian of the gradient with respect to x (wrtV = false) or v.
Eigen::MatrixXd numericJacobian(const TestScene& s, const Force& f, const VecX& x, const VecX& v, bool wrtV) {
  const Eigen::Index n = x.size();
  Eigen::MatrixXd J(n, n);
  for (Eigen::Index c = 0; c < n; ++c) {
    VecX xp = x, xm = x, vp = v, vm = v;
    (wrtV ? vp : xp)[c] += kStep;
    (wrtV ? vm : xm)[c] -= kStep;
    J.col(c) = (gradient(s, f, xp, vp) - gradient(s, f, xm, vm)) / (2 * kStep);
  }
  return J;
}

VecX numericGradient(const TestScene& s, const Force& f, const VecX& x, const VecX& v) {
  VecX g(x.size());
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    VecX xp = x, xm = x;
    xp[c] += kStep;
    xm[c] -= kStep;
    g[c] = (f.energy(s.scene, xp, v) - f.energy(s.scene, xm, v)) / (2 * kStep);
  }
  return g;
}

void expectClose(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric, const char* what) {
  const double scale = std::max(1.0, numeric.cwiseAbs().maxCoeff());
  EXPECT_LE((analytic - numeric).cwiseAbs().maxCoeff(), kTolerance * scale)
      << what << "\nanalytic:\n" << analytic << "\nnumeric:\n" << numeric;
}

/// Four particles at random positions and velocities (and masses), none coincident.
TestScene randomSetup(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-2, 2), vel(-1, 1), mass(0.5, 3);
  TestScene s;
  for (int i = 0; i < 4; ++i) {
    // One draw a statement (or braces): a call's arguments are evaluated in an order the compiler
    // picks (gcc right to left, clang left to right), and both must build the same setups.
    const double m = mass(rng);
    const Vec2 x{pos(rng), pos(rng)};
    const Vec2 v{vel(rng), vel(rng)};
    addBody(s, m, x, v, 0.3);
  }
  s.scene.edges.push_back(Edge{1, 2, 0.2});
  s.scene.halfplanes.push_back(HalfPlane{Vec2(0, -1.5), Vec2(0.3, 2.0)});
  return s;
}

void checkForce(const std::function<std::unique_ptr<Force>()>& make) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    TestScene s = randomSetup(rng);
    const auto force = make();
    const VecX& x = s.state.x;
    const VecX& v = s.state.v;
    SCOPED_TRACE(std::string(force->keyword()) + " trial " + std::to_string(trial));
    if (force->hasPotential()) expectClose(gradient(s, *force, x, v), numericGradient(s, *force, x, v), "gradient");
    if (force->hasJacobians()) {
      Triplets jx, jv;
      force->addJacobianX(s.scene, x, v, jx);
      force->addJacobianV(s.scene, x, v, jv);
      expectClose(dense(jx, x.size()), numericJacobian(s, *force, x, v, false), "Jacobian wrt x");
      expectClose(dense(jv, x.size()), numericJacobian(s, *force, x, v, true), "Jacobian wrt v");
    }
  }
}

TEST(Forces, SpringMatchesFiniteDifferences) {
  checkForce([] { return std::make_unique<SpringForce>(0, 2, 7.0, 0.8, 0.0); });
}
TEST(Forces, DampedSpringMatchesFiniteDifferences) {
  checkForce([] { return std::make_unique<SpringForce>(3, 1, 5.0, 1.2, 0.7); });
}
TEST(Forces, SimpleGravityMatchesFiniteDifferences) {
  checkForce([] { return std::make_unique<SimpleGravityForce>(Vec2(0.5, -9.8)); });
}
TEST(Forces, ConstantForceMatchesFiniteDifferences) {
  checkForce([] { return std::make_unique<ConstantForce>(Vec2(-1.0, 2.0)); });
}
TEST(Forces, GravitationalMatchesFiniteDifferences) {
  checkForce([] { return std::make_unique<GravitationalForce>(0, 3, 1.3); });
}
TEST(Forces, DragDampingMatchesFiniteDifferences) {
  checkForce([] { return std::make_unique<DragDampingForce>(0.4); });
}
TEST(Forces, PenaltyGradientMatchesItsEnergy) {
  checkForce([] { return std::make_unique<PenaltyForce>(50.0, 2.0); });
}

TEST(Forces, SpringPullsEndpointsTogetherWhenStretched) {
  TestScene s;
  addBody(s, 1, Vec2(0, 0), Vec2(0, 0));
  addBody(s, 1, Vec2(2, 0), Vec2(0, 0));
  SpringForce spring(0, 1, 3.0, 1.0, 0.0);
  const VecX g = gradient(s, spring, s.state.x, s.state.v);
  // F = -g: particle 0 is pulled toward +x with k (l - l0) = 3, particle 1 toward -x.
  EXPECT_DOUBLE_EQ(-g[0], 3.0);
  EXPECT_DOUBLE_EQ(-g[2], -3.0);
  EXPECT_DOUBLE_EQ(spring.energy(s.scene, s.state.x, s.state.v), 1.5);
}

TEST(Forces, VortexForceIsPerpendicularAndOpposite) {
  TestScene s;
  addBody(s, 1, Vec2(0, 0), Vec2(0, 0));
  addBody(s, 1, Vec2(2, 0), Vec2(0, 0));
  VortexForce vortex(0, 1, 0.5, 4.0);
  const VecX g = gradient(s, vortex, s.state.x, s.state.v);
  // F_j = kvc/|r|^2 * kbs * perp(rhat) = 4/4 * 0.5 * (0, 1); F_i = -F_j.
  EXPECT_NEAR(-g[2], 0.0, 1e-15);
  EXPECT_NEAR(-g[3], 0.5, 1e-15);
  EXPECT_NEAR(g[1], 0.5, 1e-15);
}

TEST(Forces, InternalForcesSumToZero) {
  std::mt19937 rng(3);
  TestScene s = randomSetup(rng);
  const std::unique_ptr<Force> forces[] = {std::make_unique<SpringForce>(0, 1, 2, 1, 0.5),
                                           std::make_unique<GravitationalForce>(1, 2, 1.0),
                                           std::make_unique<VortexForce>(0, 3, 0.8, 2.0)};
  for (const auto& f : forces) {
    const VecX g = gradient(s, *f, s.state.x, s.state.v);
    EXPECT_NEAR(g.reshaped(2, 4).rowwise().sum().norm(), 0.0, 1e-12) << f->keyword();
  }
}

TEST(Forces, PenaltyIsZeroOutsideReachAndRepulsiveInside) {
  TestScene s;
  addBody(s, 1, Vec2(0, 0), Vec2(0, 0), 0.5);
  addBody(s, 1, Vec2(1.05, 0), Vec2(0, 0), 0.5);
  PenaltyForce thin(100, 0.01), thick(100, 0.1);
  EXPECT_EQ(gradient(s, thin, s.state.x, s.state.v).norm(), 0.0);
  const VecX g = gradient(s, thick, s.state.x, s.state.v);
  EXPECT_LT(-g[0], 0.0);  // pushed apart
  EXPECT_GT(-g[2], 0.0);
  EXPECT_NEAR(-g[2], 100 * (1.1 - 1.05), 1e-12);
}

}  // namespace
}  // namespace fosssim
