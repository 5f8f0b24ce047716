// The implicit integrators' particles held at rest (ForceContext::resting; implicit_system.h):
// they leave the linear system. Eliminating a particle whose velocity change is known to be 0 is
// the same, in exact arithmetic, as the reference's treatment of a fixed particle (an identity
// row and a zero right-hand side), so a held particle must step exactly as the same particle
// marked fixed, and every other particle alike up to the rounding of the smaller system.
#include "fosssim/core/integrator.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <random>

namespace fosssim::testing {
namespace {

const char* const kImplicit[] = {"implicit-euler", "linearized-implicit-euler"};

/// n particles of random mass scattered in a square of side 0.3 sqrt(n) (disks of radius 0.05:
/// some touch within the penalty's reach), in threes joined by stiff damped springs, under
/// gravity, drag, pairwise gravitation between the first two, and a penalty layer (which the
/// implicit methods treat explicitly). Every third particle of each three starts moving.
TestScene springsAndDisks(const std::string& integrator, int n, unsigned seed) {
  TestScene s;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double side = 0.3 * std::sqrt(static_cast<double>(n));
  for (int i = 0; i < n; ++i) {
    // Draws in braces or separate statements, left to right: a call's arguments are evaluated in
    // an order the compiler picks (gcc right to left, clang left to right).
    const Vec2 v = i % 3 == 2 ? Vec2{u(rng) - 0.5, u(rng) - 0.5} : Vec2::Zero();
    const double m = 0.5 + u(rng);
    const Vec2 x{side * u(rng), side * u(rng)};
    addBody(s, m, x, v, 0.05);
  }
  for (int i = 0; i + 1 < n; ++i)
    if (i % 3 != 2) s.scene.forces.push_back(std::make_unique<SpringForce>(i, i + 1, 200.0, 0.2, 0.5));
  s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  s.scene.forces.push_back(std::make_unique<DragDampingForce>(0.1));
  s.scene.forces.push_back(std::make_unique<GravitationalForce>(0, 1, 0.01));
  s.scene.forces.push_back(std::make_unique<PenaltyForce>(50.0, 0.02));
  s.scene.integrator = integrator;
  s.scene.dt = 0.01;
  return s;
}

State stepOnce(const TestScene& s, const std::vector<char>* held) {
  std::unique_ptr<Integrator> integrator = findIntegrator(s.scene.integrator)->make();
  ForceContext context;
  context.setResting(held);
  State state = s.state;
  EXPECT_TRUE(integrator->step(s.scene, state, s.scene.dt, context).isOk());
  return state;
}

// Held particles at rest, chosen at random (whole threes or not: the elimination does not care
// what ties them), against the same particles fixed: with 20 particles the fixed ones' system is
// solved densely, with 300 by sparse LU; the reduced system always by sparse LU.
TEST(ImplicitSystem, HeldParticlesStepAsFixedOnesDoAndTheOthersAlike) {
  for (const char* keyword : kImplicit) {
    for (int n : {20, 300}) {
      for (double share : {0.2, 0.8}) {
        SCOPED_TRACE(std::string(keyword) + ", n " + std::to_string(n) + ", share " + std::to_string(share));
        TestScene s = springsAndDisks(keyword, n, 7);
        std::mt19937 rng(11);
        std::bernoulli_distribution pick(share);
        std::vector<char> held(n, 0);
        TestScene fixed = springsAndDisks(keyword, n, 7);
        for (int i = 0; i < n; ++i) {
          held[i] = pick(rng);
          if (!held[i]) continue;
          at(s.state.v, i).setZero();
          at(fixed.state.v, i).setZero();
          fixed.scene.fixed[i] = 1;
        }
        const State got = stepOnce(s, &held), expected = stepOnce(fixed, nullptr);
        double scale = 0;
        for (int i = 0; i < n; ++i) scale = std::max(scale, (at(expected.v, i) - at(s.state.v, i)).norm());
        ASSERT_GT(scale, 0.0);
        for (int i = 0; i < n; ++i) {
          if (held[i]) {
            EXPECT_EQ(at(got.x, i), at(s.state.x, i)) << "held particle " << i;
            EXPECT_EQ(at(got.v, i), Vec2::Zero()) << "held particle " << i;
            continue;
          }
          EXPECT_LT((at(got.v, i) - at(expected.v, i)).norm(), 1e-12 * scale) << "particle " << i;
          EXPECT_LT((at(got.x, i) - at(expected.x, i)).norm(), 1e-12 * scale * s.scene.dt) << "particle " << i;
        }
      }
    }
  }
}

/// A constant downward force of 1 N per particle that counts the calls made to it.
class CountingForce final : public Force {
 public:
  explicit CountingForce(int* calls) : calls_(calls) {}
  const char* keyword() const override { return "counting"; }
  void addGradient(const Scene&, const VecX&, const VecX&, VecX& gradE) const override {
    ++*calls_;
    for (Eigen::Index k = 1; k < gradE.size(); k += 2) gradE[k] += 1.0;
  }
  void addJacobianX(const Scene&, const VecX&, const VecX&, Triplets&) const override { ++*calls_; }

