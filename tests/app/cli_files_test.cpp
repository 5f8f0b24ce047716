// Files the command line cannot use: unreadable scene paths (missing, a directory, a named pipe,
// no read permission, an endless device), outputs that are named pipes, -o where nothing can be
// written, -i with a file that does not fit the scene. Each gives exit 1 and a message naming the
// path, never a crash or a hang.
#include "support/temp_dir_test.h"
#include "run_fosssim.h"

#include <chrono>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;

class CliFiles : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    fs::permissions(dir_, fs::perms::all);  // other users (nobody) may enter
  }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  /// A scene of `n` particles; with a collision type, records carry impulses (and polynomials).
  std::string scene(const std::string& name, int n, const std::string& collision = "") const {
    std::string text = "<scene><duration time=\"0.1\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/>";
    for (int k = 0; k < n; ++k)
      text += "<particle m=\"1\" px=\"" + std::to_string(k) + "\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"0\"/>";
    if (!collision.empty()) text += "<collision type=\"" + collision + "\"/>";
    return write(name, text + "</scene>\n");
  }
};

void expectFailure(const Outcome& o, const std::vector<std::string>& fragments) {
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  for (const auto& f : fragments) EXPECT_TRUE(contains(o.err + o.out, f)) << "missing \"" << f << "\"\n" << o;
}

TEST_F(CliFiles, UnreadableScenePaths) {
  expectFailure(runFosssim({"-s", path("missing.xml"), "-d", "0"}),
                {path("missing.xml") + ": cannot open", "No such file"});
  expectFailure(runFosssim({"-s", dir_.string(), "-d", "0"}), {dir_.string() + ": cannot read", "directory"});
  // An endless device is not read forever.
  expectFailure(runFosssim({"-s", "/dev/zero", "-d", "0"}), {"/dev/zero: ", "larger than"});
}

// Opening a named pipe blocks until someone writes to it: refused before the open, not a hang.
TEST_F(CliFiles, NamedPipesAreRefusedNotWaitedOn) {
  const std::string fifo = path("pipe");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  RunOptions options;
  options.timeoutSeconds = 20;
  expectFailure(runFosssim({"-s", fifo, "-d", "0"}, options), {fifo + ": cannot read the scene file", "named pipe"});
  expectFailure(runFosssim({"-s", scene("a.xml", 1), "-d", "0", "-q", "-i", fifo}, options),
                {fifo + ": cannot read the trajectory file", "named pipe"});
}

