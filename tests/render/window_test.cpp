// The interactive window, for real: FOSSSim -d 1 under Xvfb, driven with xdotool key presses,
// photographed with xwd. Skipped (saying why) where Xvfb, xdotool or xwd are not installed.
// Covered: stepping, zoom, pictures and -o/-g from the window; closing at the scene's end (and
// --keep-open), a failed step shown and reported, the status line over a black floor, and the
// keys i (SVG), p (PNG), h (help) and r (restart); a <maxsimfreq> beyond any step count.
#include "window_driver.h"

namespace fosssim::testing {
namespace {

/// A blue particle moving right at 1 unit/s on white, 256 pixels per unit in a 512 x 512 window.
const char* kWindowScene = R"(<scene>
  <duration time="1.0"/>
  <integrator type="explicit-euler" dt="0.1"/>
  <viewport cx="0" cy="0" size="1"/>
  <particle m="1" px="-0.5" py="0" vx="1" vy="0" fixed="0" radius="0.1"/>
  <particlecolor i="0" r="0" g="0" b="1"/>
</scene>)";

TEST(Window, StepsWithKeysAndShowsTheScene) {
  for (const char* tool : {"Xvfb", "xdotool", "xwd"})
    if (onPath(tool).empty())
      GTEST_SKIP() << tool << " is not installed, so the window cannot be tested here (scripts/setup installs xvfb, "
                   << "xdotool and x11-apps)";
  Child xvfb;
  std::string why;
  const std::string display = startXvfb(xvfb.pid, why);
  if (display.empty()) GTEST_SKIP() << "Xvfb cannot run here: " << why;

  TempDir tmp;
  writeText(tmp / "window.xml", kWindowScene);
  setenv("DISPLAY", display.c_str(), 1);
  const int log = open((tmp / "fosssim.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  Child app;
  // With -o and -g: the window's steps feed the other outputs, and the off-screen frames (OSMesa,
  // same thread) must not disturb the window's own context.
  app.pid = spawn({FOSSSIM_EXECUTABLE, "-s", tmp / "window.xml", "-d", "1", "-p", "1", "-o", tmp / "run.bin", "-g",
                   "1", "--png-dir", tmp / "pngs"},
                  log);
  close(log);
  ASSERT_GT(app.pid, 0);

  const std::string x = "DISPLAY=" + display + " ";
  std::string window;
  for (auto end = Clock::now() + std::chrono::seconds(20); Clock::now() < end && window.empty();) {
    const auto r = run(x + "xdotool search --name '^FOSSSim: '");
    if (r.exitCode == 0) window = r.output.substr(0, r.output.find('\n'));
    else std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  ASSERT_FALSE(window.empty()) << "no FOSSSim window appeared; its output:\n" << readText(tmp / "fosssim.log");

  // Three single steps: the particle moves 0.3 units = 77 pixels to the right.
  ASSERT_EQ(run(x + "xdotool key --window " + window + " s s s").exitCode, 0);
  std::string title;
  for (auto end = Clock::now() + std::chrono::seconds(10); Clock::now() < end;) {
    title = run(x + "xdotool getwindowname " + window).output;
    if (title.find("step 3/10") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_NE(title.find("window.xml  step 3/10  t = 0.3"), std::string::npos) << title;
  EXPECT_NE(title.find("paused"), std::string::npos) << title;

  const auto shot = run(x + "xwd -silent -id " + window + " -out " + (tmp / "shot.xwd"));
  ASSERT_EQ(shot.exitCode, 0) << shot.output;
  Screenshot image;
  ASSERT_TRUE(image.load(tmp / "shot.xwd", why)) << why;
  ASSERT_GE(image.width, 500);
  ASSERT_GE(image.height, 500);
  // World (-0.2, 0) is pixel (204.8, 256) from the top-left of the window.
  EXPECT_EQ(image.at(205, 255), 0x0000ffu) << hex(image.at(205, 255)) << ": the particle after 3 steps";
  EXPECT_EQ(image.at(215, 250), 0x0000ffu) << hex(image.at(215, 250));
  EXPECT_EQ(image.at(128, 255), 0xffffffu) << hex(image.at(128, 255)) << ": where the particle started";
  EXPECT_EQ(image.at(400, 100), 0xffffffu) << hex(image.at(400, 100)) << ": background";

  // Only the key press: the window is gone before a release could be delivered to it.
  // Zoom in (+): 1.25 times the scale, so the particle's centre moves to x = 256 - 0.2 * 320 = 192
  // and its radius grows from 25.6 to 32 pixels.
  ASSERT_EQ(run(x + "xdotool key --window " + window + " plus").exitCode, 0);
  Screenshot zoomed;
  for (auto end = Clock::now() + std::chrono::seconds(10); Clock::now() < end;) {
    ASSERT_EQ(run(x + "xwd -silent -id " + window + " -out " + (tmp / "zoomed.xwd")).exitCode, 0);
    ASSERT_TRUE(zoomed.load(tmp / "zoomed.xwd", why)) << why;
    if (zoomed.at(192 - 27, 255) == 0x0000ffu) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(zoomed.at(192, 255), 0x0000ffu) << hex(zoomed.at(192, 255)) << ": the particle, zoomed in";
  EXPECT_EQ(zoomed.at(192 - 27, 255), 0x0000ffu) << hex(zoomed.at(192 - 27, 255)) << ": within the larger radius";
  EXPECT_EQ(image.at(192 - 27, 255), 0xffffffu) << hex(image.at(192 - 27, 255)) << ": outside before zooming";

  const auto quit = run(x + "xdotool keydown --window " + window + " q");
  ASSERT_EQ(quit.exitCode, 0) << quit.output;
  EXPECT_EQ(app.wait(10), 0) << readText(tmp / "fosssim.log");
  // -o and -g still work from the window: record 0 and three steps of one particle (x, v: 4
  // doubles each), and three frames.
  EXPECT_EQ(std::filesystem::file_size(tmp / "run.bin"), 4u * 4u * sizeof(double));
  EXPECT_TRUE(std::filesystem::exists(tmp / "pngs/frame00003.png"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "pngs/frame00004.png"));
  xvfb.stop();
  unsetenv("DISPLAY");
}

// --- the end of a run, errors, the keys -----------------------------------------------------------

/// 10 steps of 0.1 s at <maxsimfreq> 100: the run takes a tenth of a second once started.
const char* kShortScene = R"(<scene>
  <duration time="1.0"/>
  <integrator type="explicit-euler" dt="0.1"/>
  <viewport cx="0" cy="0" size="1"/>
  <particle m="1" px="-0.5" py="0" vx="1" vy="0" fixed="0" radius="0.1"/>
</scene>)";

TEST(Window, ClosesAtTheEndOfTheSceneAsTheCoursesDid) {
  NEED_DISPLAY();
  TempDir tmp;
  writeText(tmp / "short.xml", kShortScene);
  // A scripted run: not paused, PNG frames, nobody to press q. It must return by itself.
  WindowRun w(shared.name, tmp.path, {"-s", "short.xml", "-d", "1", "-p", "0", "-g", "1"});
  ASSERT_GT(w.app.pid, 0);
  EXPECT_EQ(w.app.wait(20), 0) << w.output();
  EXPECT_TRUE(std::filesystem::exists(tmp / "pngs/frame00010.png"));
}

// A speed limit beyond any step count (the steps due overflowed a long, and the window never
// stepped): the run goes as fast as it can and ends.
TEST(Window, AHugeMaxSimFreqRunsAtFullSpeed) {
  NEED_DISPLAY();
  TempDir tmp;
  std::string scene = kShortScene;
  scene.insert(scene.find("</scene>"), "  <maxsimfreq max=\"1e30\"/>\n");
  writeText(tmp / "fast.xml", scene);
  WindowRun w(shared.name, tmp.path, {"-s", "fast.xml", "-d", "1", "-p", "0"});
  ASSERT_GT(w.app.pid, 0);
  EXPECT_EQ(w.app.wait(20), 0) << w.output();
}

TEST(Window, KeepOpenStaysAfterTheEndUntilQuit) {
  NEED_DISPLAY();
  TempDir tmp;
  writeText(tmp / "short.xml", kShortScene);
  WindowRun w(shared.name, tmp.path, {"-s", "short.xml", "-d", "1", "-p", "0", "--keep-open"});
  ASSERT_TRUE(w.find()) << w.output();
  const std::string title = w.waitTitle("done");
  EXPECT_NE(title.find("step 10/10"), std::string::npos) << title;
  EXPECT_EQ(w.app.wait(1.5), -1) << "it closed although --keep-open was given";
  ASSERT_EQ(run(w.x() + "xdotool keydown --window " + w.window + " q").exitCode, 0);
  EXPECT_EQ(w.app.wait(10), 0) << w.output();
}

/// A particle whose first step overflows to infinity: the simulation fails at step 1.
const char* kFailingScene = R"(<scene>
  <duration time="1.0"/>
  <integrator type="explicit-euler" dt="10"/>
  <viewport cx="0" cy="0" size="1"/>
  <backgroundcolor r="1" g="1" b="1"/>
  <particle m="1" px="0" py="0" vx="1e308" vy="0" fixed="0" radius="0.1"/>
</scene>)";

TEST(Window, AFailedStepIsShownAndEndsWithAnErrorStatus) {
  NEED_DISPLAY();
  TempDir tmp;
  writeText(tmp / "fail.xml", kFailingScene);
  {
    // With --keep-open the window stays, showing the error on a red panel, until q.
    WindowRun w(shared.name, tmp.path, {"-s", "fail.xml", "-d", "1", "-p", "0", "--keep-open"});
    ASSERT_TRUE(w.find()) << w.output();
    EXPECT_NE(w.waitTitle("failed").find("failed"), std::string::npos);
    Screenshot image;
    std::string why;
    bool red = false;
    for (auto end = Clock::now() + std::chrono::seconds(10); Clock::now() < end && !red;) {
      ASSERT_TRUE(w.shot(tmp / "fail.xwd", image, why)) << why;
      const std::uint32_t c = image.at(image.width / 2, image.height / 2 + 3);
      red = (c >> 16 & 0xff) > 100 && (c >> 8 & 0xff) < 40 && (c & 0xff) < 40;
    }
    EXPECT_TRUE(red) << hex(image.at(image.width / 2, image.height / 2 + 3)) << ": no error panel in the middle";
    EXPECT_EQ(w.app.wait(1), -1) << "--keep-open: the window stays after the error";
    ASSERT_EQ(run(w.x() + "xdotool keydown --window " + w.window + " q").exitCode, 0);
    EXPECT_EQ(w.app.wait(10), 1) << w.output();
    EXPECT_NE(w.output().find("FOSSSim: error:"), std::string::npos) << w.output();
  }
  {
    // Without it the window closes by itself a few seconds later, with the same message and status.
    WindowRun w(shared.name, tmp.path, {"-s", "fail.xml", "-d", "1", "-p", "0"});
    EXPECT_EQ(w.app.wait(20), 1) << w.output();
    EXPECT_NE(w.output().find("FOSSSim: error:"), std::string::npos) << w.output();
  }
}

/// A white background above a black floor that fills the lower half: the status line used to be
/// black text on it.
const char* kFloorScene = R"(<scene>
  <duration time="1.0"/>
  <integrator type="explicit-euler" dt="0.1"/>
  <viewport cx="0" cy="0" size="1"/>
  <particle m="1" px="0" py="0.5" vx="0" vy="0" fixed="0" radius="0.1"/>
  <particlepath i="0" duration="1" r="1" g="0" b="0"/>
  <halfplane px="0" py="0" nx="0" ny="1"/>
  <simplegravity fx="0" fy="-1"/>
</scene>)";

TEST(Window, TheStatusLineIsReadableOverABlackFloor) {
  NEED_DISPLAY();
  TempDir tmp;
  writeText(tmp / "floor.xml", kFloorScene);
  WindowRun w(shared.name, tmp.path, {"-s", "floor.xml", "-d", "1"});
  ASSERT_TRUE(w.find()) << w.output();
  w.waitTitle("paused");
  Screenshot image;
  std::string why;
  ASSERT_TRUE(w.shot(tmp / "floor.xwd", image, why)) << why;
  // The floor is black well above the status line...
  EXPECT_EQ(image.at(400, 400), 0x000000u) << hex(image.at(400, 400));
  // ...and the status line's strip (the bottom 20 rows) is mostly light panel with dark letters.
  int light = 0, dark = 0;
  for (int y = image.height - 20; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t c = image.at(x, y);
      const int grey = ((c >> 16 & 0xff) + (c >> 8 & 0xff) + (c & 0xff)) / 3;
      light += grey > 180;
      dark += grey < 80;
    }
  EXPECT_GT(light, image.width * 20 / 2) << "no light panel behind the status line";
  EXPECT_GT(dark, 100) << "no letters on it";
  ASSERT_EQ(run(w.x() + "xdotool keydown --window " + w.window + " q").exitCode, 0);
  EXPECT_EQ(w.app.wait(10), 0) << w.output();
}

TEST(Window, KeysSaveRestartAndHelp) {
  NEED_DISPLAY();
  TempDir tmp;
  writeText(tmp / "floor.xml", kFloorScene);
  WindowRun w(shared.name, tmp.path, {"-s", "floor.xml", "-d", "1", "--keep-open"});
  ASSERT_TRUE(w.find()) << w.output();
  ASSERT_EQ(w.key("s s s"), 0);
  EXPECT_NE(w.waitTitle("step 3/10").find("step 3/10"), std::string::npos);

  // i: an SVG of the moment, p: a PNG screenshot, both in the current folder, named by the step.
  ASSERT_EQ(w.key("i p"), 0);
  // Until the window says both were saved, which it does once each is written and renamed (each
  // is written under a partial name first: io::writeStaged).
  const auto bothSaved = [&] {
    const std::string out = w.output();
    return out.find("saved floor_step000003.png") != std::string::npos &&
           out.find("saved floor_step000003.svg") != std::string::npos;
  };
  for (auto end = Clock::now() + std::chrono::seconds(10); Clock::now() < end && !bothSaved();)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::string svg = readText(tmp / "floor_step000003.svg");
  EXPECT_NE(svg.find("<title>t = 0.3</title>"), std::string::npos) << svg.substr(0, 300);
  const std::string png = readText(tmp / "floor_step000003.png");
  ASSERT_GE(png.size(), 24u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  auto be32 = [&](std::size_t k) {
    const auto* b = reinterpret_cast<const unsigned char*>(png.data()) + k;
    return std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 | b[3];
  };
  EXPECT_EQ(be32(16), 512u) << "the window's width";
  EXPECT_EQ(be32(20), 512u) << "the window's height";
  EXPECT_NE(w.output().find("saved floor_step000003.svg"), std::string::npos) << w.output();
  EXPECT_FALSE(std::filesystem::exists(tmp / "floor_step000003.partial.png"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "floor_step000003.partial.svg"));

  // h: the help over the middle of the picture (dark letters where there was white background).
  Screenshot before, after;
  std::string why;
  ASSERT_TRUE(w.shot(tmp / "before.xwd", before, why)) << why;
  ASSERT_EQ(w.key("h"), 0);
  auto darkInMiddle = [](const Screenshot& image) {
    int dark = 0;
    for (int y = 100; y < 240; ++y)
      for (int x = 60; x < 450; ++x) dark += (image.at(x, y) & 0xff) < 80;
    return dark;
  };
  for (auto end = Clock::now() + std::chrono::seconds(10); Clock::now() < end;) {
    ASSERT_TRUE(w.shot(tmp / "after.xwd", after, why)) << why;
    if (darkInMiddle(after) > darkInMiddle(before) + 200) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_GT(darkInMiddle(after), darkInMiddle(before) + 200) << "no help text appeared";

  // r: back to t = 0 (no output records this run, so it may).
  ASSERT_EQ(w.key("h r"), 0);
  const std::string title = w.waitTitle("step 0/10");
  EXPECT_NE(title.find("step 0/10  t = 0.0"), std::string::npos) << title;
  ASSERT_EQ(run(w.x() + "xdotool keydown --window " + w.window + " q").exitCode, 0);
  EXPECT_EQ(w.app.wait(10), 0) << w.output();
}

}  // namespace
}  // namespace fosssim::testing
