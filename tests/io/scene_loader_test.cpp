// Good input: defaults, the leniency the course scenes rely on, document-order numbering, "only
// the first counts" elements, comments, and the order forces are summed in. Expected values come
// from the format description (spec section 1), not from the loader.
#include "scene_text.h"

#include "fosssim/core/simulator.h"

#include <cmath>

namespace fosssim::testing {
namespace {

SceneFile load(const std::string& text) {
  SceneFile file;
  const Status s = parseScene(text, kFile, file);
  EXPECT_TRUE(s.isOk()) << s.message() << "\n" << text;
  return file;
}

void expectColor(const Rgb& c, double r, double g, double b) {
  EXPECT_EQ(c.r, r);
  EXPECT_EQ(c.g, g);
  EXPECT_EQ(c.b, b);
}

TEST(SceneLoader, TheBaseSceneAsWritten) {
  const SceneFile f = load(join(baseLines()));
  const Scene& s = f.scene;
  ASSERT_EQ(s.numParticles(), 2);
  EXPECT_EQ(s.massOf(0), 1.0);
  EXPECT_EQ(s.massOf(1), 2.0);
  EXPECT_EQ(s.mass.size(), 4);
  EXPECT_EQ(f.initial.x, (VecX(4) << 0, 0, 1, 0).finished());
  EXPECT_EQ(f.initial.v, VecX::Zero(4));
  EXPECT_EQ(s.integrator, "explicit-euler");
  EXPECT_EQ(s.dt, 0.01);
  EXPECT_EQ(s.duration, 1.0);
  EXPECT_EQ(s.numSteps(), 100);
  ASSERT_EQ(s.edges.size(), 1u);
  EXPECT_EQ(s.edges[0].i, 0);
  EXPECT_EQ(s.edges[0].j, 1);
  ASSERT_EQ(s.halfplanes.size(), 1u);
  EXPECT_EQ(s.halfplanes[0].point, Vec2(0, -1));
  EXPECT_TRUE(s.forces.empty());
  EXPECT_EQ(s.collision.type, CollisionType::None);
}

TEST(SceneLoader, Defaults) {
  const SceneFile f = load(extra("  <springforce edge=\"0\" k=\"2\" l0=\"1\"/>"));
  EXPECT_EQ(f.scene.radius[0], 0.1);         // particle radius
  EXPECT_EQ(f.scene.edges[0].radius, 0.015);  // edge radius
  EXPECT_FALSE(f.scene.isFixed(0));
  EXPECT_EQ(f.look.maxSimFreq, 100);
  EXPECT_FALSE(f.look.viewport.has_value());
  expectColor(f.look.background, 1, 1, 1);
  expectColor(f.look.particleColors[1], 0.650980392156863, 0.294117647058824, 0);
  expectColor(f.look.edgeColors[0], 0, 0.388235294117647, 0.388235294117647);
  expectColor(f.look.halfplaneColors[0], 0, 0, 0);
  EXPECT_TRUE(f.look.paths.empty());
  EXPECT_EQ(f.description, "");
  // A spring without b is undamped: its force along the edge is k (l - l0) only, whatever the velocity.
  ASSERT_EQ(f.scene.forces.size(), 1u);
  VecX x(4), v(4), grad = VecX::Zero(4);
  x << 0, 0, 1.5, 0;
  v << 0, 0, 3, 0;
  f.scene.forces[0]->addGradient(f.scene, x, v, grad);
  EXPECT_NEAR(grad[2], 2 * 0.5, 1e-15);
}

TEST(SceneLoader, CollisionDefaults) {
  const SceneFile simple = load(extra("  <collision type=\"simple\"/>"));
  EXPECT_EQ(simple.scene.collision.cor, 1.0);
  EXPECT_EQ(simple.scene.collision.maxIterations, 10);
  EXPECT_TRUE(simple.scene.forces.empty());  // no penalty force for simple

  const SceneFile penalty = load(extra("  <collision type=\"penalty\"/>"));
  EXPECT_EQ(penalty.scene.collision.penaltyK, 100.0);
  EXPECT_EQ(penalty.scene.collision.penaltyThickness, 0.01);
  ASSERT_EQ(penalty.scene.forces.size(), 1u);

  const SceneFile hybrid = load(extra("  <collision type=\"hybrid\" maxiters=\"3.7\"/>"));
  EXPECT_EQ(hybrid.scene.collision.penaltyK, 10.0);
  EXPECT_EQ(hybrid.scene.collision.penaltyThickness, 0.1);
  EXPECT_EQ(hybrid.scene.collision.maxIterations, 3);  // read as a number and truncated
  EXPECT_EQ(hybrid.scene.forces.size(), 1u);

  const SceneFile zeroK = load(extra("  <collision type=\"penalty\" k=\"0\" thickness=\"0.5\" COR=\"0\"/>"));
  EXPECT_EQ(zeroK.scene.collision.penaltyK, 0.0);
  EXPECT_EQ(zeroK.scene.collision.penaltyThickness, 0.5);
  EXPECT_EQ(zeroK.scene.collision.cor, 0.0);
  EXPECT_EQ(zeroK.scene.forces.size(), 1u);  // k="0" still adds the force
}

// The default mode's failsafe (spec: <collision failsafe="projection|rigid">, projection when
// absent); an unknown keyword is an error that lists the valid ones.
TEST(SceneLoader, CollisionFailsafe) {
  EXPECT_EQ(load(extra("  <collision type=\"hybrid\"/>")).scene.collision.failsafe, Failsafe::Projection);
  EXPECT_EQ(load(extra("  <collision type=\"hybrid\" failsafe=\"rigid\"/>")).scene.collision.failsafe, Failsafe::Rigid);
  EXPECT_EQ(load(extra("  <collision type=\"continuous-time\" failsafe=\"projection\"/>")).scene.collision.failsafe,
            Failsafe::Projection);
  SceneFile bad;
  const Status s = parseScene(extra("  <collision type=\"hybrid\" failsafe=\"frozen\"/>"), kFile, bad);
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("projection, rigid"), std::string::npos) << s.message();
}

TEST(SceneLoader, LenientAttributeSyntaxOfTheCourseScenes) {
  // No whitespace between attributes, spaces around '=', leading and trailing spaces in numbers.
  const SceneFile f = load(
      replaced(4, "  <particle m = \"3\" px=\" 1.0\" py=\"2.5 \"vx=\"0\"vy=\"-1\" fixed= \"1\" radius =\"0.2\"/>"));
  EXPECT_EQ(f.scene.massOf(0), 3.0);
  EXPECT_EQ(f.initial.x[0], 1.0);
  EXPECT_EQ(f.initial.x[1], 2.5);
  EXPECT_EQ(f.initial.v[1], -1.0);
  EXPECT_TRUE(f.scene.isFixed(0));
  EXPECT_EQ(f.scene.radius[0], 0.2);
  // Nothing about the syntax; only that this fixed particle moves (AMovingFixedParticleIsWarnedAbout).
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("a fixed particle with a velocity"), std::string::npos) << f.warnings[0];
}