// Opening a named pipe for writing blocks until someone reads it: every output refuses one before
// the open, naming the option and the path, instead of hanging (deaf to the first SIGTERM).
TEST_F(CliFiles, NamedPipesAreRefusedAsOutputs) {
  const std::string s = scene("s.xml", 1);
  const std::string fifo = path("out.fifo"), movie = path("m.mkv");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  ASSERT_EQ(mkfifo(movie.c_str(), 0600), 0);
  fs::create_directories(path("svg"));
  ASSERT_EQ(mkfifo(path("svg/frame00001.svg").c_str(), 0600), 0);
  RunOptions options;
  options.timeoutSeconds = 20;
  const std::vector<std::string> run = {"-s", s, "-d", "0", "-q"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = run;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  expectFailure(runFosssim(with({"-o", fifo}), options),
                {"-o \"" + fifo + "\": cannot write", "named pipe that nothing reads, not a file"});
  expectFailure(runFosssim(with({"--stats", fifo}), options), {"--stats \"" + fifo + "\": cannot write", "named pipe"});
  expectFailure(runFosssim(with({"-m", path("svg")}), options),
                {"-m \"" + path("svg/frame00001.svg") + "\": cannot write the frame file", "named pipe"});
  if (FOSSSIM_WITH_RENDER)
    expectFailure(runFosssim(with({"--movie", movie}), options),
                  {"--movie \"" + movie + "\": cannot write", "named pipe"});
  // Nothing was written next to them, and a character device is still an output.
  EXPECT_FALSE(fs::exists(path("out.partial.fifo")));
  EXPECT_TRUE(exitedWith(runFosssim(with({"-o", "/dev/null", "--stats", "/dev/null"}), options), 0));
}

// A pipe that a process reads is an output as a character device is: -o /dev/stdout piped into
// gzip, or -o >(gzip > t.gz). The probe that tells it from a pipe nobody reads must stay open
// (closed, it was the pipe's last writer and the reader saw the end of its input).
TEST_F(CliFiles, APipeThatIsReadIsAnOutput) {
  const std::string s = scene("s.xml", 2), fifo = path("read.fifo");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const int reader = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  ASSERT_EQ(fcntl(reader, F_SETFL, 0), 0);  // blocking reads from here on
  std::string received;
  std::thread drain([&] {
    // A pipe without a writer reads as ended: until FOSSSim has written, that is not the end.
    char buffer[4096];
    for (int idle = 0; idle < 2000;) {
      const ssize_t n = read(reader, buffer, sizeof buffer);
      if (n > 0) received.append(buffer, static_cast<size_t>(n));
      else if (n == 0 && !received.empty()) break;
      else if (n == 0 || errno == EINTR || errno == EAGAIN)
        ++idle, std::this_thread::sleep_for(std::chrono::milliseconds(10));
      else break;
    }
  });
  RunOptions options;
  options.timeoutSeconds = 20;
  const Outcome o = runFosssim({"-s", s, "-d", "0", "-q", "-o", fifo}, options);
  drain.join();
  close(reader);
  EXPECT_TRUE(exitedWith(o, 0)) << o.err;
  // The same records as a file gets.
  const std::string file = path("t.bin");
  ASSERT_TRUE(exitedWith(runFosssim({"-s", s, "-d", "0", "-q", "-o", file}, options), 0));
  std::ifstream in(file, std::ios::binary);
  const std::string written((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(written.empty());
  EXPECT_EQ(received, written);
}

TEST_F(CliFiles, SceneWithoutReadPermission) {
  const std::string p = scene("secret.xml", 1);
  ASSERT_EQ(chmod(p.c_str(), 0), 0);
  // Root reads any file, so as root the test runs FOSSSim as the unprivileged user nobody.
  RunOptions options;
  options.asNobody = geteuid() == 0;
  const Outcome o = runFosssim({"-s", p, "-d", "0"}, options);
  if (options.asNobody && o.exited && o.code == 125)
    GTEST_SKIP()
        << "cannot run FOSSSim as the unprivileged user nobody here (no setuid, or the build is out of its reach)";
  expectFailure(o, {p + ": cannot open", "Permission denied"});
}

TEST_F(CliFiles, UnwritableOutput) {
  const std::string s = scene("s.xml", 2);
  expectFailure(runFosssim({"-s", s, "-d", "0", "-o", path("no/such/dir/t.bin")}),
                {path("no/such/dir/t.bin") + ": cannot create"});
  expectFailure(runFosssim({"-s", s, "-d", "0", "-o", dir_.string()}), {dir_.string() + ": cannot create"});
  expectFailure(runFosssim({"-s", s, "-d", "0", "-o", "/proc/fosssim-cannot-be-here.bin"}),
                {"/proc/fosssim-cannot-be-here.bin: cannot"});
  expectFailure(runFosssim({"-s", s, "-d", "0", "-o", "/dev/full"}), {"/dev/full: cannot"});
}

TEST_F(CliFiles, AFailedStartIsNotReportedAsARun) {
  // No progress summary ("done: N steps") for a run that never started.
  const Outcome o = runFosssim({"-s", scene("s.xml", 2), "-d", "0", "-o", path("no/dir/t.bin")});
  expectFailure(o, {"cannot create"});
  EXPECT_FALSE(contains(o.err, "done:")) << o;
}

TEST_F(CliFiles, OwnTrajectoryGradesAndAnotherScenesDoesNot) {
  for (const char* collision : {"", "simple", "continuous-time"}) {
    SCOPED_TRACE(collision);
    const std::string two = scene("two.xml", 2, collision), three = scene("three.xml", 3, collision);
    ASSERT_TRUE(exitedWith(runFosssim({"-s", two, "-d", "0", "-q", "-o", path("two.bin")}), 0));
    const Outcome own = runFosssim({"-s", two, "-d", "0", "-q", "-i", path("two.bin")});
    EXPECT_TRUE(exitedWith(own, 0)) << own;
    EXPECT_TRUE(contains(own.out, "Overall success: Passed.")) << own;
    const Outcome other = runFosssim({"-s", three, "-d", "0", "-q", "-i", path("two.bin")});
    expectFailure(other, {"Overall success: Failed.", "trajectory of this scene?"});
  }
}

TEST_F(CliFiles, TrajectoriesThatDoNotFit) {
  const std::string s = scene("s.xml", 2, "simple");
  ASSERT_TRUE(exitedWith(runFosssim({"-s", s, "-d", "0", "-q", "-o", path("t.bin")}), 0));
  const std::string bytes = slurp(path("t.bin"));
  ASSERT_EQ(bytes.size(), 11u * (64 + 4));  // 11 records, no impulses: 2 particles flying apart
  struct Case {
    std::string name, bytes, fragment;
  };
  std::string absurd = bytes;
  absurd.replace(64, 4, std::string("\xff\xff\xff\x7f", 4));  // record 0's impulse count: 2^31-1
  std::string negative = bytes;
  negative.replace(64 + 68, 4, std::string("\xfe\xff\xff\xff", 4));  // record 1's: -2
  const std::vector<Case> cases = {
      {"empty.bin", "", "the file ends early at record 0 (byte 0 of 0)"},
      {"truncated.bin", bytes.substr(0, bytes.size() - 5), "record 10"},
      {"half.bin", bytes.substr(0, bytes.size() / 2), "record 5 (byte "},
      {"trailing.bin", bytes + "x", "goes on after the scene's 10 steps"},
      {"absurd.bin", absurd, "impulse count 2147483647"},
      {"negative.bin", negative, "impulse count -2"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    expectFailure(runFosssim({"-s", s, "-d", "0", "-q", "-i", write(c.name, c.bytes)}),
                  {"Overall success: Failed.", c.fragment});
  }
  expectFailure(runFosssim({"-s", s, "-d", "0", "-q", "-i", path("missing.bin")}), {"missing.bin: cannot open"});
  expectFailure(runFosssim({"-s", s, "-d", "0", "-q", "-i", dir_.string()}), {"directory"});
}

TEST_F(CliFiles, ASimulationThatBlowsUpIsAnError) {
  // Forces beyond the range of doubles: the step reports the particle, nothing is written as if fine.
  const std::string s = write("boom.xml",
                              "<scene><duration time=\"1\"/><integrator type=\"explicit-euler\" dt=\"0.1\"/>"
                              "<particle m=\"1e-300\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"
                              "<simplegravity fx=\"0\" fy=\"0\"/><constantforce fx=\"1e300\" fy=\"0\"/></scene>");
  expectFailure(runFosssim({"-s", s, "-d", "0", "-q", "-o", path("boom.bin")}), {"step 1", "particle 0", "non-finite"});
}

TEST_F(CliFiles, WarningsDoNotFailTheRun) {
  const std::string s = write("warn.xml",
                              "<scene><duration time=\"0.1\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/>\n"
                              "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" spin=\"3\"/>\n"
                              "<glue strength=\"1\"/></scene>");
  // Without -q: -q shows the warnings as one line counting them (cli_scene_check_test.cpp).
  const Outcome o = runFosssim({"-s", s, "-d", "0"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_TRUE(contains(o.err, "FOSSSim: warning: " + s + ":2: <particle> attribute 'spin'")) << o;
  EXPECT_TRUE(contains(o.err, "FOSSSim: warning: " + s + ":3: <glue>")) << o;
}

}  // namespace
}  // namespace fosssim::testing
