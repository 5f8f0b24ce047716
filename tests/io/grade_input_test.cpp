// Grading (-i) files that do not fit the scene: another scene's trajectory, a truncated file,
// trailing bytes, absurd counts, a record 0 that is not the scene's initial state. Each is
// reported as a file that does not fit (structural error, "Failed."), never graded from misread
// bytes, and no category is "passed" for steps not graded. A file written by simulating the scene
// itself passes, and a copy with one position moved by 1e-6 fails, so the grader really compares.
// Polynomial findings name their pair.
#include "scene_text.h"
#include "trajectory_file.h"

#include "fosssim/core/simulator.h"
#include "fosssim/io/grader.h"
#include "fosssim/io/trajectory.h"

#include <cmath>
#include <cstring>
#include <sstream>

namespace fosssim::testing {
namespace {

std::string sceneOf(int particles, const char* collision) {
  std::string text = "<scene>\n<duration time=\"0.05\"/>\n<integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n";
  for (int k = 0; k < particles; ++k)
    text += "<particle m=\"1\" px=\"" + std::to_string(0.15 * k) + "\" py=\"0\" vx=\"" +
            std::to_string(k % 2 ? -1 : 1) + "\" vy=\"0\" fixed=\"0\"/>\n";
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
  // Nothing read, nothing to say about categories: the caller reports the error (-i: one line).
  TempDir dir("grade");
  Fixture run = prepare(2, "none");
  for (const auto& [path, fragment] :
       {std::pair{dir.file("missing.bin"), "cannot open"}, std::pair{dir.file(""), "directory"}}) {
    const Graded g = grade(run, path);
    EXPECT_FALSE(g.passed);
    EXPECT_TRUE(g.report.unreadable);
    EXPECT_NE(g.report.structuralError.find(fragment), std::string::npos) << g.report.structuralError;
    EXPECT_EQ(g.text, "");
  }
}

// Record 0 must be the scene's initial state: the reference never looks at it, so a file that
// starts elsewhere was graded from its own state (and zeros passed).
TEST(GradeInput, RecordZeroMustBeTheScenesInitialState) {
  TempDir dir("grade");
  for (const char* collision : {"none", "simple"}) {
    SCOPED_TRACE(collision);
    Fixture run = prepare(2, collision);
    const std::string bytes = writeOwn(run, dir.file("own.bin"));
    const auto withRecordZero = [&](size_t at, double value) {
      std::string b = bytes;
      std::memcpy(&b[at], &value, 8);
      return grade(run, dir.write("r0.bin", b));
    };
    // Particle 1 starts at (0.15, 0) with velocity (-1, 0) (sceneOf).
    const Graded moved = withRecordZero(16, 0.25);
    expectDoesNotFit(moved, "record 0 is not this scene's initial state: particle 1's position is (0.25, 0) in the "
                            "file, (0.15, 0) in the scene");
    EXPECT_EQ(moved.report.stepsGraded, 0);
    const Graded nan = withRecordZero(48, std::nan(""));
    expectDoesNotFit(nan, "particle 1's velocity is (nan, 0) in the file, (-1, 0) in the scene");
    EXPECT_EQ(nan.report.structuralError.find("step"), std::string::npos) << nan.report.structuralError;
    // Within the tolerance of a single residual, record 0 is the scene's (another parser's rounding).
    EXPECT_TRUE(withRecordZero(16, 0.15 + 1e-12).passed);
    // Zeros of the right size: every particle at rest at the origin stays there.
    expectDoesNotFit(grade(run, dir.write("zeros.bin", std::string(bytes.size(), '\0'))),
                     "particle 1's position is (0, 0) in the file, (0.15, 0) in the scene");
  }
}

TEST(GradeInput, NothingGradedIsNeverPassed) {
  TempDir dir("grade");
  Fixture run = prepare(2, "simple");
  const std::string bytes = writeOwn(run, dir.file("own.bin"));
  const Graded zeros = grade(run, dir.write("zeros.bin", std::string(bytes.size(), '\0')));
  EXPECT_EQ(zeros.text.find("passed"), std::string::npos) << zeros.text;
  EXPECT_NE(zeros.text.find("Positions: residual sum 0, max 0: not graded"), std::string::npos) << zeros.text;
  EXPECT_NE(zeros.text.find("Polynomials: 0 mismatches: none in this scene's records"), std::string::npos)
      << zeros.text;
  EXPECT_EQ(zeros.text.rfind("Overall success: Failed.\n"), zeros.text.size() - 25) << zeros.text;
  const Graded own = grade(run, dir.file("own.bin"));
  EXPECT_NE(own.text.find("Impulses: 0 missed, 0 superfluous, 0 wrong normals: passed\n"), std::string::npos)
      << own.text;
}

// The polynomial log of a step holds, per detection pass, every pair in the reference's order
// with 2 polynomials per particle-particle and particle-half-plane pair and 4 per particle-edge
// pair. Checked by hand on a small scene, then against the simulator's own log: each distance
// polynomial's constant term is the pair's clearance at the start of the step (spec, section 4).
TEST(GradeInput, PolynomialsAreNamedByTheirPair) {
  SceneFile file;
  ASSERT_TRUE(parseScene("<scene><duration time=\"0.02\"/><integrator type=\"explicit-euler\" dt=\"0.01\"/>"
                         "<particle m=\"1\" px=\"0\" py=\"0.3\" vx=\"1\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
                         "<particle m=\"1\" px=\"1\" py=\"0.4\" vx=\"0\" vy=\"-1\" fixed=\"0\" radius=\"0.2\"/>"
                         "<particle m=\"1\" px=\"0.5\" py=\"1\" vx=\"0\" vy=\"-2\" fixed=\"0\" radius=\"0.05\"/>"
                         "<edge i=\"0\" j=\"1\" radius=\"0.02\"/>"
                         "<halfplane px=\"0\" py=\"-1\" nx=\"0\" ny=\"2\"/>"
                         "<collision type=\"continuous-time\"/></scene>",
                         "pairs.xml", file)
                  .isOk());
  // Per pass: particle 0: PP (0,1), (0,2), PH -> 6; particle 1: PP (1,2), PH -> 4; particle 2:
  // PE with edge 0, PH -> 6. 16 in all.
  const Scene& scene = file.scene;
  EXPECT_EQ(polynomialOwner(scene, 0, 16), "the distance polynomial of particles 0 and 1");
  EXPECT_EQ(polynomialOwner(scene, 3, 16), "the approach polynomial of particles 0 and 2");
  EXPECT_EQ(polynomialOwner(scene, 4, 16), "the distance polynomial of particle 0 and half-plane 0");
  EXPECT_EQ(polynomialOwner(scene, 6, 16), "the distance polynomial of particles 1 and 2");
  EXPECT_EQ(polynomialOwner(scene, 11, 16), "the alpha > 0 polynomial of particle 2 and edge 0");
  EXPECT_EQ(polynomialOwner(scene, 13, 16), "the approach polynomial of particle 2 and edge 0");
  EXPECT_EQ(polynomialOwner(scene, 15, 16), "the approach polynomial of particle 2 and half-plane 0");
  EXPECT_EQ(polynomialOwner(scene, 17, 32), "the approach polynomial of particles 0 and 1 (detection pass 2)");
  EXPECT_EQ(polynomialOwner(scene, 3, 17), "");  // not a whole number of passes: no guess
  EXPECT_EQ(polynomialOwner(scene, 16, 16), "");

  for (bool compat : {false, true}) {
    SCOPED_TRACE(compat ? "--compat" : "default mode");
    SimulatorOptions options;
    options.logPolynomials = true;
    options.handler.compat = compat;
    std::unique_ptr<Simulator> simulator;
    ASSERT_TRUE(Simulator::create(scene, options, simulator).isOk());
    State state = file.initial;
    const State start = state;
    ASSERT_TRUE(simulator->step(scene, state).isOk());
    const PolynomialLog& log = simulator->log().polynomials;
    ASSERT_EQ(log.size(), 16);
    const auto x = [&](int i) { return Vec2(at(start.x, i)); };
    const auto constant = [&](int k) { return log.coefficients(k)[log.length(k) - 1]; };
    const HalfPlane& h = scene.halfplanes[0];
    const Vec2 e = x(1) - x(0), w = x(2) - x(0);
    const struct {
      int k;
      double clearance;
    } distances[] = {
        {0, std::pow(0.1 + 0.2, 2) - (x(1) - x(0)).squaredNorm()},
        {2, std::pow(0.1 + 0.05, 2) - (x(2) - x(0)).squaredNorm()},
        {4, 0.01 * h.normal.squaredNorm() - std::pow((h.point - x(0)).dot(h.normal), 2)},
        {6, std::pow(0.2 + 0.05, 2) - (x(2) - x(1)).squaredNorm()},
        {8, 0.04 * h.normal.squaredNorm() - std::pow((h.point - x(1)).dot(h.normal), 2)},
        {10, e.squaredNorm() * std::pow(0.05 + 0.02, 2) - e.squaredNorm() * w.squaredNorm() + std::pow(w.dot(e), 2)},
        {14, 0.0025 * h.normal.squaredNorm() - std::pow((h.point - x(2)).dot(h.normal), 2)},
    };
    for (const auto& d : distances) {
      SCOPED_TRACE(polynomialOwner(scene, d.k, log.size()));
      ASSERT_GT(log.length(d.k), 0);
      EXPECT_NEAR(constant(d.k), d.clearance, 1e-12);
      EXPECT_EQ(polynomialOwner(scene, d.k, log.size()).rfind("the distance polynomial of ", 0), 0u);
    }
  }
}

}  // namespace
}  // namespace fosssim::testing
