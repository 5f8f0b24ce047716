// Outputs that never destroy an input or hold what they should not, through the command line:
// an output that is an input (by another name, a symbolic or a hard link) is refused; -o is
// written under NAME.partial.EXT and takes its name only when the run completes; a run that
// blows up leaves no non-finite number in -o (continuous-time and hybrid, whose mid-step record
// comes before the step's finite check); --compact; the size warning of a huge -o; --movie
// names that ffmpeg would read as options or protocols.
#include "support/temp_dir_test.h"
#include "background_run.h"

#include <sys/statvfs.h>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;

constexpr RecordLayout kContinuousTime{true, true, true};

class CliOutputs : public TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }
  /// Two particles that meet (continuous-time or hybrid: mid-step records, impulses, polynomials).
  std::string meeting(const std::string& name, const std::string& collision, double duration = 2) const {
    return write(name,
                 "<scene><duration time=\"" + std::to_string(duration) +
                     "\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/><collision type=\"" + collision +
                     "\"/><particle m=\"1\" px=\"0\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
                     "<particle m=\"1\" px=\"3\" py=\"0\" vx=\"-1\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/></scene>\n");
  }
};

/// Runs FOSSSim with `args` and expects the refusal naming `output` and the scene, with the scene
/// file unchanged.
void expectRefused(const std::vector<std::string>& args, const std::string& scene, const std::string& fragment) {
  const std::string before = slurp(scene);
  const Outcome o = runFosssim(args);
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_TRUE(contains(o.err, fragment)) << "missing \"" << fragment << "\"\n" << o;
  EXPECT_TRUE(contains(o.err, "is the same file as the scene file given to -s")) << o;
  EXPECT_EQ(slurp(scene), before) << "the scene file changed";
}