TEST(SceneLoader, NumberSpellings) {
  const SceneFile f = load(replaced(
      4, "  <particle m=\"1E0\" px=\"-.5\" py=\"+2\" vx=\"1e-3\" vy=\"1e-400\" fixed=\"0.0\" radius=\"5.\"/>"));
  EXPECT_EQ(f.initial.x[0], -0.5);
  EXPECT_EQ(f.initial.x[1], 2.0);
  EXPECT_EQ(f.initial.v[0], 1e-3);
  EXPECT_EQ(f.initial.v[1], 0.0);  // underflows to zero: a fine value, not an error
  EXPECT_EQ(f.scene.radius[0], 5.0);
  EXPECT_EQ(load(replaced(3, "  <integrator type=\"explicit-euler\" dt=\"1.0e-2\"/>")).scene.dt, 0.01);
}

TEST(SceneLoader, ElementsAreNumberedInDocumentOrder) {
  // The spring and the colours come before the edge and particles they name.
  const SceneFile f = load(join({"<scene>", "  <springforce edge=\"1\" k=\"1\" l0=\"0\"/>",
                                 "  <particlecolor i=\"2\" r=\"0.25\" g=\"0.5\" b=\"1\"/>",
                                 "  <edgecolor i=\"1\" r=\"1\" g=\"0\" b=\"0\"/>", "  <duration time=\"1\"/>",
                                 "  <integrator type=\"symplectic-euler\" dt=\"0.1\"/>",
                                 "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",
                                 "  <edge i=\"0\" j=\"1\"/>",
                                 "  <particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",
                                 "  <!-- a comment between elements of one kind does not count -->",
                                 "  <particle m=\"1\" px=\"0\" py=\"3\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",
                                 "  <edge i=\"2\" j=\"1\"/>", "</scene>"}));
  ASSERT_EQ(f.scene.numParticles(), 3);
  expectColor(f.look.particleColors[2], 0.25, 0.5, 1);
  expectColor(f.look.edgeColors[1], 1, 0, 0);
  expectColor(f.look.edgeColors[0], 0, 0.388235294117647, 0.388235294117647);
  // The spring joins edge 1's particles (2 and 1) with rest length 0: pulls particle 1 towards 2.
  ASSERT_EQ(f.scene.forces.size(), 1u);
  VecX grad = VecX::Zero(6);
  f.scene.forces[0]->addGradient(f.scene, f.initial.x, f.initial.v, grad);
  EXPECT_EQ(grad.segment<2>(0), Vec2::Zero());
  // Rest length 0, k = 1: F on particle 1 (at (1,0)) is x2 - x1 = (-1, 3); the gradient is -F.
  EXPECT_NEAR(grad[2], 1, 1e-14);
  EXPECT_NEAR(grad[3], -3, 1e-14);
  EXPECT_NEAR(grad[4], -1, 1e-14);
  EXPECT_NEAR(grad[5], 3, 1e-14);
}

