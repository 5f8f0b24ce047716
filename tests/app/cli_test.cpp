// The command line: options (exit 2 with a one-line message for a bad command line, 0 and the
// usage for -h), and every bad scene in tests/data/bad (exit 1 with a located message, never a
// crash or a hang). Exit codes: 0 ok, 1 bad input or failed run or grade, 2 bad command line.
#include "run_fosssim.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/integrator.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace fosssim::testing {
namespace {

const std::string kBad = std::string(FOSSSIM_TEST_DATA) + "/bad";

/// A small good scene in a temporary file, for the option tests.
std::string goodScene() {
  static const std::string path = [] {
    const std::string p =
        std::filesystem::temp_directory_path() / ("fosssim-cli-good-" + std::to_string(getpid()) + ".xml");
    std::ofstream(p) << "<scene><duration time=\"0.1\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/>"
                        "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"0\"/></scene>\n";
    return p;
  }();
  // Shared by every test of this executable, so it goes when the executable ends.
  static const bool cleanup = std::atexit([] { std::remove(path.c_str()); }) == 0;
  (void)cleanup;
  return path;
}

void expectUsageError(const std::vector<std::string>& args, const std::string& fragment) {
  const Outcome o = runFosssim(args);
  EXPECT_TRUE(exitedWith(o, 2)) << o;
  EXPECT_TRUE(contains(o.err, fragment)) << "missing \"" << fragment << "\"\n" << o;
  EXPECT_EQ(o.out, "") << o;  // nothing ran
}

TEST(Cli, HelpPrintsTheUsageAndSucceeds) {
  for (const char* h : {"-h", "--help"}) {
    const Outcome o = runFosssim({h});
    EXPECT_TRUE(exitedWith(o, 0)) << o;
    EXPECT_EQ(o.out.rfind("usage: FOSSSim -s scene.xml", 0), 0u) << o;
    for (const char* option : {"-s FILE", "-d 0|1", "-p 0|1", "-g 0|1", "-o FILE", "-i FILE", "-m DIR"})
      EXPECT_TRUE(contains(o.out, option)) << option;
  }
  // -h wins over a missing scene, and runs nothing.
  const Outcome o = runFosssim({"-d", "0", "-h"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
}

TEST(Cli, NoSceneIsAUsageError) {
  expectUsageError({}, "no scene file given");
  expectUsageError({"-d", "0"}, "no scene file given");
  expectUsageError({"-s", ""}, "-s");
}

TEST(Cli, UnknownOptionsAreNamed) {
  expectUsageError({"-s", goodScene(), "--frobnicate"}, "\"--frobnicate\"");
  expectUsageError({"-x", "-s", goodScene()}, "\"-x\"");
  expectUsageError({goodScene()}, goodScene());  // a scene without -s
  expectUsageError({"-s", goodScene(), "-D", "0"}, "\"-D\"");
}

// "--" ends the options, as is conventional (it was "unknown option \"--\""); FOSSSim takes
// nothing but options, so a word after it is unexpected, and "-o --" names no file.
TEST(Cli, DoubleDashEndsTheOptions) {
  const Outcome o = runFosssim({"-s", goodScene(), "-d", "0", "-q", "--"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  expectUsageError({"-d", "0", "--", "-s", goodScene()}, "unexpected argument \"-s\" after \"--\"");
  expectUsageError({"-s", goodScene(), "-d", "0", "-o", "--"}, "option -o needs a value, and the next word \"--\"");
  EXPECT_FALSE(std::filesystem::exists("--"));
}

// A number on the command line is the digits alone: strtol and strtod skipped leading spaces and
// took a '+', so --threads " 2" and --threads +2 were 2.
TEST(Cli, NumbersTakeNoSpacesOrPlusSign) {
  const std::vector<std::vector<std::string>> cases = {
      {"--threads", " 2"}, {"--threads", "+2"}, {"--threads", "2 "}, {"--frame-every", "+2", "-g", "1"},
      {"--frame-size", " 64x48"}, {"--frame-size", "64x+48"}, {"--fps", "+25", "--movie", "m.mp4"}};
  for (const auto& extra : cases) {
    std::vector<std::string> args = {"-s", goodScene(), "-d", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    expectUsageError(args, "option " + extra[0] + " takes");
    expectUsageError(args, "got \"" + extra[1] + "\" (spaces and a '+' sign are not read)");
  }
}

TEST(Cli, OutputAndInputTogetherIsAUsageError) {
  expectUsageError({"-s", goodScene(), "-d", "0", "-o", "a.bin", "-i", "b.bin"}, "-o");
  expectUsageError({"-s", goodScene(), "-i", "b.bin", "-o", "a.bin"}, "cannot be used together");
}

TEST(Cli, FlagsTakeZeroOrOne) {
  for (const char* flag : {"-d", "-p", "-g"})
    for (const char* bad : {"2", "yes", "-1", "", "00", "1.0", "true"})
      expectUsageError({"-s", goodScene(), flag, bad},
                       std::string("option ") + flag + (*bad ? " takes 0 or 1" : " needs a value"));
}

TEST(Cli, OptionsWithoutTheirValue) {
  for (const char* option : {"-s", "-d", "-p", "-g", "-o", "-i", "-m"})
    expectUsageError({option}, std::string("option ") + option + " needs a value");
  // An empty file name is no file name.
  for (const char* option : {"-o", "-i", "-m"}) expectUsageError({"-s", goodScene(), "-d", "0", option, ""}, option);
}

TEST(Cli, AnOptionGivenTwiceIsAUsageError) {
  // The reference took the last -s; a user who gives two scenes meant one of them.
  expectUsageError({"-s", goodScene(), "-s", "other.xml", "-d", "0"}, "option -s given 2 times");
  expectUsageError({"-s", goodScene(), "-s", "other.xml"}, "\"other.xml\"");
  expectUsageError({"-s", goodScene(), "-d", "0", "-d", "1"}, "option -d given 2 times");
  expectUsageError({"-s", goodScene(), "--threads", "2", "--threads=3"}, "option --threads given 2 times");
}

// -i grades and writes nothing: every option that would write or show something is refused by
// name, before anything is created.
TEST(Cli, GradingRefusesWhatItWouldIgnore) {
  const std::string dir = std::filesystem::temp_directory_path() / ("fosssim-cli-svg-" + std::to_string(getpid()));
  const std::vector<std::vector<std::string>> refused = {
      {"-g", "1"}, {"-m", dir}, {"--movie", dir + ".mp4"}, {"--verify"}, {"--compact"}, {"--keep-open"}, {"--check"}};
  for (const auto& extra : refused) {
    std::vector<std::string> args = {"-s", goodScene(), "-i", "b.bin"};
    args.insert(args.end(), extra.begin(), extra.end());
    expectUsageError(args, extra[0] == "--check"
                               ? "--check runs nothing, so it cannot grade"
                               : extra[0] + (extra[0] == "-g" ? " 1" : "") + " cannot be used with it");
  }
  EXPECT_FALSE(std::filesystem::exists(dir));
  // What grading does use is accepted (the grade itself fails: b.bin does not exist).
  const Outcome o = runFosssim({"-s", goodScene(), "-i", "b.bin", "--compat", "--threads", "2", "-q", "-g", "0"});
  EXPECT_TRUE(exitedWith(o, 1)) << o;
}

// Options that only shape another output are errors without it (a user who forgot -g 1 gets no
// PNGs and would not know why); the message names what is missing.
TEST(Cli, OptionsWithoutTheOutputTheyShapeAreUsageErrors) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--png-dir", "frames"}, "-g 1 is not given"},
      {{"-g", "0", "--png-dir", "frames"}, "-g 1 is not given"},
      {{"--fps", "25"}, "no --movie is given"},
      {{"--frame-every", "2"}, "-g 1, -m and --movie, and none of them is given"},
      {{"--title-card"}, "no --movie is given"},
      {{"--compact"}, "no -o is given"},
      {{"--keep-open"}, "-d 0 opens none"},
      {{"--check", "-o", "out.bin"}, "-o cannot be used with it"},
  };
  for (const auto& [extra, fragment] : cases) {
    std::vector<std::string> args = {"-s", goodScene(), "-d", "0"};
    args.insert(args.end(), extra.begin(), extra.end());
    expectUsageError(args, fragment);
    expectUsageError(args, extra[0] == "-g" ? "--png-dir" : extra[0]);
  }
  EXPECT_FALSE(std::filesystem::exists("frames"));
}

// A frame size with nothing to draw is harmless: a warning, and the run goes on.
TEST(Cli, AFrameSizeWithNothingToDrawOnlyWarns) {
  const Outcome o = runFosssim({"-s", goodScene(), "-d", "0", "-q", "--frame-size", "64x48"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_TRUE(contains(o.err, "FOSSSim: warning: --frame-size has no effect")) << o;
}

TEST(Cli, ValuesAfterAnEqualsSign) {
  const Outcome o = runFosssim({"-s", goodScene(), "-d", "0", "-q", "--threads=2"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  // Short options too: "-o=out.bin" wrote a file named "=out.bin", and "-d=0" was refused.
  const std::string out =
      std::filesystem::temp_directory_path() / ("fosssim-cli-eq-" + std::to_string(getpid()) + ".bin");
  const Outcome shortForms = runFosssim({"-s=" + goodScene(), "-d=0", "-q", "-o=" + out});
  EXPECT_TRUE(exitedWith(shortForms, 0)) << shortForms;
  EXPECT_TRUE(std::filesystem::exists(out));
  std::filesystem::remove(out);
  expectUsageError({"-s", goodScene(), "-d=2"}, "option -d takes 0 or 1, got \"2\"");
  const bool existed = std::filesystem::exists("=");
  expectUsageError({"-s", goodScene(), "-d", "0", "-o="}, "option -o needs a value");
  if (!existed && std::filesystem::remove("=")) ADD_FAILURE() << "-o= wrote a file named \"=\"";
  expectUsageError({"-s", goodScene(), "--threads=0"}, "option --threads takes an integer from 1 to");
  expectUsageError({"-s", goodScene(), "--threads="}, "option --threads needs a value");
  expectUsageError({"-s", goodScene(), "--fps=fast", "--movie", "m.mp4"}, "option --fps takes a frame rate");
  expectUsageError({"-s", goodScene(), "--fps=0x10", "--movie", "m.mp4"}, "option --fps takes a frame rate");  // not 16
  // Flags take no value: "--compat=0" would read as "not compat" to some and be ignored by others.
  expectUsageError({"-s", goodScene(), "--compat=0"}, "option --compat takes no value");
  for (const char* flag : {"-q", "-h"}) {  // CLI11 reads "-q=1" as -q and an unknown word "-=1"
    expectUsageError({"-s", goodScene(), std::string(flag) + "=1"}, "option " + std::string(flag) + " takes no value");
    expectUsageError({"-s", goodScene(), "-d", "0", std::string(flag) + "=0"}, "takes no value");
  }
}

// CLI11 takes the next word as an option's value whatever it is: "-o -i ref.bin" wrote the
// trajectory to a file named "-i" (and graded nothing), "-o -q" ran without -q.
TEST(Cli, AnOptionIsNoOtherOptionsValue) {
  const std::vector<std::vector<std::string>> cases = {
      {"-o", "-i", "ref.bin"}, {"-o", "-q"}, {"-o", "--verify"}, {"-o", "--threads=2"}, {"-m", "-d0"},
      {"--stats", "-q"},       {"-s", "-d", "0"}, {"-i", "--compat"}, {"-d", "-q"}};
  for (const auto& extra : cases) {
    std::vector<std::string> args = {"-s", goodScene(), "-d", "0"};
    if (extra[0] == "-s" || extra[0] == "-d") args = {};
    args.insert(args.end(), extra.begin(), extra.end());
    const bool existed = std::filesystem::exists(extra[1]);
    const Outcome o = runFosssim(args);
    EXPECT_TRUE(exitedWith(o, 2)) << o;
    EXPECT_TRUE(
        contains(o.err, "option " + extra[0] + " needs a value, and the next word \"" + extra[1] + "\" is an option"))
        << o;
    // Without the check a file of the option's name appeared in the working directory.
    if (!existed && std::filesystem::remove_all(extra[1]) > 0) ADD_FAILURE() << "wrote \"" << extra[1] << "\"";
  }
  // "-" is standard output (or input) by convention: "-o -" wrote a file named "-".
  for (const char* option : {"-o", "--stats", "-m", "-s"}) {
    const bool existed = std::filesystem::exists("-");
    std::vector<std::string> args = {"-d", "0", option, "-"};
    if (option != std::string("-s")) args.insert(args.begin(), {"-s", goodScene()});
    expectUsageError(args, "option " + std::string(option) + " takes a name, and \"-\"");
    if (!existed && std::filesystem::remove_all("-") > 0) ADD_FAILURE() << option << " - wrote a file named \"-\"";
  }
}

TEST(Cli, NearMissesAreSuggested) {
  expectUsageError({"-s", goodScene(), "--thread", "2"}, "unknown option \"--thread\" (did you mean --threads?)");
  expectUsageError({"-s", goodScene(), "--verfy"}, "did you mean --verify?");
  expectUsageError({"-s", goodScene(), "-D", "0"}, "did you mean -d?");
}

TEST(Cli, VersionPrintsTheProgramAndItsVersion) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--version"}, std::vector<std::string>{"-s", goodScene(), "--version"}}) {
    const Outcome o = runFosssim(args);
    EXPECT_TRUE(exitedWith(o, 0)) << o;
    // "FOSSSim <major>.<minor>", then the commit where the build knew it; one line.
    EXPECT_TRUE(std::regex_match(o.out, std::regex("FOSSSim [0-9]+\\.[0-9]+[^\n]*\n"))) << o;
    EXPECT_EQ(o.err, "") << o;
  }
}

/// `text` with every run of white space made one space (-h wraps its lines).
std::string words(const std::string& text) {
  std::istringstream in(text);
  std::string out, word;
  while (in >> word) out += (out.empty() ? "" : " ") + word;
  return out;
}

// -h lists every collision type and integrator of the scene format with its table's summary, and
// every option.
TEST(Cli, HelpListsTheKeywordTablesAndEveryOption) {
  const Outcome o = runFosssim({"-h"});
  ASSERT_TRUE(exitedWith(o, 0)) << o;
  const std::string help = words(o.out);
  for (const CollisionEntry& e : collisionTable())
    EXPECT_TRUE(contains(help, std::string(e.keyword) + " " + words(e.summary))) << e.keyword;
  for (const IntegratorEntry& e : integratorTable())
    EXPECT_TRUE(contains(help, std::string(e.keyword) + " " + words(e.summary))) << e.keyword;
  for (const char* option : {"--compat", "--verify", "--threads N", "--strict", "--check", "--compact",
                             "--frame-size WxH", "--frame-every K", "--png-dir DIR", "--movie FILE.mp4", "--fps N",
                             "--title-card", "--keep-open", "-q", "-h, --help", "--version"})
    EXPECT_TRUE(contains(o.out, option)) << option;
}

TEST(Cli, AGoodSceneRunsHeadless) {
  const Outcome o = runFosssim({"-s", goodScene(), "-d", "0", "-q"});
  EXPECT_TRUE(exitedWith(o, 0)) << o;
  EXPECT_FALSE(contains(o.err, "error")) << o;
}

/// A scene written to a temporary file of this process (removed by the caller).
std::string tempScene(const std::string& name, const std::string& text) {
  const std::string path =
      std::filesystem::temp_directory_path() / ("fosssim-cli-" + name + "-" + std::to_string(getpid()) + ".xml");
  std::ofstream(path) << text;
  return path;
}

/// Runs a scene headless in the default mode and under --compat; calls check(outcome, compat).
template <class Check>
void runBothModes(const std::string& scene, Check&& check) {
  for (const bool compat : {false, true}) {
    std::vector<std::string> args = {"-s", scene, "-d", "0", "-q"};
    if (compat) args.push_back("--compat");
    check(runFosssim(args), compat);
  }
}

// A run whose energy blows up (a ball falling into a penalty layer of stiffness 1e200) stops at
// the step it happens with exit 1 and a message naming step, particle, force and what to change.
TEST(Cli, AnEnergyBlowUpStopsTheRunWithExitOne) {
  const std::string scene =
      tempScene("blowup",
                "<scene><duration time=\"2\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>"
                "<collision type=\"penalty\" k=\"1e200\" thickness=\"0.01\"/>"
                "<particle m=\"1\" px=\"0\" py=\"1\" vx=\"0\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
                "<halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/>"
                "<simplegravity fx=\"0\" fy=\"-9.81\"/></scene>\n");
  runBothModes(scene, [](const Outcome& o, bool) {
    EXPECT_TRUE(exitedWith(o, 1)) << o;
    for (const char* part : {"FOSSSim: error: step 4", "energy blow-up", "particle 0", "collision penalty",
                             "smaller time step", "smaller stiffness k"})
      EXPECT_TRUE(contains(o.err, part)) << "missing \"" << part << "\"\n" << o;
  });
  std::filesystem::remove(scene);
}

// Finite coordinates at +-9e307 (their difference overflows) used to crash every collision
// handler in the broad phase (SIGSEGV). Now: no crash in either mode; the default mode's exact
// query names the pair it cannot represent and exits 1, --compat's reference query finds the
// overflowing polynomials never positive (no collision, as the course's) and finishes.
TEST(Cli, HugeFiniteCoordinatesDoNotCrashAnyHandler) {
  for (const std::string type : {"simple", "continuous-time", "hybrid", "penalty"}) {
    const std::string scene =
        tempScene("huge", "<scene><duration time=\"0.02\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>"
                          "<collision type=\"" + type + "\"/>"
                          "<particle m=\"1\" px=\"9e307\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"
                          "<particle m=\"1\" px=\"-9e307\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"
                          "<particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/></scene>\n");
    runBothModes(scene, [&](const Outcome& o, bool compat) {
      const bool exact = !compat && (type == "continuous-time" || type == "hybrid");
      EXPECT_TRUE(exitedWith(o, exact ? 1 : 0)) << type << (compat ? " --compat" : "") << "\n" << o;
      if (exact) {
        EXPECT_TRUE(contains(o.err, "particle-particle pair (particle 0, particle 1) cannot be tested")) << o;
      }
    });
    std::filesystem::remove(scene);
  }
}

TEST(Cli, EveryBadSceneFailsWithALocatedMessage) {
  const auto table = readExpectations(kBad);
  ASSERT_GE(table.size(), 25u) << "tests/data/bad/EXPECTED is missing or short";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kBad)) {
    const std::string name = entry.path().filename().string();
    if (name == "EXPECTED") continue;
    ++files;
    SCOPED_TRACE(name);
    const auto it = table.find(name);
    ASSERT_NE(it, table.end()) << name << " has no line in tests/data/bad/EXPECTED";
    const std::string path = entry.path().string();
    const Outcome o = runFosssim({"-s", path, "-d", "0", "-q"});
    EXPECT_TRUE(exitedWith(o, 1)) << o;
    EXPECT_TRUE(contains(o.err, "FOSSSim: error: " + path + ":")) << o;
    for (const std::string& fragment : it->second) EXPECT_TRUE(contains(o.err, fragment)) << fragment << "\n" << o;
    EXPECT_EQ(o.out, "");
  }
  EXPECT_EQ(files, static_cast<int>(table.size())) << "EXPECTED names files that do not exist";
}

}  // namespace
}  // namespace fosssim::testing
