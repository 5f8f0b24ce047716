// parseOptions itself: what each accepted command line sets (the command-line tests in
// cli_test.cpp check the refusals through the program).
#include "options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fosssim::app {
namespace {

/// Parses `args` (after the program name); fails the test with the error when they are refused.
Options parse(std::vector<std::string> args) {
  args.insert(args.begin(), "FOSSSim");
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  Options o;
  std::string error;
  EXPECT_TRUE(parseOptions(static_cast<int>(argv.size()), argv.data(), o, error)) << error;
  return o;
}

/// What -s a.xml -d 0 -p 0 -g 1 -o out.bin -m svg say, in whichever form they were written.
void expectTheReferenceOptions(const Options& o) {
  EXPECT_EQ(o.scene, "a.xml");
  EXPECT_FALSE(o.display);
  EXPECT_FALSE(o.paused);
  EXPECT_TRUE(o.pngs);
  EXPECT_EQ(o.output, "out.bin");
  EXPECT_EQ(o.svgDir, "svg");
}

TEST(Options, TheReferenceForms) {
  expectTheReferenceOptions(parse({"-s", "a.xml", "-d", "0", "-p", "0", "-g", "1", "-o", "out.bin", "-m", "svg"}));
  const Options defaults = parse({"-s", "a.xml"});  // the reference's defaults
  EXPECT_TRUE(defaults.display);
  EXPECT_TRUE(defaults.paused);
  EXPECT_FALSE(defaults.pngs);
  EXPECT_TRUE(defaults.warnings.empty());
  const Options graded = parse({"-s", "a.xml", "-i", "ref.bin", "-d", "0"});
  EXPECT_EQ(graded.input, "ref.bin");
}

TEST(Options, ValuesJoinedOrAfterAnEqualsSign) {
  EXPECT_EQ(parse({"-s", "a.xml", "--threads", "2"}).threads, 2);
  EXPECT_EQ(parse({"-s", "a.xml", "--threads=3"}).threads, 3);
  EXPECT_FALSE(parse({"-s", "a.xml", "-d0"}).display);
  EXPECT_EQ(parse({"-sa.xml"}).scene, "a.xml");
  // "after '='" holds for the short options too: CLI11 alone gave -o the value "=out.bin".
  expectTheReferenceOptions(parse({"-s=a.xml", "-d=0", "-p=0", "-g=1", "-o=out.bin", "-m=svg"}));
  EXPECT_EQ(parse({"-s", "a.xml", "-i=ref.bin"}).input, "ref.bin");
  EXPECT_EQ(parse({"-s", "a.xml", "-o", "=x.bin"}).output, "=x.bin");  // a separate word is the value as given
  // A file whose name begins with '-' is given with a path: ./-i.
  EXPECT_EQ(parse({"-s", "a.xml", "-o", "./-i"}).output, "./-i");
  // After '=' a value is plainly one, even one that begins like an option.
  EXPECT_EQ(parse({"-s", "a.xml", "--stats=-q.csv"}).stats, "-q.csv");
  EXPECT_EQ(parse({"-s", "a.xml", "-o=-d.bin"}).output, "-d.bin");
}

TEST(Options, TheFrameRateIsADecimal) {
  EXPECT_EQ(parse({"-s", "a.xml", "--movie", "m.mp4", "--fps", "29.97"}).fps, 29.97);
  EXPECT_EQ(parse({"-s", "a.xml", "--movie", "m.mp4", "--fps=12.5"}).fps, 12.5);
}

TEST(Options, PicturesAndMovies) {
  const Options o = parse({"-s", "a.xml", "-g", "1", "--png-dir", "frames", "--frame-size", "640x480", "--frame-every",
                           "4", "--movie", "m.mp4", "--title-card"});
  EXPECT_EQ(o.pngDir, "frames");
  EXPECT_EQ(o.frameWidth, 640);
  EXPECT_EQ(o.frameHeight, 480);
  EXPECT_EQ(o.frameEvery, 4);
  EXPECT_EQ(o.movie, "m.mp4");
  EXPECT_TRUE(o.titleCard);
  EXPECT_TRUE(parse({"-s", "a.xml", "-m", "svg", "--frame-every", "2"}).frameEvery == 2);
  EXPECT_TRUE(parse({"-s", "a.xml", "--keep-open"}).keepOpen);
}

TEST(Options, ChecksAndModes) {
  const Options o = parse({"-s", "a.xml", "-o", "out.bin", "--compact", "--compat", "--verify", "--strict", "-q"});
  EXPECT_TRUE(o.compact && o.compat && o.verify && o.strict && o.quiet);
  EXPECT_TRUE(parse({"-s", "a.xml", "--check", "--strict"}).check);
  // Grading with what applies to it.
  const Options graded = parse({"-s", "a.xml", "-i", "ref.bin", "--compat", "--threads", "4", "--strict", "-q"});
  EXPECT_TRUE(graded.compat && graded.strict && graded.quiet);
  EXPECT_EQ(graded.threads, 4);
}

TEST(Options, HelpAndVersionNeedNoScene) {
  EXPECT_TRUE(parse({"-h"}).help);
  EXPECT_TRUE(parse({"--help"}).help);
  EXPECT_TRUE(parse({"--version"}).version);
  EXPECT_EQ(versionText().rfind("FOSSSim ", 0), 0u);
}

TEST(Options, AFrameSizeWithNothingToDrawIsAWarning) {
  const Options o = parse({"-s", "a.xml", "-d", "0", "--frame-size", "64x64"});
  ASSERT_EQ(o.warnings.size(), 1u);
  EXPECT_NE(o.warnings[0].find("--frame-size"), std::string::npos);
  EXPECT_TRUE(parse({"-s", "a.xml", "--frame-size", "64x64"}).warnings.empty());  // the window uses it
  EXPECT_TRUE(parse({"-s", "a.xml", "-d", "0", "-m", "svg", "--frame-size", "64x64"}).warnings.empty());
}

}  // namespace
}  // namespace fosssim::app
