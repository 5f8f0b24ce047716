// Grading (-i) files that do not fit the scene: another scene's trajectory, a truncated file,
// trailing bytes, absurd counts. Each is reported as a file that does not fit (structural
// error, "Failed."), never graded from misread bytes. A file written by simulating the scene
// itself passes, and a copy with one position moved by 1e-6 fails, so the grader really compares.
#include "scene_text.h"
#include "trajectory_file.h"

#include "fosssim/core/simulator.h"
#include "fosssim/io/grader.h"
#include "fosssim/io/trajectory.h"

#include <sstream>

namespace fosssim::testing {
namespace {

std::string sceneOf(int particles, const char* collision) {
  std::string text = "<scene>\n<duration time=\"0.05\"/>\n<integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n";
  for (int k = 0; k < particles; ++k)
    text += "<particle m=\"1\" px=\"" + std::to_string(0.15 * k) + "\" py=\"0\" vx=\"" + std::to_string(k % 2 ? -1 : 1) +
            "\" vy=\"0\" fixed=\"0\"/>\n";
  text += "<halfplane px=\"0\" py=\"-0.05\" nx=\"0\" ny=\"1\"/>\n<simplegravity fx=\"0\" fy=\"-10\"/>\n";
  return text + "<collision type=\"" + collision + "\"/>\n</scene>\n";
}

struct Fixture {
  SceneFile file;
  std::unique_ptr<Simulator> simulator;
};

Fixture prepare(int particles, const char* collision) {
  Fixture run;
  EXPECT_TRUE(parseScene(sceneOf(particles, collision), "grade.xml", run.file).isOk());
  SimulatorOptions options;
  options.logPolynomials = true;
  EXPECT_TRUE(Simulator::create(run.file.scene, options, run.simulator).isOk());
  return run;
}

/// The scene's own trajectory (layouts without mid-step records only).
std::string writeOwn(Fixture& run, const std::string& path) {
  std::unique_ptr<TrajectoryWriter> writer;
  EXPECT_TRUE(TrajectoryWriter::open(path, run.simulator->layout(), writer).isOk());
  State state = run.file.initial;
  EXPECT_TRUE(writer->write(state, CollisionLog{}).isOk());
  for (long k = 0; k < run.file.scene.numSteps(); ++k) {
    EXPECT_TRUE(run.simulator->step(run.file.scene, state).isOk());
    EXPECT_TRUE(writer->write(state, run.simulator->log()).isOk());
  }
  EXPECT_TRUE(writer->close().isOk());
  return readFile(path);
}

struct Graded {
  GradeReport report;
  std::string text;
  bool passed;
};

Graded grade(Fixture& run, const std::string& path) {
  std::ostringstream out;
  Graded g;
  g.report = gradeTrajectory(run.file.scene, run.file.initial, *run.simulator, path, out);
  g.text = out.str();
  g.passed = g.report.passed(GradeTolerances{});
  return g;
}

void expectDoesNotFit(const Graded& g, const std::string& fragment) {
  EXPECT_FALSE(g.passed);
  EXPECT_NE(g.report.structuralError.find(fragment), std::string::npos) << g.report.structuralError;
  EXPECT_NE(g.text.find("Overall success: Failed."), std::string::npos) << g.text;
}

TEST(GradeInput, OwnTrajectoryPassesAndAMovedPositionFails) {
  TempDir dir("grade");
  for (const char* collision : {"none", "simple"}) {
    Fixture run = prepare(2, collision);
    const std::string bytes = writeOwn(run, dir.file("own.bin"));
    const Graded own = grade(run, dir.file("own.bin"));
    EXPECT_TRUE(own.passed) << own.text;
    EXPECT_EQ(own.report.stepsGraded, run.file.scene.numSteps());
    std::string moved = bytes;
    double x;
    const size_t at = moved.size() / 2 / 8 * 8;  // some double in the middle of the file
    std::memcpy(&x, &moved[at], 8);
    x += 1e-6;
    std::memcpy(&moved[at], &x, 8);
    EXPECT_FALSE(grade(run, dir.write("moved.bin", moved)).passed) << collision;
  }
}

TEST(GradeInput, TheTrajectoryOfAnotherSceneDoesNotFit) {
  TempDir dir("grade");
  for (const char* collision : {"none", "simple"}) {
    SCOPED_TRACE(collision);
    Fixture two = prepare(2, collision), three = prepare(3, collision);
    writeOwn(two, dir.file("two.bin"));
    writeOwn(three, dir.file("three.bin"));
    expectDoesNotFit(grade(three, dir.file("two.bin")), "this scene");
    expectDoesNotFit(grade(two, dir.file("three.bin")), "this scene");
  }
}

TEST(GradeInput, JunkOfTheRightSizeFailsWithoutCrashing) {
  // 6 records of 2 particles' worth of bytes: the size fits, the values do not.
  TempDir dir("grade");
  Fixture two = prepare(2, "none");
  const Graded junk = grade(two, dir.write("junk.bin", std::string(6 * 64, 'a')));
  EXPECT_FALSE(junk.passed);
  EXPECT_NE(junk.text.find("Overall success: Failed."), std::string::npos);
  // All bits set: every value is NaN, which must fail (NaN compares false with everything).
  const Graded nan = grade(two, dir.write("nan.bin", std::string(6 * 64, '\xff')));
  EXPECT_FALSE(nan.passed);
  EXPECT_NE(nan.text.find("Overall success: Failed."), std::string::npos);
}

TEST(GradeInput, TruncatedOrTrailingBytes) {
  TempDir dir("grade");
  for (const char* collision : {"none", "simple"}) {
    SCOPED_TRACE(collision);
    Fixture run = prepare(2, collision);
    const std::string bytes = writeOwn(run, dir.file("own.bin"));
    for (size_t cut : {size_t(0), size_t(1), size_t(64), bytes.size() / 2, bytes.size() - 1}) {
      SCOPED_TRACE(cut);
      expectDoesNotFit(grade(run, dir.write("cut.bin", bytes.substr(0, cut))), "");
    }
    expectDoesNotFit(grade(run, dir.write("long.bin", bytes + std::string(8, '\0'))), "");
    expectDoesNotFit(grade(run, dir.write("longer.bin", bytes + bytes)), "");
  }
}

TEST(GradeInput, AbsurdImpulseCountIsReportedNotRead) {
  TempDir dir("grade");
  Fixture run = prepare(2, "simple");
  std::string bytes = writeOwn(run, dir.file("own.bin"));
  bytes.replace(64, 4, Bytes().i32(1 << 30).data);  // record 0's impulse count
  const Graded g = grade(run, dir.write("absurd.bin", bytes));
  expectDoesNotFit(g, "impulse count 1073741824");
  EXPECT_NE(g.report.structuralError.find("record 0"), std::string::npos);
}

TEST(GradeInput, MissingFileOrDirectory) {
  TempDir dir("grade");
  Fixture run = prepare(2, "none");
  expectDoesNotFit(grade(run, dir.file("missing.bin")), "cannot open");
  expectDoesNotFit(grade(run, dir.file("")), "directory");
}

}  // namespace
}  // namespace fosssim::testing