 private:
  int* calls_;
};

// A pile asleep costs nothing: with every movable particle held (one particle fixed), the step
// evaluates no force and changes nothing.
TEST(ImplicitSystem, WithEveryParticleHeldNothingIsEvaluatedAndNothingMoves) {
  for (const char* keyword : kImplicit) {
    SCOPED_TRACE(keyword);
    TestScene s = springsAndDisks(keyword, 30, 3);
    s.state.v.setZero();
    s.scene.fixed[4] = 1;
    int calls = 0;
    s.scene.forces.push_back(std::make_unique<CountingForce>(&calls));
    const std::vector<char> held(30, 1);
    const State got = stepOnce(s, &held);
    EXPECT_EQ(got.x, s.state.x);
    EXPECT_EQ(got.v, s.state.v);
    EXPECT_EQ(calls, 0);
    stepOnce(s, nullptr);
    EXPECT_GT(calls, 0) << "the count must see an ordinary step";
  }
}

// Masses far apart do not make a system singular. Three particles of masses 1e-9, 1 and 1e9 under
// gravity and drag (F = m g - b v, linear: one Newton step is exact), the densely solved system
// M + h b I: full-pivoting LU called it singular (its smallest pivot is 1e-18 of its largest,
// below n eps) and the step failed, although it is diagonal. Each particle's implicit step is the closed form
// m (v1 - v0) = h (m g - b v1), that is v1 = (m v0 + h m g) / (m + h b), and x1 = x0 + h v1.
TEST(ImplicitSystem, MassesFarApartAreNotASingularSystem) {
  const double h = 0.01, b = 1e-9;  // the drag matters to the lightest only
  const Vec2 g(0.0, -9.81);
  for (const char* keyword : kImplicit) {
    SCOPED_TRACE(keyword);
    TestScene s;
    addBody(s, 1e-9, Vec2(0, 0), Vec2(1, 2), 0.05);
    addBody(s, 1.0, Vec2(1, 0), Vec2(-2, 0.5), 0.05);
    addBody(s, 1e9, Vec2(2, 0), Vec2(-3, 0.5), 0.05);
    s.scene.forces.push_back(std::make_unique<SimpleGravityForce>(g));
    s.scene.forces.push_back(std::make_unique<DragDampingForce>(b));
    s.scene.integrator = keyword;
    s.scene.dt = h;
    const State got = stepOnce(s, nullptr);
    for (int i = 0; i < 3; ++i) {
      const double m = s.scene.massOf(i);
      const Vec2 v1 = (m * at(s.state.v, i) + h * m * g) / (m + h * b), x1 = at(s.state.x, i) + h * v1;
      // The step adds a change to v0 (v1 = v0 + delta): rounding of the size of |v0| + |v1|.
      const double speed = at(s.state.v, i).norm() + v1.norm();
      EXPECT_LT((at(got.v, i) - v1).norm(), 1e-12 * speed) << "particle " << i;
      EXPECT_LT((at(got.x, i) - x1).norm(), 1e-12 * (at(s.state.x, i).norm() + h * speed)) << "particle " << i;
    }
  }
}

}  // namespace
}  // namespace fosssim::testing