TEST(SceneLoader, OnlyTheFirstOfSomeElementsCounts) {
  const SceneFile f =
      load(join({"<scene>", "  <duration time=\"1\"/>", "  <integrator type=\"explicit-euler\" dt=\"0.01\"/>",
                 "  <viewport cx=\"1\" cy=\"2\" size=\"3\"/>", "  <collision type=\"simple\" COR=\"0.25\"/>",
                 "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>", "  <duration time=\"5\"/>",
                 "  <integrator type=\"implicit-euler\" dt=\"0.5\"/>", "  <viewport cx=\"9\" cy=\"9\" size=\"9\"/>",
                 "  <collision type=\"penalty\"/>", "</scene>"}));
  EXPECT_EQ(f.scene.duration, 1.0);
  EXPECT_EQ(f.scene.integrator, "explicit-euler");
  EXPECT_EQ(f.scene.dt, 0.01);
  ASSERT_TRUE(f.look.viewport.has_value());
  EXPECT_EQ(f.look.viewport->size, 3.0);
  EXPECT_EQ(f.scene.collision.type, CollisionType::Simple);
  EXPECT_EQ(f.scene.collision.cor, 0.25);
  EXPECT_TRUE(f.scene.forces.empty());  // the ignored penalty collision adds no force
  ASSERT_EQ(f.warnings.size(), 4u);
  const char* expected[] = {":7: <duration>", ":8: <integrator>", ":9: <viewport>", ":10: <collision>"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NE(f.warnings[k].find(kFile + expected[k]), std::string::npos) << f.warnings[k];
    EXPECT_NE(f.warnings[k].find("only the first"), std::string::npos) << f.warnings[k];
  }
  // Ignored copies are not checked either (the reference never reads them).
  EXPECT_TRUE(parseScene(extra("  <duration time=\"oops\"/>"), kFile, *std::make_unique<SceneFile>()).isOk());
}