/// `args` followed by `extra`.
std::vector<std::string> joined(std::vector<std::string> args, const std::vector<std::string>& extra) {
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST_F(CliOutputs, AnOutputThatIsTheSceneIsRefused) {
  const std::string scene = meeting("scene.xml", "continuous-time");
  const std::vector<std::string> run = {"-s", scene, "-d", "0", "-q"};
  auto with = [&](const std::vector<std::string>& extra) { return joined(run, extra); };
  // The same name, another spelling of it, a symbolic link, a hard link.
  fs::create_symlink(scene, path("symlink.bin"));
  fs::create_hard_link(scene, path("hardlink.bin"));
  for (const std::string& out :
       {scene, (dir_ / "." / "scene.xml").string(), path("symlink.bin"), path("hardlink.bin")}) {
    SCOPED_TRACE(out);
    expectRefused(with({"-o", out}), scene, "-o \"" + out + "\" is the same file");
  }
  // --movie takes movie names only (MovieNamesMustBeMovies): links to the scene with such a name.
  fs::create_symlink(scene, path("symlink.mp4"));
  fs::create_hard_link(scene, path("hardlink.mkv"));
  for (const std::string& out : {path("symlink.mp4"), path("hardlink.mkv")}) {
    SCOPED_TRACE(out);
    expectRefused(with({"--movie", out}), scene, "--movie \"" + out + "\" is the same file");
  }
  // -o's partial name: "x.bin" is written as "x.partial.bin" until the run completes.
  fs::create_hard_link(scene, path("x.partial.bin"));
  expectRefused(with({"-o", path("x.bin")}), scene, "its partial file \"" + path("x.partial.bin") + "\"");
  // A frame that -m or -g would write over, and a frame's partial name: each frame is written
  // there and renamed, and a file left there is removed first (the scene itself, had it that name).
  struct FrameCase {
    std::string folder, name;
    bool symbolic;  // a symbolic link to the scene, else a hard link
    std::vector<std::string> options;
    std::string fragment;
  };
  const std::vector<FrameCase> frames = {
      {"svg", "frame00000000000000000001.svg", true, {"-m"}, "the frame file"},
      {"png", "frame00002.png", false, {"-g", "1", "--png-dir"}, "the frame file"},
      {"svg2", "frame00000000000000000004.partial.svg", false, {"-m"}, "the partial file of a frame"},
      {"png2", "frame00001.partial.png", true, {"-g", "1", "--png-dir"}, "the partial file of a frame"}};
  for (const FrameCase& f : frames) {
    SCOPED_TRACE(f.folder + "/" + f.name);
    fs::create_directories(path(f.folder));
    const std::string frame = path(f.folder + "/" + f.name);
    if (f.symbolic) fs::create_symlink(scene, frame);
    else fs::create_hard_link(scene, frame);
    expectRefused(with(joined(f.options, {path(f.folder)})), scene, f.fragment);
  }
}

// --stats is an output like the others: never an input, and never a file another output writes
// (-o's or --movie's final or partial name, a frame). Each refusal happens before the run: no
// output is created, and files that were there stay as they were.
TEST_F(CliOutputs, StatsIsNeitherAnInputNorAnotherOutput) {
  const std::string scene = meeting("scene.xml", "continuous-time");
  const std::vector<std::string> run = {"-s", scene, "-d", "0", "-q"};
  auto with = [&](const std::vector<std::string>& extra) { return joined(run, extra); };
  expectRefused(with({"--stats", scene}), scene, "--stats \"" + scene + "\" is the same file");

  // Refused with both names in the message; `made` must not exist afterwards.
  auto expectClash = [&](const std::vector<std::string>& extra, const std::vector<std::string>& fragments,
                         const std::vector<std::string>& made) {
    const Outcome o = runFosssim(with(extra));
    EXPECT_TRUE(exitedWith(o, 1)) << o;
    for (const std::string& f : fragments) EXPECT_TRUE(contains(o.err, f)) << "missing \"" << f << "\"\n" << o;
    EXPECT_TRUE(contains(o.err, "give each output its own name")) << o;
    for (const std::string& m : made) EXPECT_FALSE(fs::exists(m)) << m;
  };
  const std::string o1 = path("o1.bin"), o1Partial = path("o1.partial.bin");
  expectClash({"-o", o1, "--stats", o1}, {"--stats \"" + o1 + "\" and -o \"" + o1 + "\" are the same file"},
              {o1, o1Partial});
  // The trajectory is written under its partial name: a CSV there would be renamed to "o1.bin".
  expectClash({"-o", o1, "--stats", o1Partial},
              {"--stats \"" + o1Partial + "\" and the partial file \"" + o1Partial + "\" of -o"}, {o1, o1Partial});
  // Another spelling of the same name, and a hard link to an existing file.
  expectClash({"-o", o1, "--stats", (dir_ / "." / "o1.bin").string()}, {"are the same file"}, {o1, o1Partial});
  write("old.bin", "an older trajectory");
  fs::create_hard_link(path("old.bin"), path("old-link.csv"));
  expectClash({"-o", path("old.bin"), "--stats", path("old-link.csv")}, {"are the same file"},
              {path("old.partial.bin")});
  EXPECT_EQ(slurp(path("old.bin")), "an older trajectory");
  // -o through a symbolic link is written next to the file it points at, under that file's
  // partial name.
  write("real.bin", "the link's target");
  fs::create_symlink(path("real.bin"), path("link.bin"));
  expectClash({"-o", path("link.bin"), "--stats", path("real.partial.bin")}, {"the partial file"},
              {path("real.partial.bin")});
  EXPECT_EQ(slurp(path("real.bin")), "the link's target");
  // A frame of -m.
  const std::string frame = path("svg/frame00000000000000000002.svg");
  expectClash({"-m", path("svg"), "--stats", frame}, {"--stats \"" + frame + "\" is a frame file that -m writes"},
              {frame});
  const std::string framePartial = path("svg/frame00000000000000000002.partial.svg");
  expectClash({"-m", path("svg"), "--stats", framePartial},
              {"--stats \"" + framePartial + "\" is the partial file of a frame, which -m writes before renaming it"},
              {framePartial});
  // -m's folder under an output's name (or its partial name): the folder was made, then the
  // output's open failed on it.
  expectClash({"-o", o1, "-m", o1}, {"-o \"" + o1 + "\" is the folder that -m writes its frames into"},
              {o1, o1Partial});
  expectClash({"-o", o1, "-m", o1Partial + "/"}, {"the partial file \"" + o1Partial + "\" of -o", "-m"},
              {o1, o1Partial});
  expectClash({"--stats", o1, "-m", (dir_ / "." / "o1.bin").string()}, {"--stats \"" + o1 + "\" is the folder"}, {o1});
  if (FOSSSIM_WITH_RENDER) {
    expectClash({"--stats", o1, "-g", "1", "--png-dir", o1}, {"is the folder that --png-dir writes"}, {o1});
    const std::string movie = path("base.mp4"), moviePartial = path("base.partial.mp4");
    expectClash({"--movie", movie, "--stats", movie}, {"--stats \"" + movie + "\" and --movie \"" + movie + "\""},
                {movie, moviePartial});
    expectClash({"--movie", movie, "--stats", moviePartial}, {"the partial file \"" + moviePartial + "\" of --movie"},
                {movie, moviePartial});
    // -o and --movie, one's final name the other's partial one.
    expectClash({"--movie", movie, "-o", moviePartial}, {"are the same file"}, {movie, moviePartial});
  }
  // Devices are written directly and destroy nothing: both outputs may go to /dev/null.
  const Outcome discard = runFosssim(with({"-o", "/dev/null", "--stats", "/dev/null"}));
  EXPECT_TRUE(exitedWith(discard, 0)) << discard;
  // Distinct names: both written in full.
  const Outcome both = runFosssim(with({"-o", o1, "--stats", path("o1.csv")}));
  ASSERT_TRUE(exitedWith(both, 0)) << both;
  EXPECT_EQ(wholeFiniteRecords(o1, 2, kContinuousTime), 1 + 2 * 200);
  EXPECT_EQ(slurp(path("o1.csv")).rfind("step,time,", 0), 0u);
}

// Frames are written over by number: after a 20-step run, a 10-step run into the same folder left
// frames 11 to 20 of the first, which passed for the second's without a word.
TEST_F(CliOutputs, FramesOfAnEarlierRunAreWarnedAbout) {
  const std::string longer = meeting("long.xml", "continuous-time", 0.2),
                    shorter = meeting("short.xml", "continuous-time", 0.1);
  const std::string svg = path("svg");
  ASSERT_TRUE(exitedWith(runFosssim({"-s", longer, "-d", "0", "-q", "-m", svg}), 0));
  const Outcome again = runFosssim({"-s", longer, "-d", "0", "-q", "-m", svg});  // the same frames: nothing to say
  EXPECT_TRUE(exitedWith(again, 0)) << again;
  EXPECT_FALSE(contains(again.err, "earlier run")) << again;
  const Outcome o = runFosssim({"-s", shorter, "-d", "0", "-q", "-m", svg});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_TRUE(contains(o.err, "FOSSSim: warning: -m: \"" + svg +
                                  "\" holds 10 frames of an earlier run beyond this run's 10 "
                                  "(frame00000000000000000011.svg to frame00000000000000000020.svg)"))
      << o;
  // Thinned out: 20 steps, every 4th is 5 frames; frames 6 to 20 are the earlier run's.
  const Outcome thinned = runFosssim({"-s", longer, "-d", "0", "-q", "-m", svg, "--frame-every", "4"});
  EXPECT_TRUE(contains(thinned.err, "holds 15 frames of an earlier run beyond this run's 5")) << thinned;
  // A run killed while writing frames 14 and 30 (SIGKILL: no clean-up) left their partial files.
  // The 10-frame run removes neither; they are named apart from the frames. A 20-frame run replaces
  // frame 14 (and its partial file) and leaves frame 30's.
  for (const char* left : {"frame00000000000000000014.partial.svg", "frame00000000000000000030.partial.svg"})
    std::ofstream(svg + "/" + left) << "<svg";
  const Outcome killed = runFosssim({"-s", shorter, "-d", "0", "-q", "-m", svg});
  EXPECT_TRUE(exitedWith(killed, 0)) << killed;
  EXPECT_TRUE(contains(killed.err, "holds 10 frames of an earlier run beyond this run's 10 (")) << killed;
  EXPECT_TRUE(contains(killed.err, "\" holds 2 partial files of an earlier run beyond this run's 10 frames "
                                   "(frame00000000000000000014.partial.svg to frame00000000000000000030.partial.svg)"
                                   ": runs stopped while writing those frames left them"))
      << killed;
  const Outcome whole = runFosssim({"-s", longer, "-d", "0", "-q", "-m", svg});
  EXPECT_TRUE(exitedWith(whole, 0)) << whole;
  EXPECT_FALSE(fs::exists(svg + "/frame00000000000000000014.partial.svg"));
  EXPECT_FALSE(contains(whole.err, "holds 1 frame")) << whole;
  EXPECT_TRUE(contains(whole.err, "holds 1 partial file of an earlier run beyond this run's 20 frames "
                                  "(frame00000000000000000030.partial.svg): a run stopped while writing that "
                                  "frame left it; it is not a frame"))
      << whole;
}

// --frame-every beyond the run's steps wrote no frame at all, without a word: refused as a usage
// error (exit 2) before anything is created; up to the step count it writes its frames.
TEST_F(CliOutputs, FrameEveryBeyondTheRunIsRefused) {
  const std::string scene = meeting("scene.xml", "continuous-time", 0.1);  // 10 steps
  const std::string svg = path("svg"), png = path("png");
  for (const std::vector<std::string>& frames : {std::vector<std::string>{"-m", svg},
                                                 std::vector<std::string>{"-g", "1", "--png-dir", png}}) {
    const Outcome o = runFosssim(joined({"-s", scene, "-d", "0", "-q", "--frame-every", "11"}, frames));
    EXPECT_TRUE(exitedWith(o, 2)) << o;
    EXPECT_TRUE(contains(o.err,
                         "FOSSSim: --frame-every 11 writes a frame after steps 11, 22, ..., and the scene runs 10 "
                         "steps: -g 1, -m and --movie would write no frame (give at most --frame-every 10)"))
        << o;
    EXPECT_FALSE(fs::exists(frames[0] == "-m" ? svg : png));
  }
  const Outcome o = runFosssim({"-s", scene, "-d", "0", "-q", "-m", svg, "--frame-every", "10"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_TRUE(fs::exists(path("svg/frame00000000000000000001.svg")));
  EXPECT_FALSE(fs::exists(path("svg/frame00000000000000000002.svg")));
}

// A run whose pictures fail says only what was written: frames up to the last one written, and
// no movie when ffmpeg could not create its file.
TEST_F(CliOutputs, TheSummaryCountsOnlyWhatWasWritten) {
  const std::string scene = meeting("scene.xml", "continuous-time", 0.05);  // 5 steps, 5 frames
  // Frame 3's name is taken by a folder: frames 1 and 2 are written, then the run stops.
  fs::create_directories(path("svg/frame00000000000000000003.svg"));
  const Outcome third = runFosssim({"-s", scene, "-d", "0", "-q", "-m", path("svg")});
  EXPECT_TRUE(exitedWith(third, 1)) << third;
  EXPECT_TRUE(contains(third.err, "FOSSSim: frames 1 to 2: SVG in \"" + path("svg") + "\"\n")) << third;
  EXPECT_TRUE(fs::exists(path("svg/frame00000000000000000002.svg")));
  fs::create_directories(path("first/frame00000000000000000001.svg"));
  const Outcome first = runFosssim({"-s", scene, "-d", "0", "-q", "-m", path("first")});
  EXPECT_TRUE(exitedWith(first, 1)) << first;
  EXPECT_TRUE(contains(first.err, "FOSSSim: no frame was written (SVG in \"" + path("first") + "\")\n")) << first;
  EXPECT_FALSE(contains(first.err, "frames 1 to")) << first;
  if (!FOSSSIM_WITH_RENDER) GTEST_SKIP() << "this build has no renderer (--movie)";
  // /proc takes no new files, not even root's: ffmpeg starts but makes no movie.
  const Outcome movie = runFosssim({"-s", scene, "-d", "0", "-q", "--movie", "/proc/fosssim-test.mp4"});
  EXPECT_TRUE(exitedWith(movie, 1)) << movie;
  EXPECT_TRUE(contains(movie.err, "no movie was made (\"/proc/fosssim-test.partial.mp4\" does not exist)")) << movie;
  EXPECT_FALSE(contains(movie.err, "the movie is in")) << movie;
}

TEST_F(CliOutputs, TheFinalNameOnlyForACompletedRun) {
  const std::string scene = meeting("scene.xml", "continuous-time");
  // Completed: the final name, no partial file left.
  const Outcome done = runFosssim({"-s", scene, "-d", "0", "-q", "-o", path("t.bin")});
  ASSERT_TRUE(exitedWith(done, 0)) << done;
  EXPECT_TRUE(fs::exists(path("t.bin")));
  EXPECT_FALSE(fs::exists(path("t.partial.bin")));
  EXPECT_EQ(wholeFiniteRecords(path("t.bin"), 2, kContinuousTime), 1 + 2 * 200);
  // A stale partial file of an earlier run is replaced, not appended to or followed.
  write("u.partial.bin", "stale");
  ASSERT_TRUE(exitedWith(runFosssim({"-s", scene, "-d", "0", "-q", "-o", path("u.bin")}), 0));
  EXPECT_EQ(slurp(path("u.bin")), slurp(path("t.bin")));
  EXPECT_FALSE(fs::exists(path("u.partial.bin")));
  // A symbolic link as -o: the file it points at gets the trajectory, the link stays.
  write("target.bin", "old");
  fs::create_symlink(path("target.bin"), path("link.bin"));
  ASSERT_TRUE(exitedWith(runFosssim({"-s", scene, "-d", "0", "-q", "-o", path("link.bin")}), 0));
  EXPECT_TRUE(fs::is_symlink(path("link.bin")));
  EXPECT_EQ(slurp(path("target.bin")), slurp(path("t.bin")));
  // A device is written directly.
  EXPECT_TRUE(exitedWith(runFosssim({"-s", scene, "-d", "0", "-q", "-o", "/dev/null"}), 0));
}

// Forces beyond the range of doubles: the first step's velocity is infinite. The mid-step record
// of continuous-time and hybrid used to reach the file before the step's finite check.
TEST_F(CliOutputs, ABlowUpWritesNothingNonFinite) {
  for (const std::string collision : {"continuous-time", "hybrid"}) {
    SCOPED_TRACE(collision);
    const std::string scene =
        write("boom.xml", "<scene><duration time=\"1\"/><integrator type=\"explicit-euler\" dt=\"0.1\"/>"
                          "<collision type=\"" + collision + "\"/>"
                          "<particle m=\"1e-300\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"
                          "<particle m=\"1\" px=\"5\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"
                          "<simplegravity fx=\"0\" fy=\"0\"/><constantforce fx=\"1e300\" fy=\"0\"/></scene>");
    write("boom.bin", "an older file");
    const Outcome o = runFosssim({"-s", scene, "-d", "0", "-q", "-o", path("boom.bin")});
    EXPECT_TRUE(exitedWith(o, 1)) << o;
    EXPECT_TRUE(contains(o.err, "step 1")) << o;
    EXPECT_TRUE(contains(o.err, "non-finite")) << o;
    // The failed run's records are whole and finite: record 0 only. The older file is untouched.
    EXPECT_EQ(wholeFiniteRecords(path("boom.partial.bin"), 2, kContinuousTime), 1);
    EXPECT_TRUE(contains(o.err, "the trajectory up to step 0 (1 whole records")) << o;
    EXPECT_TRUE(contains(o.err, "the older file of that name is as it was")) << o;
    EXPECT_EQ(slurp(path("boom.bin")), "an older file");
  }
}

// --compact: the same positions, velocities and impulses, without the polynomial log.
TEST_F(CliOutputs, CompactKeepsEverythingButThePolynomials) {
  for (const std::string collision : {"continuous-time", "hybrid"}) {
    SCOPED_TRACE(collision);
    const std::string scene = meeting("m.xml", collision);
    ASSERT_TRUE(exitedWith(runFosssim({"-s", scene, "-d", "0", "-q", "-o", path("full.bin")}), 0));
    ASSERT_TRUE(exitedWith(runFosssim({"-s", scene, "-d", "0", "-q", "-o", path("compact.bin"), "--compact"}), 0));
    std::unique_ptr<TrajectoryReader> full, compact;
    ASSERT_TRUE(TrajectoryReader::open(path("full.bin"), 2, kContinuousTime, full).isOk());
    ASSERT_TRUE(TrajectoryReader::open(path("compact.bin"), 2, RecordLayout{true, false, true}, compact).isOk());
    EXPECT_LT(sizeOf(path("compact.bin")), sizeOf(path("full.bin")));
    long records = 0, impulses = 0, polynomials = 0;
    for (;; ++records) {
      TrajectoryRecord a, b;
      bool endA = false, endB = false;
      ASSERT_TRUE(full->next(a, endA).isOk());
      const Status s = compact->next(b, endB);
      ASSERT_TRUE(s.isOk()) << s.message();
      ASSERT_EQ(endA, endB) << "record " << records;
      if (endA) break;
      EXPECT_EQ(a.x, b.x) << "record " << records;
      EXPECT_EQ(a.v, b.v) << "record " << records;
      ASSERT_EQ(a.log.impulses.size(), b.log.impulses.size()) << "record " << records;
      impulses += static_cast<long>(a.log.impulses.size());
      polynomials += a.log.polynomials.size();
      EXPECT_EQ(b.log.polynomials.size(), 0);
    }
    EXPECT_EQ(records, 1 + 2 * 200);
    EXPECT_GT(polynomials, 0);  // what --compact leaves out was there
    if (collision == "continuous-time") {
      EXPECT_GT(impulses, 0);  // they meet (hybrid's list stays empty)
    }
  }
}

// A continuous-time -o whose estimated size is large (every pair's polynomials in every record,
// 10^8 steps): the warning comes with the figure after the first step; the free space it is
// compared with is the real one, so either form of the warning may come.
TEST_F(CliOutputs, AHugeTrajectoryIsAnnouncedAtOnce) {
  std::string text = "<scene><duration time=\"100000\"/><integrator type=\"explicit-euler\" dt=\"0.001\"/>"
                     "<collision type=\"continuous-time\"/>";
  for (int k = 0; k < 40; ++k)
    text += "<particle m=\"1\" px=\"" + std::to_string(3 * k) + "\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>";
  const std::string scene = write("big.xml", text + "</scene>");
  BackgroundRun run({"-s", scene, "-d", "0", "-q", "-o", path("big.bin")}, dir_.string());
  ASSERT_TRUE(run.started());
  const std::string warning = "FOSSSim: warning: " + path("big.bin") + ": at this rate the trajectory will take about ";
  const bool warned = run.waitFor([&] { return contains(run.err(), warning); }, 60);
  run.signal(SIGTERM);
  const Outcome o = run.finish(60);
  ASSERT_TRUE(warned) << o;
  EXPECT_TRUE(contains(o.err, "--compact leaves out the polynomial log")) << o;
  // Said at once: before step 100 at the latest (the first steps give the estimate).
  EXPECT_TRUE(exitedWith(o, 143)) << o;
  EXPECT_LT(stepAfter(o.err, "after step "), 1000) << o;
  struct statvfs st {};
  ASSERT_EQ(statvfs(dir_.c_str(), &st), 0);
  const double freeBytes = static_cast<double>(st.f_bavail) * static_cast<double>(st.f_frsize);
  // 780 pairs' polynomials twice a step for 10^8 steps: terabytes, more than most disks hold.
  if (freeBytes < 1e12) {
    EXPECT_TRUE(contains(o.err, "are free on its disk: the run will stop before the disk is full")) << o;
  }
}

// An image name makes ffmpeg write the first frame as a picture and fail at the second ("Cannot
// write more than one file with the same name"), a pattern writes numbered pictures under the
// partial name, other endings leave ffmpeg without a format: --movie refuses them before the run.
TEST_F(CliOutputs, MovieNamesMustBeMovies) {
  const std::string scene = meeting("m.xml", "continuous-time", 0.1);
  const std::string before = slurp(scene);
  const std::vector<std::pair<std::string, std::string>> names = {
      {"out.png", " (PNG frames: -g 1)"}, {"frame%03d.png", " (PNG frames: -g 1)"},
      {"out.svg", " (SVG frames: -m DIR)"}, {"out.jpg", ""}, {"out.txt", ""}, {"movie", ""}, {"movie.", ""},
      {scene, ""}};
  for (const auto& [name, hint] : names) {
    SCOPED_TRACE(name);
    const std::string out = name == scene ? scene : path(name);
    const Outcome o = runFosssim({"-s", scene, "-d", "0", "-q", "--frame-size", "32x32", "--movie", out});
    EXPECT_TRUE(exitedWith(o, 2)) << o;
    EXPECT_TRUE(contains(o.err, "option --movie takes a movie file ending in .mp4, .mov, .mkv, .webm, .avi or .gif, "
                                "got \"" + out + "\"" + hint + "\n"))
        << o;
  }
  EXPECT_EQ(slurp(scene), before);
  // Nothing was written: the folder holds the scene only.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

// ffmpeg reads "-name" as an option and "proto:name" as a protocol ("pipe:1" is its stdout):
// FOSSSim hands it every name as a file.
TEST_F(CliOutputs, MovieNamesAreFilesWhateverTheyLookLike) {
  if (!onPath("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed (scripts/setup installs it)";
  const std::string scene = meeting("m.xml", "continuous-time", 0.1);
  const fs::path before = fs::current_path();
  fs::current_path(dir_);  // relative names, as a user types them
  // and every ending --movie accepts is a movie ffmpeg writes (in any case).
  for (const std::string name : {"-movie.mkv", "pipe:1.mkv", "file:x.mkv", "a:b.mkv", "m.mp4", "m.MOV", "m.webm",
                                 "m.avi", "m.gif"}) {
    SCOPED_TRACE(name);
    const Outcome o = runFosssim({"-s", scene, "-d", "0", "-q", "--frame-size", "32x32", "--movie=" + name});
    if (contains(o.err, "built without the renderer")) {
      fs::current_path(before);
      GTEST_SKIP() << "this build has no renderer";
    }
    EXPECT_TRUE(exitedWith(o, 0)) << o;
    EXPECT_GT(sizeOf((dir_ / name).string()), 0u) << name << " is not a file in " << dir_;
    EXPECT_EQ(o.out, "") << "the movie went to stdout";
  }
  fs::current_path(before);
}

}  // namespace
}  // namespace fosssim::testing
