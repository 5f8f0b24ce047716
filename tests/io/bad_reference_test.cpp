// Bad references and keywords: indices naming particles, edges or half-planes that do not exist,
// an edge or pair force from a particle to itself, unknown integrator and collision types (the
// message lists the valid ones), missing required elements, and unknown elements and attributes
// (a warning naming them, not an error).
#include "scene_text.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/integrator.h"

#include <algorithm>

namespace fosssim::testing {
namespace {

// The base scene has 2 particles, 1 edge and 1 half-plane.
struct IndexCase {
  std::string text;  ///< the element, inserted at kExtraLine
  const char* element;
  const char* attribute;
  const char* what;  ///< "particle 2", "edge 1", ...
};

TEST(BadReference, IndicesOutOfRangeNameTheElementAndTheCount) {
  const std::vector<IndexCase> cases = {
      {"  <edge i=\"2\" j=\"0\"/>", "edge", "i", "particle 2 does not exist (the scene has 2 particles)"},
      {"  <edge i=\"0\" j=\"7\"/>", "edge", "j", "particle 7 does not exist (the scene has 2 particles)"},
      {"  <springforce edge=\"1\" k=\"1\" l0=\"1\"/>", "springforce", "edge",
       "edge 1 does not exist (the scene has 1 edge)"},
      {"  <particlecolor i=\"2\" r=\"0\" g=\"0\" b=\"0\"/>", "particlecolor", "i", "particle 2 does not exist"},
      {"  <edgecolor i=\"1\" r=\"0\" g=\"0\" b=\"0\"/>", "edgecolor", "i", "edge 1 does not exist"},
      {"  <halfplanecolor i=\"1\" r=\"0\" g=\"0\" b=\"0\"/>", "halfplanecolor", "i", "half-plane 1 does not exist"},
      {"  <gravitationalforce i=\"0\" j=\"2\" G=\"1\"/>", "gravitationalforce", "j", "particle 2 does not exist"},
      {"  <gravitationalforce i=\"5\" j=\"1\" G=\"1\"/>", "gravitationalforce", "i", "particle 5 does not exist"},
      {"  <vortexforce i=\"3\" j=\"0\" kbs=\"1\" kvc=\"1\"/>", "vortexforce", "i", "particle 3 does not exist"},
      {"  <vortexforce i=\"0\" j=\"2\" kbs=\"1\" kvc=\"1\"/>", "vortexforce", "j", "particle 2 does not exist"},
      {"  <particlepath i=\"2\" duration=\"1\" r=\"0\" g=\"0\" b=\"0\"/>", "particlepath", "i",
       "particle 2 does not exist"},
      {"  <particlepath i=\"2000000000\" duration=\"1\" r=\"0\" g=\"0\" b=\"0\"/>", "particlepath", "i",
       "particle 2000000000"},
  };
  for (const IndexCase& c : cases) {
    SCOPED_TRACE(c.text);
    expectError(extra(c.text), {located(kExtraLine, c.element, c.attribute), c.what});
  }
}

TEST(BadReference, AnIndexIsCheckedAgainstTheWholeFile) {
  // A later element may be named (document order numbering), but not one that never comes.
  std::vector<std::string> lines = baseLines();
  lines.insert(lines.begin() + 1, "  <springforce edge=\"1\" k=\"1\" l0=\"1\"/>");  // line 2
  lines.insert(lines.end() - 1, "  <edge i=\"1\" j=\"0\"/>");
  EXPECT_EQ(loadError(join(lines)), "");
  lines.at(1) = "  <springforce edge=\"2\" k=\"1\" l0=\"1\"/>";
  expectError(join(lines), {located(2, "springforce", "edge"), "edge 2 does not exist (the scene has 2 edges)"});
}

TEST(BadReference, AnEdgeFromAParticleToItselfIsRejected) {
  expectError(replaced(6, "  <edge i=\"1\" j=\"1\"/>"), {located(6, "edge", "j"), "two different particles"});
  expectError(extra("  <gravitationalforce i=\"0\" j=\"0\" G=\"1\"/>"),
              {located(kExtraLine, "gravitationalforce", "j")});
  expectError(extra("  <vortexforce i=\"1\" j=\"1\" kbs=\"1\" kvc=\"1\"/>"), {located(kExtraLine, "vortexforce", "j")});
}

TEST(BadReference, UnknownIntegratorListsTheValidOnes) {
  const std::string message = loadError(replaced(3, "  <integrator type=\"runge-kutta\" dt=\"0.01\"/>"));
  EXPECT_NE(message.find(located(3, "integrator", "type")), std::string::npos) << message;
  EXPECT_NE(message.find("\"runge-kutta\""), std::string::npos) << message;
  // The keywords of the format (spec section 1), all of which must be offered.
  for (const char* valid : {"explicit-euler", "symplectic-euler", "forward-backward-euler", "implicit-euler",
                            "linearized-implicit-euler"})
    EXPECT_NE(message.find(valid), std::string::npos) << valid << " not listed in: " << message;
  // Keywords are case-sensitive, as in the reference.
  EXPECT_NE(loadError(replaced(3, "  <integrator type=\"Explicit-Euler\" dt=\"0.01\"/>")), "");
  EXPECT_NE(loadError(replaced(3, "  <integrator type=\"\" dt=\"0.01\"/>")), "");
}

TEST(BadReference, UnknownCollisionTypeListsTheValidOnes) {
  const std::string message = loadError(extra("  <collision type=\"magic\"/>"));
  EXPECT_NE(message.find(located(kExtraLine, "collision", "type")), std::string::npos) << message;
  EXPECT_NE(message.find("\"magic\""), std::string::npos) << message;
  for (const char* valid : {"none", "simple", "penalty"}) EXPECT_NE(message.find(valid), std::string::npos) << message;
  // Every type the simulator knows is offered, however many there are.
  for (const CollisionEntry& e : collisionTable()) EXPECT_NE(message.find(e.keyword), std::string::npos) << message;
}

TEST(BadReference, UnknownSimulationTypeIsRejected) {
  expectError(extra("  <simtype type=\"rigid-body\"/>"), {located(kExtraLine, "simtype", "type"), "particle-system"});
}

TEST(BadReference, MissingRequiredElementsAreNamed) {
  std::vector<std::string> lines = baseLines();
  lines.erase(lines.begin() + 2);  // the integrator
  expectError(join(lines), {kFile + ":", "<integrator", "required"});
  lines = baseLines();
  lines.erase(lines.begin() + 1);  // the duration
  expectError(join(lines), {kFile + ":", "<duration", "required"});
  // An ignored later copy does not make up for a missing first one; a misspelt element neither.
  expectError(replaced(2, "  <durration time=\"1\"/>"), {kFile + ":", "<duration", "required"});
  // Particles: a scene without any has nothing to simulate (and no trajectory bytes).
  lines = baseLines();
  lines.erase(lines.begin() + 3, lines.begin() + 7);
  expectError(join(lines), {kFile + ":", "no <particle>"});
}

bool hasWarning(const SceneFile& file, const std::vector<std::string>& fragments) {
  return std::any_of(file.warnings.begin(), file.warnings.end(), [&](const std::string& w) {
    return std::all_of(fragments.begin(), fragments.end(),
                       [&](const std::string& f) { return w.find(f) != std::string::npos; });
  });
}

TEST(BadReference, UnknownElementsAndAttributesAreWarningsThatNameThem) {
  SceneFile file;
  std::vector<std::string> lines = baseLines();
  lines.insert(lines.begin() + 1, "  <partcle m=\"1\"/>");                                                // 2
  lines.at(4) = "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" colour=\"red\"/>";  // 5
  lines.insert(lines.end() - 1, "  <collision type=\"simple\" COR=\"0.5\" cor=\"0.2\"/>");              // 9
  ASSERT_TRUE(parseScene(join(lines), kFile, file).isOk());
  EXPECT_TRUE(hasWarning(file, {kFile + ":2: <partcle>", "unknown element", "particle"}));
  EXPECT_TRUE(hasWarning(file, {located(5, "particle", "colour"), "unknown attribute", "radius"}));
  EXPECT_TRUE(hasWarning(file, {located(9, "collision", "cor"), "unknown attribute", "COR"}));
  EXPECT_EQ(file.warnings.size(), 3u);
  EXPECT_EQ(file.scene.numParticles(), 2);      // the unknown element was not taken for a particle
  EXPECT_EQ(file.scene.collision.cor, 0.5);     // attribute names are case-sensitive
}

TEST(BadReference, AWellFormedSceneHasNoWarnings) {
  SceneFile file;
  ASSERT_TRUE(parseScene(extra("  <collision type=\"simple\" COR=\"0.5\"/>"), kFile, file).isOk());
  EXPECT_TRUE(file.warnings.empty()) << file.warnings.front();
}

}  // namespace
}  // namespace fosssim::testing