TEST(SceneLoader, CommentsAroundParticles) {
  const SceneFile f = load(join({"<!-- a scene -->", "<scene>", "  <duration time=\"1\"/>",
                                 "  <integrator type=\"explicit-euler\" dt=\"0.01\"/>",
                                 "  <!--<particle m=\"1\" px=\"5\" py=\"5\" vx=\"0\" vy=\"0\" fixed=\"0\"/>-->",
                                 "  <particle m=\"1\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/> <!-- first -->",
                                 "  <!--", "  <particle m=\"1\" px=\"6\" py=\"6\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",
                                 "  -->", "  <particle m=\"1\" px=\"2\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",
                                 "  <edge i=\"0\" j=\"1\"/>", "</scene>", "<!-- trailing -->"}));
  ASSERT_EQ(f.scene.numParticles(), 2);
  EXPECT_EQ(f.initial.x, (VecX(4) << 1, 0, 2, 0).finished());
}

TEST(SceneLoader, ForcesAreSummedInTheReferenceOrder) {
  // Document order is mixed; the sum order is springs, simple gravity, gravitational, constant,
  // drag, vortex (each in document order), then the collision penalty (spec section 1; replaying
  // the course's penalty scenes bit for bit confirms gravity is summed before the penalty).
  const SceneFile f = load(extra("<collision type=\"penalty\"/><vortexforce i=\"0\" j=\"1\" kbs=\"1\" kvc=\"1\"/>"
                                 "<dragdamping b=\"1\"/><constantforce fx=\"1\" fy=\"0\"/>"
                                 "<gravitationalforce i=\"0\" j=\"1\" G=\"1\"/><simplegravity fx=\"0\" fy=\"-1\"/>"
                                 "<springforce edge=\"0\" k=\"1\" l0=\"1\"/><simplegravity fx=\"0\" fy=\"-2\"/>"));
  const std::vector<std::string> order = {"springforce", "simplegravity", "simplegravity", "gravitationalforce",
                                          "constantforce", "dragdamping", "vortexforce"};
  ASSERT_EQ(f.scene.forces.size(), order.size() + 1);
  std::vector<const Force*> others;
  int penalties = 0;
  for (const auto& force : f.scene.forces) {
    if (std::string(force->keyword()).find("penalty") != std::string::npos) ++penalties;
    else others.push_back(force.get());
  }
  EXPECT_EQ(penalties, 1);
  EXPECT_NE(std::string(f.scene.forces.back()->keyword()).find("penalty"), std::string::npos);
  ASSERT_EQ(others.size(), order.size());
  for (size_t k = 0; k < order.size(); ++k) EXPECT_EQ(others[k]->keyword(), order[k]) << k;
  // The two simple gravities keep their document order (fy = -1 first).
  VecX grad = VecX::Zero(4);
  others[1]->addGradient(f.scene, f.initial.x, f.initial.v, grad);
  EXPECT_EQ(grad[1], 1.0);  // -F_y = -m g_y = 1 for particle 0 (m = 1)
}

// A fixed particle given a velocity moves at it in the course simulator (and --compat), but the
// default mode's time-ordered handling refuses it at run time, where the line is not known: the
// loader warns at the element, naming the first non-zero component. A fixed particle at rest,
// or a moving free one, draws no warning.
TEST(SceneLoader, AMovingFixedParticleIsWarnedAbout) {
  const SceneFile moving = load(replaced(5, "  <particle m=\"2\" px=\"1\" py=\"0\" vx=\"0\" vy=\"-3\" fixed=\"1\"/>"));
  ASSERT_EQ(moving.warnings.size(), 1u);
  EXPECT_NE(moving.warnings[0].find(located(5, "particle", "vy") + ": a fixed particle with a velocity moves at it"),
            std::string::npos)
      << moving.warnings[0];
  EXPECT_NE(moving.warnings[0].find("--compat"), std::string::npos) << moving.warnings[0];
  EXPECT_TRUE(
      load(replaced(5, "  <particle m=\"2\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"1\"/>")).warnings.empty());
  EXPECT_TRUE(
      load(replaced(5, "  <particle m=\"2\" px=\"1\" py=\"0\" vx=\"5\" vy=\"0\" fixed=\"0\"/>")).warnings.empty());
}

