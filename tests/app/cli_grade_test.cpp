// Grading through the command line (-i): files are made by FOSSSim -o in a temporary folder, then
// zeroed, corrupted, cut short or graded against another scene or in the other mode. A grade must
// never pass a file that does not start from the scene, never call a category "passed" when nothing
// was graded, and a failed grade leads with where the run first diverged (or why the file does not
// fit), then the mode hint, then the details.
#include "support/temp_dir_test.h"
#include "run_fosssim.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

/// Index of the first line starting with `prefix`, or -1.
long lineStarting(const std::vector<std::string>& ls, const std::string& prefix) {
  for (size_t k = 0; k < ls.size(); ++k)
    if (startsWith(ls[k], prefix)) return static_cast<long>(k);
  return -1;
}

double getDouble(const std::string& bytes, size_t at) {
  double v;
  std::memcpy(&v, &bytes[at], 8);
  return v;
}
void setDouble(std::string& bytes, size_t at, double v) { std::memcpy(&bytes[at], &v, 8); }

class CliGrade : public TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(path(name), std::ios::binary) << bytes;
    return path(name);
  }
  /// `n` particles in a row, no collision handling, 10 steps: records of 32 n bytes. Particle k
  /// starts at (0.5 k + shift, 0.25) with velocity (1, -1).
  std::string row(const std::string& name, int n, double shift = 0) const {
    std::string text = "<scene><duration time=\"0.1\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>";
    for (int k = 0; k < n; ++k) {
      std::ostringstream p;
      p << "<particle m=\"1\" px=\"" << 0.5 * k + shift << "\" py=\"0.25\" vx=\"1\" vy=\"-1\" fixed=\"0\"/>";
      text += p.str();
    }
    return write(name, text + "</scene>\n");
  }
  /// Continuous-time: a ball falls onto a turning edge. The modes log the edge's approach quintic
  /// differently, so a file made in one fails in the other. 20 steps, two records each.
  std::string edgeScene(const std::string& name) const {
    return write(name,
                 "<scene><duration time=\"0.2\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>"
                 "<collision type=\"continuous-time\" COR=\"1\"/>"
                 "<particle m=\"1\" px=\"-0.5\" py=\"0\" vx=\"0\" vy=\"1\" fixed=\"0\" radius=\"0.05\"/>"
                 "<particle m=\"1\" px=\"0.5\" py=\"0\" vx=\"0\" vy=\"-1\" fixed=\"0\" radius=\"0.05\"/>"
                 "<particle m=\"1\" px=\"0.2\" py=\"0.5\" vx=\"0\" vy=\"-3\" fixed=\"0\" radius=\"0.05\"/>"
                 "<edge i=\"0\" j=\"1\" radius=\"0.02\"/></scene>\n");
  }
  /// FOSSSim -o; the file's bytes.
  std::string make(const std::string& scene, const std::string& out, bool compat = false) const {
    std::vector<std::string> args = {"-s", scene, "-d", "0", "-q", "-o", path(out)};
    if (compat) args.insert(args.begin(), "--compat");
    const Outcome o = runFosssim(args);
    EXPECT_TRUE(exitedWith(o, 0)) << o;
    return slurp(path(out));
  }
  Outcome grade(const std::string& scene, const std::string& file, bool compat = false) const {
    std::vector<std::string> args = {"-s", scene, "-d", "0", "-q", "-i", file};
    if (compat) args.insert(args.begin(), "--compat");
    return runFosssim(args);
  }
};

/// A failed grade: exit 1, the summary first, the reference's verdict last.
void expectFailedGrade(const Outcome& o, const std::string& firstLine) {
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  const std::vector<std::string> ls = lines(o.out);
  ASSERT_FALSE(ls.empty()) << o;
  EXPECT_TRUE(startsWith(ls.front(), firstLine)) << "first line should start with \"" << firstLine << "\"\n" << o;
  EXPECT_EQ(ls.back(), "Overall success: Failed.") << o;
}

