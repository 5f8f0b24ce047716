// The profile's TimedForce is invisible to the simulation: the caller's ForceContext reaches the
// wrapped force (the penalty force searches its near pairs with the simulator's options and
// storage), its answers and properties come through unchanged, and every evaluation is counted.
#include "timed_force.h"

#include "fosssim/core/scene.h"

#include <gtest/gtest.h>

namespace fosssim::study {
namespace {

/// Records the context it was given and answers with fixed numbers.
class ProbeForce final : public Force {
 public:
  mutable const ForceContext* seen = nullptr;
  const char* keyword() const override { return "probe"; }
  void addGradient(const Scene&, const VecX&, const VecX&, VecX& gradE) const override { gradE[0] += 1; }
  void addGradientWith(const Scene&, const VecX&, const VecX&, VecX& gradE, ForceContext& context) const override {
    seen = &context;
    gradE[0] += 2;
  }
  double energyWith(const Scene&, const VecX&, const VecX&, ForceContext& context) const override {
    seen = &context;
    return 3;
  }
  bool hasPotential() const override { return true; }
  bool mayAddEnergy() const override { return true; }
  double stiffness() const override { return 7; }
};

TEST(StudyTimedForce, PassesTheContextThroughAndCountsTheCall) {
  auto probe = std::make_unique<ProbeForce>();
  const ProbeForce& inner = *probe;
  ForceTime time;
  const TimedForce timed(std::move(probe), &time);
  Scene scene;
  addParticle(scene, 1.0, false, 0.1);
  const VecX x = VecX::Zero(2), v = VecX::Zero(2);
  VecX gradient = VecX::Zero(2);
  ForceContext context(true, 2);
  timed.addGradientWith(scene, x, v, gradient, context);
  EXPECT_EQ(inner.seen, &context);
  EXPECT_EQ(gradient[0], 2.0);  // the context version answered, not the plain one
  EXPECT_EQ(time.calls, 1);
  inner.seen = nullptr;
  EXPECT_EQ(timed.energyWith(scene, x, v, context), 3.0);
  EXPECT_EQ(inner.seen, &context);
  EXPECT_TRUE(timed.hasPotential());
  EXPECT_TRUE(timed.mayAddEnergy());  // a potential force that says it may add energy: passed on, not the default
  EXPECT_EQ(timed.stiffness(), 7.0);
  EXPECT_STREQ(timed.keyword(), "probe");
}

}  // namespace
}  // namespace fosssim::study