TEST(SceneLoader, EverythingElse) {
  const SceneFile f =
      load(extra("<description text=\"A &amp; B\"/><scenetag tag=\"t\"/><simtype type=\"particle-system\"/>"
                 "<maxsimfreq max=\"250\"/><backgroundcolor r=\"0\" g=\"0.5\" b=\"1\"/>"
                 "<particlepath i=\"1\" duration=\"0.5\" r=\"1\" g=\"1\" b=\"0\"/>"));
  EXPECT_EQ(f.description, "A & B");
  EXPECT_EQ(f.tag, "t");
  EXPECT_EQ(f.look.maxSimFreq, 250);
  expectColor(f.look.background, 0, 0.5, 1);
  ASSERT_EQ(f.look.paths.size(), 1u);
  EXPECT_EQ(f.look.paths[0].particle, 1);
  EXPECT_EQ(f.look.paths[0].duration, 0.5);
  // The half-plane normal is kept unnormalised; duration 0 means no steps.
  const SceneFile h = load(replaced(7, "  <halfplane px=\"1\" py=\"2\" nx=\"3\" ny=\"4\"/>"));
  EXPECT_EQ(h.scene.halfplanes[0].normal, Vec2(3, 4));
  EXPECT_EQ(load(replaced(2, "  <duration time=\"0\"/>")).scene.numSteps(), 0);
  EXPECT_EQ(load(replaced(2, "  <duration time=\"0.105\"/>")).scene.numSteps(), 11);  // ceil(10.5)
}

/// The state after running `file` to its end (simple collisions: the contact uses |n|).
State runToEnd(const SceneFile& file) {
  std::unique_ptr<Simulator> simulator;
  EXPECT_TRUE(Simulator::create(file.scene, SimulatorOptions{}, simulator).isOk());
  State state = file.initial;
  for (long k = 0; k < file.scene.numSteps(); ++k) EXPECT_TRUE(simulator->step(file.scene, state).isOk()) << k;
  return state;
}

// "need not be a unit vector; not zero" (the format's words): the core takes |n| as
// sqrt(nx^2 + ny^2), whose square overflowed beyond about 1e154 (the ball fell through the floor)
// and underflowed below about 1e-154 (refused as "zero"). Any length must give the same wall.
TEST(SceneLoader, AHalfPlaneNormalOfAnyLengthIsTheSameWall) {
  const auto ball = [](const std::string& nx, const std::string& ny) {
    return load("<scene><duration time=\"1\"/><integrator type=\"symplectic-euler\" dt=\"0.01\"/>"
                "<particle m=\"1\" px=\"0\" py=\"0.5\" vx=\"0.3\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>"
                "<simplegravity fx=\"0\" fy=\"-9.81\"/><collision type=\"simple\"/>"
                "<halfplane px=\"0\" py=\"0\" nx=\"" + nx + "\" ny=\"" + ny + "\"/></scene>");
  };
  const State unit = runToEnd(ball("0", "1"));
  ASSERT_GT(unit.x[1], 0.0);  // it bounced: the floor held
  for (const char* length : {"1e155", "1e200", "1e308", "1e-155", "1e-170", "4e-320"}) {
    SCOPED_TRACE(length);
    const SceneFile f = ball("0", length);
    const Vec2 n = f.scene.halfplanes.at(0).normal;
    EXPECT_TRUE(std::isfinite(n.norm()) && n.norm() > 0) << n.transpose();
    EXPECT_EQ(n.x(), 0.0);
    EXPECT_EQ(runToEnd(f).x, unit.x);
  }
  // A slanted normal keeps its direction exactly (scaling by a power of two is exact).
  const Vec2 slanted = ball("3e-200", "-4e-200").scene.halfplanes.at(0).normal;
  EXPECT_NEAR(slanted.normalized().x(), 0.6, 1e-15);
  EXPECT_NEAR(slanted.normalized().y(), -0.8, 1e-15);
}

}  // namespace
}  // namespace fosssim::testing
