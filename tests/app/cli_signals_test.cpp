// SIGINT and SIGTERM sent to a running FOSSSim, headless and in a window (under Xvfb): the step
// under way finishes, every output is closed after whole records, the run says what it wrote
// and where, and the exit status is 128 + the signal (130, 143). -o of a run that did not
// complete keeps its partial name; the final name is not written.
#include "background_run.h"
#include "support/xvfb.h"

#include <poll.h>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;

/// Two particles approaching, continuous-time (records with a mid-step record, impulses and
/// polynomials): 10^7 steps, far more than any test waits for.
const char* kLongScene =
    "<scene><duration time=\"10000\"/><integrator type=\"explicit-euler\" dt=\"0.001\"/>"
    "<collision type=\"continuous-time\"/>"
    "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
    "<particle m=\"1\" px=\"3\" py=\"0\" vx=\"-1\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/></scene>";
constexpr RecordLayout kContinuousTime{true, true, true};
constexpr std::uintmax_t kRecord0 = 2 * 4 * 8 + 4 + 4;  // x, v of 2 particles; no impulse, no polynomial

class CliSignals : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fosssim-cli-signals-" + std::to_string(getpid()));
    fs::create_directories(dir_);
    std::ofstream(path("long.xml")) << kLongScene;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// Checks the end of an interrupted run with -o out.bin: exit status, message, and a partial
  /// file of whole finite records, as many as the steps the message reports.
  void expectInterrupted(const Outcome& o, int sig, const std::string& name) {
    const int code = 128 + sig;
    EXPECT_TRUE(exitedWith(o, code)) << o;
    const std::string signalName = sig == SIGINT ? "SIGINT" : "SIGTERM";
    EXPECT_TRUE(contains(o.err, "FOSSSim: interrupted by " + signalName + " after step ")) << o;
    const long steps = stepAfter(o.err, "after step ");
    EXPECT_GT(steps, 0) << o;
    EXPECT_EQ(stepAfter(o.err, "the trajectory up to step "), steps) << o;
    EXPECT_TRUE(contains(o.err, "is in \"" + path(name + ".partial.bin") + "\"")) << o;
    EXPECT_FALSE(fs::exists(path(name + ".bin"))) << "the final name of an interrupted run";
    // Record 0, then a mid-step and an end-of-step record per step.
    EXPECT_EQ(wholeFiniteRecords(path(name + ".partial.bin"), 2, kContinuousTime), 1 + 2 * steps);
  }

  fs::path dir_;
};

TEST_F(CliSignals, HeadlessRunsCloseTheirOutputsAndExit128PlusTheSignal) {
  for (const int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(sig == SIGINT ? "SIGINT" : "SIGTERM");
    const std::string name = sig == SIGINT ? "int" : "term";
    BackgroundRun run({"-s", path("long.xml"), "-d", "0", "-q", "-o", path(name + ".bin")}, dir_.string());
    ASSERT_TRUE(run.started());
    // Wait until some steps are in the file, then interrupt.
    ASSERT_TRUE(run.waitFor([&] { return sizeOf(path(name + ".partial.bin")) > 100 * kRecord0; }, 60))
        << run.err();
    run.signal(sig);
    expectInterrupted(run.finish(60), sig, name);
  }
}

// Frames and the movie close too: the PNG frames are those of the steps taken, and ffmpeg has
// ended the movie properly (ffprobe reads it).
TEST_F(CliSignals, PicturesAndTheMovieCloseOnASignal) {
  if (!FOSSSIM_WITH_RENDER) GTEST_SKIP() << "this build has no renderer (-g, --movie)";
  const bool ffmpeg = onPath("ffmpeg");
  std::vector<std::string> args = {"-s", path("long.xml"), "-d", "0", "-q", "-o", path("pics.bin"),
                                   "-g", "1", "--png-dir", path("pngs"), "--frame-size", "64x64"};
  if (ffmpeg) args.insert(args.end(), {"--movie", path("pics.mkv")});
  BackgroundRun run(args, dir_.string());
  ASSERT_TRUE(run.started());
  ASSERT_TRUE(run.waitFor([&] { return fs::exists(path("pngs/frame00010.png")); }, 60)) << run.err();
  run.signal(SIGTERM);
  const Outcome o = run.finish(60);
  expectInterrupted(o, SIGTERM, "pics");
  const long steps = stepAfter(o.err, "after step ");
  char frame[64];
  std::snprintf(frame, sizeof frame, "pngs/frame%05ld.png", steps);
  EXPECT_TRUE(fs::exists(path(frame))) << frame << "\n" << o;
  std::snprintf(frame, sizeof frame, "pngs/frame%05ld.png", steps + 1);
  EXPECT_FALSE(fs::exists(path(frame))) << frame;
  if (!ffmpeg) GTEST_SKIP() << "ffmpeg is not installed: the movie part is not tested";
  EXPECT_FALSE(fs::exists(path("pics.mkv")));
  EXPECT_TRUE(contains(o.err, "the movie is in \"" + path("pics.partial.mkv") + "\"")) << o;
  if (!onPath("ffprobe")) return;
  const std::string probe = "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                            "-of csv=p=0 '" + path("pics.partial.mkv") + "' > '" + path("probe.txt") + "' 2>&1";
  ASSERT_EQ(std::system(probe.c_str()), 0) << slurp(path("probe.txt"));
  // How many frames depends on the movie's pace (--fps against the scene's time step); it must
  // hold some and be readable to its end.
  EXPECT_GE(std::atol(slurp(path("probe.txt")).c_str()), 1) << slurp(path("probe.txt"));
}

// A window run writes -o step by step (nothing waits in a buffer: the file grows by whole
// records while the window runs) and closes it on a signal as a headless run does.
TEST_F(CliSignals, WindowRunsWriteAsTheyGoAndCloseOnASignal) {
  if (!onPath("Xvfb")) GTEST_SKIP() << "Xvfb is not installed (scripts/setup installs xvfb)";
  pid_t xvfb = -1;
  std::string why;
  const std::string display = startXvfb(xvfb, why, "640x480x24");
  struct Reap {
    pid_t& pid;
    ~Reap() {
      if (pid > 0) kill(pid, SIGTERM), waitpid(pid, nullptr, 0);
    }
  } reap{xvfb};
  if (display.empty()) GTEST_SKIP() << "Xvfb cannot run here: " << why;

  for (const int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(sig == SIGINT ? "SIGINT" : "SIGTERM");
    const std::string name = sig == SIGINT ? "wint" : "wterm";
    BackgroundRun run({"-s", path("long.xml"), "-d", "1", "-p", "0", "-o", path(name + ".bin")}, dir_.string(),
                      {{"DISPLAY", display}});
    ASSERT_TRUE(run.started());
    // The window runs at the scene's pace (100 steps per second): wait for a few steps on disk.
    const bool grew = run.waitFor([&] { return sizeOf(path(name + ".partial.bin")) > 5 * kRecord0; }, 30);
    if (!grew && contains(run.err(), "no window")) GTEST_SKIP() << "no window here: " << run.err();
    // Steps on disk while the window runs: nothing waits in a stream buffer.
    ASSERT_TRUE(grew) << run.err();
    run.signal(sig);
    const Outcome o = run.finish(30);
    if (contains(o.err, "running headless")) GTEST_SKIP() << "FOSSSim could not open a window here: " << o.err;
    expectInterrupted(o, sig, name);
  }
}

}  // namespace
}  // namespace fosssim::testing
