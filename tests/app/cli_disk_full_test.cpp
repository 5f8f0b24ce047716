// Outputs on a full disk, without mounting one: RunOptions::fileSize caps every file the run
// writes (RLIMIT_FSIZE, SIGXFSZ ignored), so a write past the cap fails with EFBIG where a full
// disk fails with ENOSPC, through the same code. Each output must end the run with exit 1 and
// leave only whole data: --stats whole rows, -m no frame cut short, --movie no broken movie under
// its final name (ffmpeg exited 0 after "Error writing trailer").
#include "support/temp_dir_test.h"
#include "run_fosssim.h"

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;

class CliDiskFull : public TempDirTest {
 protected:
  /// `particles` particles falling for `steps` steps of 0.01 s.
  std::string scene(int particles, int steps) const {
    std::string text = "<scene><duration time=\"" + std::to_string(steps / 100.0) +
                       "\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/><simplegravity fx=\"0\" fy=\"-1\"/>";
    for (int k = 0; k < particles; ++k)
      text += "<particle m=\"1\" px=\"" + std::to_string(k) +
              "\" py=\"0\" vx=\"0.1\" vy=\"0\" fixed=\"0\" radius=\"0.3\"/>";
    std::ofstream(path("scene.xml")) << text << "</scene>\n";
    return path("scene.xml");
  }
};

RunOptions capped(rlim_t bytes) {
  RunOptions options;
  options.fileSize = bytes;
  return options;
}

TEST_F(CliDiskFull, StatsKeepsWholeRowsAndSaysHowMany) {
  const std::string s = scene(2, 2000), csv = path("s.csv");
  const Outcome o = runFosssim({"-s", s, "-d", "0", "-q", "--stats", csv}, capped(100000));
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_TRUE(contains(o.err, csv + ": cannot write the --stats file (File too large)")) << o;
  EXPECT_TRUE(contains(o.err, "--stats: the rows of steps 0 to ")) << o;
  const std::string text = slurp(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "the file ends in the middle of a row";
  std::istringstream lines(text);
  std::string header, line;
  std::getline(lines, header);
  const auto commas = std::count(header.begin(), header.end(), ',');
  long rows = 0;
  while (std::getline(lines, line)) {
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), commas) << "row " << rows;
    ++rows;
  }
  EXPECT_GT(rows, 0);
  EXPECT_LT(rows, 2001);
  EXPECT_TRUE(contains(o.err, "(" + std::to_string(rows) + " whole rows under the header) are in " + csv)) << o;
}

TEST_F(CliDiskFull, NoSvgFrameIsLeftCutShort) {
  const std::string s = scene(60, 3);  // a frame of 60 circles is larger than the cap
  const Outcome o = runFosssim({"-s", s, "-d", "0", "-q", "-m", path("svg")}, capped(4096));
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_TRUE(contains(o.err, "cannot write SVG file")) << o;
  EXPECT_TRUE(contains(o.err, "no frame was written")) << o;
  for (const auto& entry : fs::directory_iterator(path("svg"))) ADD_FAILURE() << "left behind: " << entry.path();
}

// Frames are written under their partial names and renamed once whole: a frame that fails leaves
// the earlier run's frame of that number as it was, where a direct write truncated it and then
// removed what it had cut short.
TEST_F(CliDiskFull, AFailedFrameLeavesAnEarlierRunsFrameAsItWas) {
  const std::string small = path("small.xml");
  fs::rename(scene(1, 3), small);
  struct Frames {
    std::vector<std::string> options;
    std::string first;  // frame 1's name
  };
  std::vector<Frames> kinds = {{{"-m", path("svg")}, path("svg/frame00000000000000000001.svg")}};
  if (FOSSSIM_WITH_RENDER)  // 512 x 512 PNGs of 60 disks are larger than the cap; one disk's is not
    kinds.push_back({{"-g", "1", "--png-dir", path("png"), "--frame-size", "512x512"}, path("png/frame00001.png")});
  for (const Frames& kind : kinds) {
    SCOPED_TRACE(kind.first);
    auto run = [&](const std::string& scenePath) {
      std::vector<std::string> args = {"-s", scenePath, "-d", "0", "-q"};
      args.insert(args.end(), kind.options.begin(), kind.options.end());
      return args;
    };
    const Outcome earlier = runFosssim(run(small), capped(65536));
    ASSERT_TRUE(exitedWith(earlier, 0)) << earlier;
    const std::string before = slurp(kind.first);
    ASSERT_FALSE(before.empty());
    const Outcome o = runFosssim(run(scene(60, 3)), capped(4096));
    EXPECT_TRUE(exitedWith(o, 1)) << o;
    EXPECT_TRUE(contains(o.err, "was not written")) << o;
    EXPECT_EQ(slurp(kind.first), before) << "the earlier run's frame 1 was changed";
    for (const auto& entry : fs::directory_iterator(fs::path(kind.first).parent_path()))
      EXPECT_FALSE(contains(entry.path().filename().string(), "partial")) << "left behind: " << entry.path();
  }
}

TEST_F(CliDiskFull, AMovieThatCannotBeFinishedKeepsItsPartialName) {
  if (!FOSSSIM_WITH_RENDER) GTEST_SKIP() << "this build has no renderer (--movie)";
  const std::string s = scene(2, 100), movie = path("m.mp4");
  const Outcome o = runFosssim({"-s", s, "-d", "0", "-q", "--movie", movie, "--frame-size", "320x240"}, capped(4096));
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_TRUE(contains(o.err, "ffmpeg failed writing the movie")) << o;
  EXPECT_TRUE(contains(o.err, path("m.partial.mp4"))) << o;
  EXPECT_FALSE(fs::exists(movie)) << "a broken movie under the final name";
}

}  // namespace
}  // namespace fosssim::testing
