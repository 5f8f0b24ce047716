// The command line and the scene loader's messages: --check (load and check only), --strict
// (warnings are errors), -q (one line counting the warnings), "did you mean", every error of a
// file in one pass in line order, floods summarised, the warnings catalogue (tests/data/warnings),
// runaway settings, and every shipped scene in assets/ loading without a warning.
#include "run_fosssim.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;

const std::string kWarnings = std::string(FOSSSIM_TEST_DATA) + "/warnings";
const std::string kBad = std::string(FOSSSIM_TEST_DATA) + "/bad";

/// A scene in a temporary file, removed when the test's object goes.
struct TempScene {
  explicit TempScene(const std::string& text, const std::string& name = "scene") {
    path = fs::temp_directory_path() / ("fosssim-check-" + name + "-" + std::to_string(getpid()) + ".xml");
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempScene() { fs::remove(path); }
  std::string path;
};

const std::string kHead =
    "<scene>\n"                                                            // 1
    "  <duration time=\"0.05\"/>\n"                                        // 2
    "  <integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n"              // 3
    "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"  // 4
    "  <particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";  // 5

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CliSceneCheck, CheckLoadsAndSummarisesWithoutRunning) {
  const TempScene scene(kHead + "  <edge i=\"0\" j=\"1\"/>\n  <simplegravity fx=\"0\" fy=\"-9.81\"/>\n</scene>\n");
  const Outcome o = runFosssim({"-s", scene.path, "--check"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_TRUE(contains(o.out, scene.path + ": ok (2 particles, 1 edge, 0 half-planes, 1 force, 5 steps of dt 0.01"))
      << o;
  EXPECT_EQ(o.err, "");
}

// Two particles in one place under mutual gravitation: the force is infinite at the first step.
// --check does not run (exit 0); a run stops at step 1 and names the force responsible, with any
// collision handling (continuous-time and hybrid used to test the pair first and report an
// overflow of its coordinates instead).
TEST(CliSceneCheck, CheckRunsNothingAndARunNamesTheForceThatWentNonFinite) {
  for (const std::string collision :
       {"", "  <collision type=\"continuous-time\"/>\n", "  <collision type=\"hybrid\"/>\n"}) {
    SCOPED_TRACE(collision);
    std::string text = kHead + collision + "  <gravitationalforce i=\"0\" j=\"1\" G=\"1\"/>\n</scene>\n";
    text.replace(text.find("px=\"1\""), 6, "px=\"0\"");
    const TempScene scene(text);
    const Outcome checked = runFosssim({"-s", scene.path, "--check"});
    EXPECT_TRUE(exitedWith(checked, 0)) << checked;
    const Outcome ran = runFosssim({"-s", scene.path, "-d", "0", "-q"});
    EXPECT_TRUE(exitedWith(ran, 1)) << ran;
    EXPECT_TRUE(contains(ran.err, "step 1 (t = 0 to 0.01): particle 0 has a non-finite")) << ran;
    EXPECT_TRUE(contains(ran.err, "the force 'gravitationalforce' #1 on it was already non-finite at the step's start"))
        << ran;
  }
}

TEST(CliSceneCheck, CheckReportsEveryErrorInLineOrderWithTheWarningFirst) {
  const TempScene scene(
      kHead +
      "  <particle m=\"1\" pxx=\"2\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n"  // 6: typo, then missing px
      "  <edge i=\"0\" j=\"9\"/>\n"                                               // 7: no particle 9
      "  <collision type=\"simple\" COR=\"2\"/>\n"                                // 8
      "</scene>\n");
  const Outcome o = runFosssim({"-s", scene.path, "--check"});
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_EQ(o.out, "");
  const std::vector<std::string> inOrder = {
      "warning: " + scene.path + ":6: <particle> attribute 'pxx': unknown attribute ignored; did you mean 'px'?",
      "error: " + scene.path + ":6: <particle> attribute 'px': missing (required)",
      "error: " + scene.path + ":7: <edge> attribute 'j': particle 9 does not exist",
      "error: " + scene.path + ":8: <collision> attribute 'COR': must lie in [0, 1]"};
  size_t at = 0;
  for (const std::string& line : inOrder) {
    const size_t found = o.err.find(line);
    ASSERT_NE(found, std::string::npos) << "missing " << line << "\n" << o;
    EXPECT_GE(found, at) << "out of order: " << line << "\n" << o;
    at = found;
  }
}

TEST(CliSceneCheck, StrictMakesWarningsErrors) {
  const TempScene scene(kHead + "  <simplegravty fx=\"0\" fy=\"-9.81\"/>\n</scene>\n");
  const Outcome lenient = runFosssim({"-s", scene.path, "-d", "0", "-q"});
  EXPECT_TRUE(exitedWith(lenient, 0)) << lenient;
  const Outcome strict = runFosssim({"-s", scene.path, "-d", "0", "-q", "--strict"});
  EXPECT_TRUE(exitedWith(strict, 1)) << strict;
  EXPECT_TRUE(contains(strict.err, "error: " + scene.path +
                                       ":6: <simplegravty>: unknown element ignored; did you mean <simplegravity>?"))
      << strict;
  EXPECT_TRUE(contains(strict.err, "--strict")) << strict;
  const Outcome strictCheck = runFosssim({"-s", scene.path, "--check", "--strict"});
  EXPECT_TRUE(exitedWith(strictCheck, 1)) << strictCheck;
  EXPECT_EQ(strictCheck.out, "");
}

TEST(CliSceneCheck, QuietPrintsOneLineCountingTheWarnings) {
  std::string text = kHead;
  for (int k = 0; k < 7; ++k) text += "  <foo/>\n";
  text += "  <particle m=\"1\" px=\"2\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" colour=\"red\"/>\n</scene>\n";
  const TempScene scene(text);
  const Outcome quiet = runFosssim({"-s", scene.path, "-d", "0", "-q"});
  EXPECT_TRUE(exitedWith(quiet, 0)) << quiet;
  EXPECT_EQ(quiet.err,
            "FOSSSim: warning: " + scene.path + ": 8 warnings about the scene (run without -q to see them)\n");
  const Outcome loud = runFosssim({"-s", scene.path, "--check"});
  EXPECT_TRUE(exitedWith(loud, 0)) << loud;
  EXPECT_EQ(count(loud.err, "unknown element ignored"), 3u) << loud;  // then counted
  EXPECT_TRUE(contains(loud.err, scene.path + ": ... and 4 more unknown elements <foo> (lines 9-12)")) << loud;
  EXPECT_TRUE(contains(loud.out, "ok (3 particles")) << loud;
  EXPECT_TRUE(contains(loud.out, "8 warnings")) << loud;
}

// A scene of 100,000 unknown elements used to print 72 MB of warnings.
TEST(CliSceneCheck, AFloodOfWarningsIsCounted) {
  std::string text = kHead;
  for (int k = 0; k < 50000; ++k) text += "<bar/><baz" + std::to_string(k) + "/>\n";
  text += "</scene>\n";
  const TempScene scene(text);
  const Outcome o = runFosssim({"-s", scene.path, "--check"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_LT(o.err.size(), 20000u) << o.err.size() << " bytes of warnings";
  EXPECT_TRUE(contains(o.err, "... and 49,997 more unknown elements <bar>")) << o;
  EXPECT_TRUE(contains(o.err, "more warnings of")) << o;
  EXPECT_TRUE(contains(o.out, "100,000 warnings") || contains(o.out, "100000 warnings")) << o;
}

TEST(CliSceneCheck, EveryUnusedInputIsAWarningAndStrictMakesItAnError) {
  const auto table = readExpectations(kWarnings);
  ASSERT_GE(table.size(), 8u);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kWarnings)) {
    const std::string name = entry.path().filename().string();
    if (name == "EXPECTED") continue;
    ++files;
    SCOPED_TRACE(name);
    const auto it = table.find(name);
    ASSERT_NE(it, table.end()) << name << " has no line in tests/data/warnings/EXPECTED";
    const std::string path = entry.path().string();
    for (const bool strict : {false, true}) {
      std::vector<std::string> args = {"-s", path, "-d", "0"};
      if (strict) args.push_back("--strict");
      const Outcome o = runFosssim(args);
      EXPECT_TRUE(exitedWith(o, strict ? 1 : 0)) << o;
      const std::string prefix = std::string("FOSSSim: ") + (strict ? "error: " : "warning: ") + path + ":";
      EXPECT_TRUE(contains(o.err, prefix)) << o;
      for (const std::string& fragment : it->second) EXPECT_TRUE(contains(o.err, fragment)) << fragment << "\n" << o;
    }
  }
  EXPECT_EQ(files, static_cast<int>(table.size())) << "EXPECTED names files that do not exist";
}

// Every scene the project ships loads without a warning: a warning there would teach users to
// ignore warnings.
TEST(CliSceneCheck, EveryShippedSceneChecksWithoutWarnings) {
  int scenes = 0;
  for (const auto& entry : fs::recursive_directory_iterator(std::string(FOSSSIM_SOURCE_DIR) + "/assets")) {
    if (entry.path().extension() != ".xml") continue;
    ++scenes;
    const Outcome o = runFosssim({"-s", entry.path().string(), "--check", "--strict"});
    EXPECT_TRUE(exitedWith(o, 0)) << entry.path() << "\n" << o;
    EXPECT_EQ(o.err, "") << entry.path();
    EXPECT_TRUE(contains(o.out, ": ok (")) << entry.path() << "\n" << o;
  }
  EXPECT_GT(scenes, 20);
}

// maxiters="1e9" made a 2-step hybrid scene run for minutes; now the load refuses it, saying why.
TEST(CliSceneCheck, RunawaySettingsAreRefusedWithTheReason) {
  const TempScene scene(kHead + "  <collision type=\"hybrid\" maxiters=\"1e9\"/>\n</scene>\n");
  const Outcome o = runFosssim({"-s", scene.path, "-d", "0", "-q"}, RunOptions{20});
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_TRUE(contains(o.err, ":6: <collision> attribute 'maxiters': must be at most 10000,")) << o;
  // The course's largest value still loads.
  const TempScene course(kHead + "  <collision type=\"hybrid\" maxiters=\"10000\"/>\n</scene>\n", "course");
  EXPECT_TRUE(exitedWith(runFosssim({"-s", course.path, "--check"}), 0));
}

// Forty trails of 1e300 s used to abort with std::bad_alloc (exit 134). A trail never keeps more
// positions than the run has steps, so on a short run they load; on a long run their sum is
// refused.
TEST(CliSceneCheck, LongParticlePathsAreBounded) {
  std::string paths;
  for (int k = 0; k < 40; ++k) paths += "  <particlepath i=\"0\" duration=\"1e300\" r=\"1\" g=\"0\" b=\"0\"/>\n";
  const TempScene shortRun(kHead + paths + "</scene>\n");
  const std::string svg = fs::temp_directory_path() / ("fosssim-check-svg-" + std::to_string(getpid()));
  const Outcome ran = runFosssim({"-s", shortRun.path, "-d", "0", "-q", "-m", svg});
  EXPECT_TRUE(exitedWith(ran, 0)) << ran;
  fs::remove_all(svg);
  std::string longText = kHead + paths + "</scene>\n";
  longText.replace(longText.find("time=\"0.05\""), 11, "time=\"1e6\"");
  const TempScene longRun(longText, "long");
  const Outcome refused = runFosssim({"-s", longRun.path, "--check"});
  EXPECT_TRUE(exitedWith(refused, 1)) << refused;
  EXPECT_TRUE(
      contains(refused.err, "<particlepath> attribute 'duration': the trails would keep more than 1e+07 positions"))
      << refused;
}

/// Runs FOSSSim with its address space limited to `bytes`: the exit status (or 128 + signal) and
/// stderr.
std::pair<int, std::string> runWithMemoryLimit(const std::vector<std::string>& args, rlim_t bytes) {
  RunOptions options;
  options.addressSpace = bytes;
  options.timeoutSeconds = 300;
  const Outcome o = runFosssim(args, options);
  return {o.exited ? o.code : 128 + o.signal, o.err};
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

// An allocation that fails is a clear error with exit 1, not std::bad_alloc's abort (exit 134).
// The smallest address space in which the scene loads is found first; then a run that needs 160 MB
// more (a trail of 1e7 positions for -m's pictures) is started in that space plus 64 MB.
TEST(CliSceneCheck, AnAllocationFailureIsAClearErrorWithExitOne) {
  if (kSanitized) GTEST_SKIP() << "sanitizers reserve terabytes of address space: no limit can be set";
  const TempScene scene(
      "<scene><duration time=\"1e5\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/>"
      "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"
      "<particlepath i=\"0\" duration=\"1e5\" r=\"1\" g=\"0\" b=\"0\"/></scene>\n");
  constexpr rlim_t kMiB = 1 << 20;
  rlim_t low = 16 * kMiB, high = 4096 * kMiB;  // --check fails at low, works at high
  if (runWithMemoryLimit({"-s", scene.path, "--check"}, high).first != 0) GTEST_SKIP() << "cannot start in 4 GiB";
  while (high - low > 16 * kMiB) {
    const rlim_t mid = (low + high) / 2;
    (runWithMemoryLimit({"-s", scene.path, "--check"}, mid).first == 0 ? high : low) = mid;
  }
  const std::string svg = fs::temp_directory_path() / ("fosssim-check-mem-svg-" + std::to_string(getpid()));
  const auto [code, err] = runWithMemoryLimit({"-s", scene.path, "-d", "0", "-q", "-m", svg}, high + 64 * kMiB);
  fs::remove_all(svg);
  EXPECT_EQ(code, 1) << err;
  EXPECT_TRUE(contains(err, "FOSSSim: error: out of memory")) << err;
}

// OSMesa crashed (SIGSEGV, exit 139) when one of its allocations failed: at some limits between
// 650 and 750 MB with 8000x8000 frames, inside OSMesaCreateContextExt. What it will need is now
// checked first (osmesa_context.cpp): at every limit the run ends with exit 0 or 1, never a signal.
TEST(CliSceneCheck, FramesTooLargeForTheMemoryAreAClearError) {
  if (kSanitized) GTEST_SKIP() << "sanitizers reserve terabytes of address space: no limit can be set";
  if (!FOSSSIM_WITH_RENDER) GTEST_SKIP() << "this build has no renderer (-g)";
  const TempScene scene("<scene><duration time=\"0.01\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/>"
                        "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/></scene>\n");
  constexpr rlim_t kMiB = 1 << 20;
  const std::string pngs = fs::temp_directory_path() / ("fosssim-check-mem-png-" + std::to_string(getpid()));
  bool refused = false;
  for (rlim_t limit = 600 * kMiB; limit <= 1200 * kMiB; limit += 25 * kMiB) {
    SCOPED_TRACE(std::to_string(limit / kMiB) + " MiB");
    const auto [code, err] = runWithMemoryLimit(
        {"-s", scene.path, "-d", "0", "-q", "-g", "1", "--png-dir", pngs, "--frame-size", "8000x8000"}, limit);
    EXPECT_TRUE(code == 0 || code == 1) << "exit " << code << "\n" << err;
    if (code == 1 && contains(err, "FOSSSim: error: -g: out of memory for 8000x8000 frames")) refused = true;
  }
  fs::remove_all(pngs);
  EXPECT_TRUE(refused) << "no limit up to 1200 MiB refused 8000x8000 frames";
}

}  // namespace
}  // namespace fosssim::testing
