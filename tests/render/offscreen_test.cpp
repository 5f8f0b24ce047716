// Headless frames (OSMesa): pixels that must hold in a rendered picture, PNG files, and the
// command line's -g, --frame-every, --frame-size, --movie and -d 1 without a display.
#include "render_test_support.h"

#include "fosssim/render/offscreen_renderer.h"
#include "fosssim/render/png_writer.h"
#include "fosssim/render/raster_frames.h"

#include <cstdlib>
#include <limits>

namespace fosssim::render {
namespace {

using testing::kShapesScene;
using testing::parsed;
using testing::TempDir;

/// The shapes scene (render_test_support.h) drawn at 100 x 80: 40 pixels per unit, origin at
/// pixel (50, 40) counted from the bottom-left.
class Offscreen : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = parsed(kShapesScene);
    View view;
    view.width = 100;
    view.height = 80;
    view.camera = initialCamera(file_.look, file_.initial, 100, 80);
    picture_ = makePicture(file_, file_.initial, PathTrails(), view);
    std::unique_ptr<OffscreenRenderer> renderer;
    const Status s = OffscreenRenderer::create(100, 80, renderer);
    ASSERT_TRUE(s.isOk()) << s.message();
    const Status r = renderer->render(picture_, image_);
    ASSERT_TRUE(r.isOk()) << r.message();
    ASSERT_EQ(image_.width, 100);
    ASSERT_EQ(image_.height, 80);
  }

  /// Pixel (i, j) counted from the bottom-left, as the picture's coordinates are.
  void expectColor(int i, int j, int r, int g, int b, const char* what) const {
    const std::uint8_t* p = image_.pixel(i, image_.height - 1 - j);
    EXPECT_NEAR(p[0], r, 2) << what << " at (" << i << ", " << j << ")";
    EXPECT_NEAR(p[1], g, 2) << what << " at (" << i << ", " << j << ")";
    EXPECT_NEAR(p[2], b, 2) << what << " at (" << i << ", " << j << ")";
  }

  SceneFile file_;
  Picture picture_;
  Image image_;
};

TEST_F(Offscreen, BackgroundAwayFromObjects) {
  expectColor(90, 40, 51, 102, 153, "background");
  expectColor(90, 22, 51, 102, 153, "free side of the half-plane");
}

TEST_F(Offscreen, ParticleColourAtItsCentre) {
  expectColor(70, 50, 255, 0, 0, "particle 0");
  expectColor(30, 60, 166, 75, 0, "particle 1 (default colour)");
}

TEST_F(Offscreen, HalfPlaneSolidSideIsFilled) {
  expectColor(10, 5, 0, 128, 0, "solid side");
  expectColor(90, 2, 0, 128, 0, "solid side");
  expectColor(70, 15, 0, 128, 0, "just below the boundary");
}

TEST_F(Offscreen, ParticlesAreDrawnOverHalfPlanesAndEdges) {
  expectColor(50, 20, 166, 75, 0, "particle on the half-plane's boundary");
  expectColor(30, 44, 0, 99, 99, "edge between its particles");
  expectColor(29, 44, 0, 99, 99, "edge between its particles");
}

TEST_F(Offscreen, DiskEdgesAreSmoothed) {
  // Around particle 0 (centre (70, 50), radius 8 px) some pixels mix red and background.
  int mixed = 0;
  for (int j = 40; j < 60; ++j)
    for (int i = 60; i < 80; ++i) {
      const std::uint8_t* p = image_.pixel(i, image_.height - 1 - j);
      if (p[0] > 60 && p[0] < 245 && p[2] > 10 && p[2] < 145) ++mixed;
    }
  EXPECT_GE(mixed, 20);
}

TEST_F(Offscreen, TimeIsShownInTheTopLeftCornerInTheInverseColour) {
  // Ink is (204, 153, 102) on (51, 102, 153): count pixels nearer the ink than the background
  // (thin anti-aliased strokes at this small size cover few pixels fully).
  int ink = 0, fullInk = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 60; ++x) {
      const std::uint8_t* p = image_.pixel(x, y);
      auto d2 = [&](int r, int g, int b) {
        return (p[0] - r) * (p[0] - r) + (p[1] - g) * (p[1] - g) + (p[2] - b) * (p[2] - b);
      };
      if (d2(204, 153, 102) < d2(51, 102, 153)) ++ink;
      if (d2(204, 153, 102) < 3 * 8 * 8) ++fullInk;
    }
  EXPECT_GE(ink, 30);
  EXPECT_GE(fullInk, 3);
  // and nothing of it elsewhere, e.g. the top-right corner
  for (int y = 0; y < 20; ++y)
    for (int x = 80; x < 100; ++x) EXPECT_EQ(image_.pixel(x, y)[0], 51) << x << "," << y;
}

