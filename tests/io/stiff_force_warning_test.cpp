// A spring-like force too stiff for an explicit step is reported when the scene loads: a force
// of stiffness k on a reduced mass mu oscillates at omega = sqrt(k / mu), and symplectic Euler
// is unstable for omega dt > 2 (the oscillator's update matrix [[1, dt], [-omega^2 dt,
// 1 - omega^2 dt^2]] has trace 2 - omega^2 dt^2 and determinant 1: its eigenvalues leave the unit
// circle once |trace| > 2). An independent check found a 1e-6 kg disk resting in hybrid's
// default penalty layer (k = 10) launched at 1e4 m/s in its first step, and a k = 1e5 spring
// whose energy grew 1.9e5-fold, both exit 0 without a word. Expected figures are worked by hand
// in each test.
#include "scene_text.h"

#include <string>

namespace fosssim::testing {
namespace {

std::string scene(const std::string& integrator, double dt, const std::string& body) {
  return "<scene>\n  <duration time=\"1\"/>\n  <integrator type=\"" + integrator + "\" dt=\"" + std::to_string(dt) +
         "\"/>\n" + body + "</scene>\n";
}

const std::string kLightDiskOnFloor =  // hybrid's penalty layer: k = 10 (its default)
    "  <collision type=\"hybrid\" COR=\"0\"/>\n"
    "  <particle m=\"1e-6\" px=\"0\" py=\"0.1\" vx=\"0\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>\n"
    "  <halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/>\n";

const std::string kStiffSpring =  // two 1 kg particles: reduced mass 1/2
    "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
    "  <particle m=\"1\" px=\"2\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"
    "  <edge i=\"0\" j=\"1\"/>\n"
    "  <springforce edge=\"0\" k=\"1e5\" l0=\"2\"/>\n";

// omega = sqrt(10 / 1e-6) = 3162.28 rad/s; at dt = 0.01, omega dt = 31.6228, and the stable step
// is 2 / omega = 6.32456e-4 s.
TEST(StiffForceWarning, APenaltyLayerTooStiffForTheLightestDiskIsReported) {
  const SceneFile file = loaded(scene("symplectic-euler", 0.01, kLightDiskOnFloor));
  ASSERT_EQ(file.warningCount, 1);
  expectContains(file.warnings.front(), {kFile + ":3: <integrator>", "collision penalty", "mass 1e-06, k = 10",
                                         "omega dt = 31.6228", "use dt below 0.000632456"});
}

// omega = sqrt(1e5 / 0.5) = 447.214 rad/s; at dt = 0.05, omega dt = 22.3607. With one end fixed
// the reduced mass is the other's, 1 kg: omega dt = sqrt(1e5) * 0.05 = 15.8114.
TEST(StiffForceWarning, ASpringIsJudgedByItsReducedMass) {
  const SceneFile file = loaded(scene("explicit-euler", 0.05, kStiffSpring));
  ASSERT_EQ(file.warningCount, 1);
  expectContains(file.warnings.front(),
                 {"springforce between particles 0 and 1 (reduced mass 0.5, k = 100000)", "omega dt = 22.3607",
                  "explicit-euler is unstable above 2", "or implicit-euler"});
  std::string pinned = kStiffSpring;
  pinned.replace(pinned.find("fixed=\"0\""), 9, "fixed=\"1\"");
  const SceneFile one = loaded(scene("explicit-euler", 0.05, pinned));
  ASSERT_EQ(one.warningCount, 1);
  expectContains(one.warnings.front(), {"(reduced mass 1, k = 100000)", "omega dt = 15.8114"});
}

// Implicit Euler is stable for a spring at any omega dt; the penalty force has no Jacobian and is
// stepped explicitly by every integrator, so it is still reported (without the advice to go
// implicit). A spring well inside the limit (k = 100, 1 kg each: omega dt = 0.141 at dt = 0.01)
// is not.
TEST(StiffForceWarning, OnlyWhatIsSteppedExplicitlyAndPastTheLimitIsReported) {
  EXPECT_EQ(loaded(scene("implicit-euler", 0.05, kStiffSpring)).warningCount, 0);
  const SceneFile penalty = loaded(scene("implicit-euler", 0.01, kLightDiskOnFloor));
  ASSERT_EQ(penalty.warningCount, 2);  // and the implicit integrator's note on the penalty's Jacobian
  bool reported = false;
  for (const std::string& w : penalty.warnings)
    if (w.find("omega dt = 31.6228") != std::string::npos) {
      reported = true;
      EXPECT_EQ(w.find("or implicit-euler"), std::string::npos) << w;
    }
  EXPECT_TRUE(reported);
  std::string soft = kStiffSpring;
  soft.replace(soft.find("1e5"), 3, "100");
  EXPECT_EQ(loaded(scene("symplectic-euler", 0.01, soft)).warningCount, 0);
}

}  // namespace
}  // namespace fosssim::testing
