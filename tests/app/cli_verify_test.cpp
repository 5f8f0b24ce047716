// --verify checks the promise of continuous-time and hybrid handling in the default mode: after
// every step no pair is left colliding. Scenes where that promise is kept pass; where it is broken
// (the course's one-pass continuous-time under --compat lets a particle out of a corridor it
// crosses twice in a step) the run fails, naming step and pair. The other methods make no such
// promise: the same check finds their contacts, and the summary says why, so that a finding the
// method allows is not read as a defect of the run.
#include "run_fosssim.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fosssim::testing {
namespace {

/// Writes `body` as a scene file in the temporary folder; removes it when the test ends.
class TempScene {
 public:
  TempScene(const std::string& name, const std::string& body)
      : path_(std::filesystem::temp_directory_path() / ("fosssim-verify-" + std::to_string(getpid()) + "-" + name)) {
    std::ofstream(path_) << body;
  }
  ~TempScene() { std::remove(path_.c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// A particle at 100 m/s across a 0.5 m corridor between two half-planes: 1 m a step, so it
/// meets both walls within one step (the reference's one pass sees only the first).
std::string corridor(const std::string& type) {
  return "<scene><duration time=\"0.05\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>"
         "<collision type=\"" + type + "\" COR=\"1\"/>"
         "<halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/><halfplane px=\"0\" py=\"0.5\" nx=\"0\" ny=\"-1\"/>"
         "<particle m=\"1\" px=\"0\" py=\"0.25\" vx=\"0\" vy=\"100\" fixed=\"0\" radius=\"0.05\"/></scene>\n";
}

/// Two disks 1 m apart closing at 200 m/s: they meet within the first step and, unhindered,
/// are past each other by its end (`collision` is the whole collision element, or none).
std::string passThrough(const std::string& collision) {
  return "<scene><duration time=\"0.03\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>" + collision +
         "<particle m=\"1\" px=\"-0.5\" py=\"0\" vx=\"100\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
         "<particle m=\"1\" px=\"0.5\" py=\"0\" vx=\"-100\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/></scene>\n";
}

Outcome verify(const TempScene& scene, bool compat = false) {
  std::vector<std::string> args{"-s", scene.path(), "-d", "0", "-q", "--verify"};
  if (compat) args.push_back("--compat");
  return runFosssim(args);
}

TEST(CliVerify, TheDefaultModesPromiseHoldsAndNothingIsExplained) {
  for (const char* type : {"continuous-time", "hybrid"}) {
    const TempScene scene(std::string(type) + ".xml", corridor(type));
    const Outcome o = verify(scene);
    EXPECT_TRUE(exitedWith(o, 0)) << type << "\n" << o;
    EXPECT_TRUE(contains(o.err, "verify: 5 steps checked, 0 violations in 0 steps")) << type << "\n" << o;
    EXPECT_FALSE(contains(o.err, "promise")) << type << "\n" << o;
  }
}

TEST(CliVerify, TheCoursesOnePassFailsAndCompatIsNamed) {
  const TempScene scene("compat.xml", corridor("continuous-time"));
  const Outcome o = verify(scene, /*compat=*/true);
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_TRUE(contains(o.err, "verify: step 1: particle-half-plane pair (0, 0) still collides")) << o;
  EXPECT_TRUE(contains(o.err, "1 violation in 1 step\n")) << o;
  EXPECT_TRUE(contains(o.err, "--compat reproduces the course's handling")) << o;
  EXPECT_TRUE(contains(o.err, "without --compat continuous-time handling promises that none is")) << o;
}

TEST(CliVerify, MethodsWithoutThePromiseSayWhyContactsAreFound) {
  const std::pair<std::string, std::string> cases[] = {
      {"<collision type=\"simple\" COR=\"1\"/>", "simple handling responds only to pairs that overlap at the end"},
      {"<collision type=\"penalty\" k=\"100\" thickness=\"0.01\"/>", "penalty handling lets pairs overlap"},
      {"", "the scene has no collision handling"},
  };
  int k = 0;
  for (const auto& [collision, why] : cases) {
    const TempScene scene("method" + std::to_string(k++) + ".xml", passThrough(collision));
    const Outcome o = verify(scene);
    EXPECT_TRUE(exitedWith(o, 1)) << collision << "\n" << o;
    EXPECT_TRUE(contains(o.err, "verify: step 1: particle-particle pair (0, 1) still collides"))
        << collision << "\n" << o;
    EXPECT_TRUE(contains(o.err, "verify: " + why)) << collision << "\n" << o;
    EXPECT_TRUE(contains(o.err, "--verify found 1 violation in 1 step")) << collision << "\n" << o;
  }
}

}  // namespace
}  // namespace fosssim::testing