// Issue 12's false pass: 71,556 zero bytes (every record of the billiards example, all zero)
// passed, because every step restarted from the file's state and balls at rest stay at rest.
TEST_F(CliGrade, ZerosOfTheRightSizeFailOnRecordZero) {
  const std::string billiards = std::string(FOSSSIM_SOURCE_DIR) + "/assets/examples/billiards.xml";
  // 200 steps + record 0, each 11 particles (32 bytes each) and an impulse count.
  ASSERT_EQ(201 * (11 * 32 + 4), 71556);
  const Outcome o = grade(billiards, write("zeros.bin", std::string(71556, '\0')));
  // The scene's first ball is at (-1.5, 0.03) (billiards.xml).
  expectFailedGrade(o, "Failed: record 0 is not this scene's initial state: particle 0's position is (0, 0) in the "
                       "file, (-1.5, 0.03) in the scene");
  EXPECT_TRUE(contains(o.out, "Steps graded: 0 of 200")) << o;
  EXPECT_FALSE(contains(o.out, "passed")) << o;  // nothing was graded
  EXPECT_TRUE(contains(o.out, "\nPositions: residual sum 0, max 0: not graded\n")) << o;
  EXPECT_TRUE(contains(o.out, "\nImpulses: 0 missed, 0 superfluous, 0 wrong normals: not graded\n")) << o;
}

TEST_F(CliGrade, ARecordZeroOffTheSceneFailsEvenWhenEveryStepFollowsIt) {
  // The file's own steps are consistent (it is another scene's run): only record 0 tells.
  const std::string here = row("here.xml", 3), there = row("there.xml", 3, 0.125);
  make(there, "there.bin");
  const Outcome o = grade(here, path("there.bin"));
  expectFailedGrade(o, "Failed: record 0 is not this scene's initial state: particle 0's position is (0.125, 0.25) "
                       "in the file, (0, 0.25) in the scene");
  EXPECT_TRUE(contains(o.out, "is it the trajectory of this scene?")) << o;
  EXPECT_FALSE(contains(o.out, "grading from the file's state")) << o;
  // Continuous-time files of another particle count: record 0 is misread, and said to be so.
  const std::string edge = edgeScene("edge.xml");
  make(edge, "edge.bin");
  const Outcome other = grade(row("two.xml", 2), path("edge.bin"));
  expectFailedGrade(other, "Failed: record 0 is not this scene's initial state");
}

TEST_F(CliGrade, ANanInRecordZeroIsBlamedOnRecordZero) {
  const std::string s = row("s.xml", 2);
  std::string bytes = make(s, "own.bin");
  setDouble(bytes, 8 * 3, std::nan(""));  // particle 1's y in record 0
  const Outcome o = grade(s, write("nan.bin", bytes));
  expectFailedGrade(o, "Failed: record 0 is not this scene's initial state: particle 1's position is (0.5, nan)");
  EXPECT_FALSE(contains(o.out + o.err, "step 1")) << o;
  EXPECT_FALSE(contains(o.out, "passed")) << o;
}

TEST_F(CliGrade, ANanInALaterRecordNamesThatRecord) {
  const std::string s = row("s.xml", 2);
  std::string bytes = make(s, "own.bin");
  setDouble(bytes, 3 * 64 + 32, std::nan(""));  // record 3: particle 0's velocity x
  const Outcome o = grade(s, write("nan3.bin", bytes));
  expectFailedGrade(o, "Failed: the run first diverges from the file in step 3 of 10");
  EXPECT_TRUE(contains(o.out, "record 3 (the end-of-step record of step 3) holds a non-finite number, particle 0's "
                              "velocity (nan, -1)")) << o;
  EXPECT_FALSE(contains(o.out, "step 4")) << o;  // no step starts from it
  EXPECT_TRUE(contains(o.out, "Steps graded: 3 of 10")) << o;
  EXPECT_TRUE(contains(o.out, "Positions: residual sum 0, max 0: passed in the 3 of 10 steps graded")) << o;
}

TEST_F(CliGrade, AFailedGradeLeadsWithWhereTheRunDiverged) {
  const std::string s = row("s.xml", 3);
  std::string bytes = make(s, "own.bin");
  ASSERT_EQ(bytes.size(), 11u * 96);
  setDouble(bytes, 4 * 96 + 2 * 16, getDouble(bytes, 4 * 96 + 2 * 16) + 1e-6);  // record 4, particle 2's x
  const Outcome o = grade(s, write("moved.bin", bytes));
  expectFailedGrade(o, "Failed: the run first diverges from the file in step 4 of 10 (t = 0.04, end-of-step record 4): "
                       "positions: particle 2 differs by ");
  const std::vector<std::string> ls = lines(o.out);
  // Then the details, then the categories: the position moved in record 4 fails step 4 and, as
  // step 5 starts from it, step 5.
  const long findings = lineStarting(ls, "Findings: 2 in 2 steps (positions 2):");
  const long graded = lineStarting(ls, "Steps graded: 10 of 10");
  EXPECT_EQ(findings, 1) << o;
  EXPECT_TRUE(startsWith(ls.at(2), "  step 4, end-of-step record 4: positions: particle 2 differs by ")) << o;
  EXPECT_TRUE(startsWith(ls.at(3), "  step 5, end-of-step record 5: positions: particle 2 differs by ")) << o;
  EXPECT_EQ(graded, 4) << o;
  EXPECT_TRUE(contains(o.out, "Positions: residual sum")) << o;
  EXPECT_TRUE(contains(o.out, ": FAILED\nVelocities:")) << o;
  EXPECT_FALSE(contains(o.out, "Hint:")) << o;  // no mode explains a moved position
}