TEST_F(Offscreen, PngRoundTrip) {
  TempDir tmp;
  const std::string path = pngFrameName(tmp.path, 7);
  EXPECT_EQ(path, tmp.path + "/frame00007.png");
  ASSERT_TRUE(writePng(path, image_).isOk());
  Image back;
  const Status s = readPng(path, back);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(back.width, image_.width);
  EXPECT_EQ(back.height, image_.height);
  EXPECT_EQ(back.rgb, image_.rgb);
}

TEST(OffscreenRenderer, RejectsAPictureOfAnotherSize) {
  std::unique_ptr<OffscreenRenderer> renderer;
  ASSERT_TRUE(OffscreenRenderer::create(32, 32, renderer).isOk());
  Picture pic;
  pic.view.width = 64;
  pic.view.height = 64;
  Image image;
  EXPECT_FALSE(renderer->render(pic, image).isOk());
}

// --- the command line -------------------------------------------------------------------------

std::string fosssim() { return FOSSSIM_EXECUTABLE; }

std::vector<std::string> filesIn(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir, ec))
    if (e.is_regular_file()) names.push_back(std::filesystem::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(CommandLine, PngFramesAfterEveryStepNumberedFromOneInANewFolder) {
  TempDir tmp;
  testing::writeText(tmp / "scene.xml", kShapesScene);
  const auto r = testing::run("cd " + tmp.path + " && " + fosssim() + " -s scene.xml -d 0 -q -g 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::string> expected = {"scene.xml"};
  for (int k = 1; k <= 10; ++k) expected.push_back(pngFrameName("pngs", k));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(filesIn(tmp.path), expected);
  Image frame;
  ASSERT_TRUE(readPng(tmp / "pngs/frame00010.png", frame).isOk());
  EXPECT_EQ(frame.width, 512);
  EXPECT_EQ(frame.height, 512);
}

TEST(CommandLine, FrameEveryAndFrameSizeAndPngDir) {
  TempDir tmp;
  testing::writeText(tmp / "scene.xml", kShapesScene);
  const auto r = testing::run(fosssim() + " -s " + (tmp / "scene.xml") + " -d 0 -q -g 1 --frame-every 3 " +
                              "--frame-size 64x48 --png-dir " + (tmp / "deep/frames"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(filesIn(tmp / "deep"), (std::vector<std::string>{"frames/frame00001.png", "frames/frame00002.png",
                                                             "frames/frame00003.png"}));
  Image frame;
  ASSERT_TRUE(readPng(tmp / "deep/frames/frame00003.png", frame).isOk());
  EXPECT_EQ(frame.width, 64);
  EXPECT_EQ(frame.height, 48);
}

TEST(CommandLine, MoviePipedIntoFfmpegLeavesNoFrames) {
  if (testing::onPath("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed (scripts/setup installs it)";
  TempDir tmp;
  testing::writeText(tmp / "scene.xml", kShapesScene);
  const auto r = testing::run("cd " + tmp.path + " && " + fosssim() +
                              " -s scene.xml -d 0 -q --movie out/movie.mp4 --fps 10 --frame-size 96x64");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(filesIn(tmp.path), (std::vector<std::string>{"out/movie.mp4", "scene.xml"}));
  EXPECT_GT(std::filesystem::file_size(tmp / "out/movie.mp4"), 0u);
  if (!testing::onPath("ffprobe").empty()) {
    const auto probe = testing::run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                    "stream=width,height,nb_read_frames -of csv=p=0 " + (tmp / "out/movie.mp4"));
    EXPECT_EQ(probe.output, "96,64,11\n") << "the initial state and the 10 steps";
  }
}

// --- movies: real-time rate, the initial state first, the title card ---------------------------

TEST(MovieTiming, DefaultsToRealTimeCappedNearSixtyFrames) {
  // Real time: each movie frame lasts as long as the scene time between frames.
  auto realTime = [](const MovieTiming& t, double dt, int every) {
    return std::abs(t.fps * dt * every * static_cast<double>(t.every) - 1) < 1e-12;
  };
  const MovieTiming a = movieTiming(0, 0.04, 1);  // 25 frames a second
  EXPECT_TRUE(a.realTime);
  EXPECT_EQ(a.every, 1);
  EXPECT_DOUBLE_EQ(a.fps, 25);
  const MovieTiming b = movieTiming(0, 0.01, 8);  // scripts/run's old --frame-every 8 at dt 0.01
  EXPECT_DOUBLE_EQ(b.fps, 12.5);
  EXPECT_TRUE(realTime(b, 0.01, 8));
  for (double dt : {0.01, 0.005, 0.001, 1e-5, 3e-3}) {  // above 60 fps: frames left out, still real time
    const MovieTiming t = movieTiming(0, dt, 1);
    EXPECT_TRUE(t.realTime) << dt;
    EXPECT_TRUE(realTime(t, dt, 1)) << dt;
    EXPECT_LE(t.fps, kMaxRealTimeFps + 1e-9) << dt;
    EXPECT_GT(t.fps, kMaxRealTimeFps / 2) << dt << ": no more frames left out than needed";
  }
  EXPECT_EQ(movieTiming(0, 1e-5, 1).every, 1667);  // 100,000 frames a second would be no movie
  for (double dt : {1e-20, 1e-30, 1e-300, 5e-324}) {  // more steps a frame than any run takes: the first frame alone
    const MovieTiming t = movieTiming(0, dt, 1);
    EXPECT_EQ(t.every, std::numeric_limits<long>::max()) << dt;
    EXPECT_DOUBLE_EQ(t.fps, kMaxRealTimeFps) << dt << ": not 1e+30 fps, which ffmpeg refuses";
  }
  // With --frame-every, the steps between movie frames (every x K) still fit a long.
  EXPECT_EQ(movieTiming(0, 1e-30, 1000).every, std::numeric_limits<long>::max() / 1000);
  const MovieTiming slow = movieTiming(0, 10, 1);  // one frame per 10 s of the scene
  EXPECT_FALSE(slow.realTime);
  EXPECT_DOUBLE_EQ(slow.fps, kMinRealTimeFps);
  EXPECT_DOUBLE_EQ(slow.speed, 10);
  const MovieTiming given = movieTiming(30, 0.01, 1);  // --fps 30: every frame, 0.3 x real time
  EXPECT_FALSE(given.realTime);
  EXPECT_EQ(given.every, 1);
  EXPECT_DOUBLE_EQ(given.fps, 30);
  EXPECT_DOUBLE_EQ(given.speed, 0.3);
}

/// A blue disk of radius 0.3 that jumps 1 unit right in each of its 4 steps, seen through a fixed
/// viewport at 256 x 128: 128 pixels per unit, x = -0.5 at pixel column 0.
const char* kJumpScene = R"(<scene>
  <description text="A blue disk jumps to the right."/>
  <duration time="0.4"/>
  <integrator type="explicit-euler" dt="0.1"/>
  <viewport cx="0.5" cy="0" size="0.5"/>
  <backgroundcolor r="1" g="1" b="1"/>
  <particle m="1" px="-0.5" py="0" vx="10" vy="0" fixed="0" radius="0.3"/>
  <particlecolor i="0" r="0" g="0" b="1"/>
</scene>)";

/// The movie's frames as images (ffmpeg decodes them to PNG files in `dir`).
std::vector<Image> decodeMovie(const std::string& movie, const std::string& dir) {
  std::vector<Image> frames;
  const auto r = testing::run("ffmpeg -hide_banner -loglevel error -i " + movie + " " + dir + "/decoded%03d.png");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  for (int k = 1;; ++k) {
    Image image;
    char name[32];
    std::snprintf(name, sizeof name, "/decoded%03d.png", k);
    if (!readPng(dir + name, image).isOk()) break;
    frames.push_back(std::move(image));
  }
  return frames;
}

bool blueAt(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[2] > 200 && p[0] < 60 && p[1] < 60;  // H.264 is lossy: near blue
}

TEST(CommandLine, MovieAtRealTimeOpensWithTheInitialState) {
  if (testing::onPath("ffmpeg").empty() || testing::onPath("ffprobe").empty())
    GTEST_SKIP() << "ffmpeg and ffprobe are not installed (scripts/setup installs them)";
  TempDir tmp;
  testing::writeText(tmp / "jump.xml", kJumpScene);
  const auto r = testing::run(fosssim() + " -s " + (tmp / "jump.xml") + " -d 0 --movie " + (tmp / "m.mp4") +
                              " --frame-size 256x128");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // dt = 0.1: real time is 10 frames a second, and the run says so.
  EXPECT_NE(r.output.find("10 fps"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("real time"), std::string::npos) << r.output;
  const auto probe = testing::run(
      "ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of csv=p=0 " + (tmp / "m.mp4"));
  EXPECT_EQ(probe.output, "10/1\n");
  const std::vector<Image> frames = decodeMovie(tmp / "m.mp4", tmp.path);
  ASSERT_EQ(frames.size(), 5u) << "t = 0 and the 4 steps";
  // The disk's centre: x = -0.5 (pixel 0) at t = 0, then 0.5 (128) after step 1, 1.5 (off the
  // picture) after step 2. The first frame is the initial state, not the first step.
  EXPECT_TRUE(blueAt(frames[0], 10, 64)) << "the first frame shows the disk where it starts";
  EXPECT_FALSE(blueAt(frames[0], 128, 64));
  EXPECT_TRUE(blueAt(frames[1], 128, 64)) << "the second frame, after step 1";
  EXPECT_FALSE(blueAt(frames[1], 10, 64));
}

TEST(CommandLine, TitleCardOpensTheMovieForTwoSeconds) {
  if (testing::onPath("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed (scripts/setup installs it)";
  TempDir tmp;
  testing::writeText(tmp / "jump.xml", kJumpScene);
  const auto r = testing::run(fosssim() + " -s " + (tmp / "jump.xml") + " -d 0 -q --title-card --movie " +
                              (tmp / "m.mp4") + " --frame-size 256x128");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output, "") << "-q: nothing said";
  const std::vector<Image> frames = decodeMovie(tmp / "m.mp4", tmp.path);
  ASSERT_EQ(frames.size(), 20u + 5u) << "2 s at 10 fps, then t = 0 and the 4 steps";
  for (int k = 0; k < 20; ++k) {
    // The card: no disk, some dark ink (the description) on white.
    EXPECT_FALSE(blueAt(frames[k], 10, 64)) << k;
    int ink = 0;
    for (int y = 0; y < 128; ++y)
      for (int x = 0; x < 256; ++x) ink += frames[k].pixel(x, y)[0] < 100;
    EXPECT_GT(ink, 100) << k;
  }
  EXPECT_TRUE(blueAt(frames[20], 10, 64)) << "then the initial state";
}

TEST(CommandLine, MovieWithoutFfmpegSaysSo) {
  TempDir tmp;
  testing::writeText(tmp / "scene.xml", kShapesScene);
  const auto r = testing::run("cd " + tmp.path + " && PATH=" + tmp.path + " " + fosssim() +
                              " -s scene.xml -d 0 -q --movie movie.mp4");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("--movie needs ffmpeg, which is not on PATH"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(tmp / "movie.mp4"));
}

TEST(CommandLine, WindowWithoutADisplayRunsHeadless) {
  TempDir tmp;
  testing::writeText(tmp / "scene.xml", kShapesScene);
  const auto r = testing::run("cd " + tmp.path + " && env -u DISPLAY " + fosssim() + " -s scene.xml -d 1 -g 1");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("no window (DISPLAY is not set); running headless"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(tmp / "pngs/frame00010.png"));
}

TEST(CommandLine, HelpNamesThePictureOptions) {
  const auto r = testing::run(fosssim() + " -h");
  ASSERT_EQ(r.exitCode, 0);
  for (const char* option : {"--frame-size", "--frame-every", "--png-dir", "--movie", "--fps", "-m DIR", "-g 0|1",
                             "--title-card", "--keep-open"})
    EXPECT_NE(r.output.find(option), std::string::npos) << option;
  // and the window's keys (the help wraps lines: compare with single spaces)
  std::string text = r.output;
  for (char& c : text) c = c == '\n' ? ' ' : c;
  while (text.find("  ") != std::string::npos) text.replace(text.find("  "), 2, " ");
  for (const char* key : {"r restart", "i save an SVG", "p save a PNG screenshot", "h or ? help", "q/Esc quit"})
    EXPECT_NE(text.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace fosssim::render