TEST_F(CliGrade, DetailsAreCappedWithACount) {
  const std::string s = row("s.xml", 30);
  std::string bytes = make(s, "own.bin");
  for (int i = 0; i < 30; ++i) setDouble(bytes, 2 * 960 + 16 * i, getDouble(bytes, 2 * 960 + 16 * i) + 1e-6);
  const Outcome o = grade(s, write("moved.bin", bytes));
  expectFailedGrade(o, "Failed: the run first diverges from the file in step 2 of 10");
  const std::vector<std::string> ls = lines(o.out);
  long shown = 0, total = -1, more = -1;
  for (const std::string& l : ls) {
    shown += startsWith(l, "  step ");
    std::sscanf(l.c_str(), "Findings: %ld in", &total);
    std::sscanf(l.c_str(), "  (%ld more not shown)", &more);
  }
  EXPECT_EQ(shown, 20) << o;
  EXPECT_GE(total, 60) << o;  // 30 particles in step 2 and again in step 3
  EXPECT_EQ(more, total - shown) << o;
}

TEST_F(CliGrade, AFileOfTheOtherModeGetsAHint) {
  const std::string s = edgeScene("edge.xml");
  make(s, "default.bin");
  make(s, "compat.bin", true);
  for (bool compat : {false, true}) {
    SCOPED_TRACE(compat ? "made with --compat" : "made in the default mode");
    const std::string file = path(compat ? "compat.bin" : "default.bin");
    const Outcome right = grade(s, file, compat);
    EXPECT_TRUE(exitedWith(right, 0)) << right;
    EXPECT_FALSE(contains(right.out, "Hint:")) << right;
    const Outcome wrong = grade(s, file, !compat);
    expectFailedGrade(wrong, "Failed: the run first diverges from the file in step ");
    const std::vector<std::string> ls = lines(wrong.out);
    const long hint = lineStarting(ls, compat ? "Hint: this file looks made with --compat: grade with --compat"
                                              : "Hint: this file looks made without --compat (the default mode): "
                                                "grade without --compat");
    EXPECT_EQ(hint, 1) << wrong;  // right after the summary, before the details
    EXPECT_LT(hint, lineStarting(ls, "Findings: ")) << wrong;
  }
  // A file that fails in both modes gets no hint.
  // Record 0 holds the state (96 bytes) and two empty counts; record 1 (step 1's mid-step record)
  // starts with particle 0's x.
  std::string bytes = slurp(path("default.bin"));
  setDouble(bytes, 104, getDouble(bytes, 104) + 1e-3);
  const Outcome both = grade(s, write("broken.bin", bytes), true);
  expectFailedGrade(both, "Failed: ");
  EXPECT_FALSE(contains(both.out, "Hint:")) << both;
}

// A file written with -o --compact has the impulses but not the polynomial log that grading
// compares: it does not fit, and the grade says why and what to do.
TEST_F(CliGrade, ACompactFileGetsAHint) {
  const std::string s = edgeScene("edge.xml");
  const Outcome made = runFosssim({"-s", s, "-d", "0", "-q", "-o", path("compact.bin"), "--compact"});
  ASSERT_TRUE(exitedWith(made, 0)) << made;
  const Outcome o = grade(s, path("compact.bin"));
  expectFailedGrade(o, "Failed: ");
  EXPECT_EQ(lineStarting(lines(o.out), "Hint: this file looks written with -o --compact"), 1) << o;
  // The hint asks that the file read to its end as the compact records of this scene: the full
  // file cut short, or a compact file with a record missing, gets none.
  const std::string compact = slurp(path("compact.bin"));
  const Outcome shortened = grade(s, write("short.bin", compact.substr(0, compact.size() - 104)));
  expectFailedGrade(shortened, "Failed: ");
  EXPECT_FALSE(contains(shortened.out, "Hint:")) << shortened;
  const std::string full = make(s, "full.bin");
  const Outcome cut = grade(s, write("cut.bin", full.substr(0, full.size() - 5)));
  expectFailedGrade(cut, "Failed: ");
  EXPECT_FALSE(contains(cut.out, "Hint:")) << cut;
}

// Read as full records, a compact file's numbers are no states: stepping from them failed with an
// "energy blow-up ... try a smaller time step" line before the hint, sending the user after the
// scene instead of the file (seesaw.xml's compact file). The hint alone says what to do.
TEST_F(CliGrade, ACompactFileIsNotBlamedOnTheScene) {
  const std::string seesaw = std::string(FOSSSIM_SOURCE_DIR) + "/assets/t2m2/HolisticTests/seesaw.xml";
  ASSERT_TRUE(exitedWith(runFosssim({"-s", seesaw, "-d", "0", "-q", "-o", path("c.bin"), "--compact"}), 0));
  const Outcome o = grade(seesaw, path("c.bin"));
  expectFailedGrade(o, "Failed: ");
  EXPECT_TRUE(contains(o.out, "Hint: this file looks written with -o --compact")) << o;
  EXPECT_TRUE(contains(o.out, "the file does not read as this scene's full records")) << o;
  EXPECT_FALSE(contains(o.out, "energy blow-up")) << o;
  EXPECT_FALSE(contains(o.out, "smaller time step")) << o;
}

// A device has no size to read records against: /dev/zero was graded as an empty file.
TEST_F(CliGrade, ADeviceIsNotATrajectoryFile) {
  const Outcome o = grade(row("s.xml", 2), "/dev/zero");
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_EQ(o.out, "") << o;
  EXPECT_TRUE(contains(o.err, "/dev/zero: cannot read the trajectory file (it is a device, not a file")) << o;
}

// The scene given to -i as well (a slip of the shell's history) was read as records: a "Failed"
// grade of numbers made of XML text. It is one error naming both options, and no verdicts.
TEST_F(CliGrade, TheSceneItselfIsNoTrajectoryFile) {
  const std::string scene = row("s.xml", 2);
  fs::create_symlink(scene, path("s-link.bin"));
  for (const std::string& graded : {scene, path("s-link.bin")}) {
    const Outcome o = grade(scene, graded);
    EXPECT_TRUE(exitedWith(o, 1)) << o;
    EXPECT_EQ(o.out, "") << o;
    EXPECT_TRUE(contains(o.err, "-i \"" + graded + "\" is the scene file given to -s")) << o;
  }
}

TEST_F(CliGrade, AMissingFileIsOneErrorAndNoVerdicts) {
  const Outcome o = grade(row("s.xml", 2), path("missing.bin"));
  EXPECT_TRUE(exitedWith(o, 1)) << o;
  EXPECT_EQ(o.out, "") << o;  // no category lines, no verdict on nothing
  EXPECT_EQ(lines(o.err).size(), 1u) << o;
  EXPECT_TRUE(contains(o.err, path("missing.bin") + ": cannot open the trajectory file")) << o;
}

TEST_F(CliGrade, ATruncatedFileEndsEarly) {
  // Cut inside the last polynomial of the last record (record 40: 20 steps of two records).
  const std::string s = edgeScene("edge.xml");
  const std::string bytes = make(s, "own.bin");
  const std::string cut = bytes.substr(0, bytes.size() - 5);
  const Outcome o = grade(s, write("cut.bin", cut));
  expectFailedGrade(o, "Failed: " + path("cut.bin") + ": the file ends early at record 40 (byte ");
  EXPECT_TRUE(contains(o.out, " of " + std::to_string(cut.size()) + "): polynomial ")) << o;
  EXPECT_FALSE(contains(o.out, "impossible")) << o;
  EXPECT_TRUE(contains(o.out, "Steps graded: 19 of 20")) << o;
  // Cut between records: the first missing record is named.
  const std::string r = row("r.xml", 2);
  const std::string plain = make(r, "plain.bin").substr(0, 5 * 64);
  const Outcome p = grade(r, write("five.bin", plain));
  expectFailedGrade(p, "Failed: the file ends early at record 5 (byte 320 of 320): the end-of-step record of step 5 "
                       "is missing");
  EXPECT_TRUE(contains(p.out, "Velocities: residual sum 0, max 0: passed in the 4 of 10 steps graded")) << p;
}

}  // namespace
}  // namespace fosssim::testing
