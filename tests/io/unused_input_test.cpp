// Everything in a scene file that the loader does not use is reported: elements nested
// inside elements, text, CDATA, declarations, attributes on <scene>, a NUL byte; misspellings get
// "did you mean"; one pass reports every error, in line order; floods are counted, not printed.
#include "scene_text.h"

#include "fosssim/io/spelling.h"

#include <algorithm>

namespace fosssim::testing {
namespace {

/// The one warning of `text`, which must load.
std::string onlyWarning(const std::string& text) {
  const SceneFile file = loaded(text);
  EXPECT_EQ(file.warningCount, 1) << text;
  return file.warnings.empty() ? "" : file.warnings.front();
}

TEST(UnusedInput, ElementsInsideElementsAreReported) {
  // A spring nested in its edge used to vanish: the scene ran without it.
  std::vector<std::string> lines = baseLines();
  lines.at(5) = "  <edge i=\"0\" j=\"1\">";
  lines.insert(lines.begin() + 6, {"    <springforce edge=\"0\" k=\"1\" l0=\"1\"/>", "  </edge>"});
  const SceneFile file = loaded(join(lines));
  EXPECT_TRUE(file.scene.forces.empty());
  ASSERT_EQ(file.warningCount, 1);
  expectContains(file.warnings.front(), {kFile + ":7: <springforce> inside <edge> ignored"});
  // Text inside a known element, too.
  expectContains(onlyWarning(replaced(7, "  <halfplane px=\"0\" py=\"-1\" nx=\"0\" ny=\"1\">floor</halfplane>")),
                 {kFile + ":7: text \"floor\" inside <halfplane> ignored"});
}

// The format's elements inside an unknown one: the warning named only <forces>, and the gravity
// in it was dropped without a word about it.
TEST(UnusedInput, ElementsInsideAnUnknownElementAreReported) {
  const SceneFile file = loaded(extra("  <forces>\n    <simplegravity fx=\"0\" fy=\"-9.81\"/>\n"
                                      "    <group><dragdamping b=\"1\"/></group>\n  </forces>"));
  EXPECT_TRUE(file.scene.forces.empty());
  ASSERT_EQ(file.warningCount, 3);
  const auto has = [&](const std::string& fragment) {
    return std::any_of(file.warnings.begin(), file.warnings.end(),
                       [&](const std::string& w) { return w.find(fragment) != std::string::npos; });
  };
  EXPECT_TRUE(has(kFile + ":8: <forces>: unknown element ignored"));
  EXPECT_TRUE(has(kFile + ":9: <simplegravity> inside <forces> ignored"));
  EXPECT_TRUE(has(kFile + ":10: <dragdamping> inside <group> ignored"));
  // A second <scene> inside the first, too.
  EXPECT_EQ(loaded(extra("  <scene><particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/></scene>"))
                .warningCount,
            2);
}

TEST(UnusedInput, TextCdataAndDeclarationsAreReported) {
  expectContains(onlyWarning(extra("  gravity please")), {kFile + ":8: stray text \"gravity please\" ignored"});
  expectContains(onlyWarning(extra("  <![CDATA[<simplegravity fx=\"0\" fy=\"-1\"/>]]>")),
                 {kFile + ":8: CDATA section \"<simplegravity", "ignored"});
  expectContains(onlyWarning("<!DOCTYPE scene>\n" + join(baseLines())), {kFile + ":1: <!DOCTYPE scene> ignored"});
  // Comments and whitespace are not content.
  EXPECT_EQ(loaded(extra("  <!-- a note -->\n\n\t")).warningCount, 0);
}

TEST(UnusedInput, AttributesOnTheSceneAreReported) {
  expectContains(onlyWarning(replaced(1, "<scene version=\"2\">")),
                 {kFile + ":1: <scene> attribute 'version': ignored (<scene> takes no attributes)"});
}

TEST(UnusedInput, ANulByteIsAnErrorWhereverItIs) {
  // tinyxml2 stops reading at a NUL: a scene after it would be dropped without a word.
  std::string text = join(baseLines());
  text += std::string("\0", 1) + "<particle m=\"1\"/>\n";
  expectError(text, {kFile + ":9: a NUL byte (at byte " + std::to_string(text.find('\0')) + ")"});
  text = join(baseLines());
  text.insert(text.find("<edge"), std::string("\0", 1));
  expectError(text, {kFile + ":6: a NUL byte"});
}

TEST(UnusedInput, MisspellingsGetASuggestion) {
  expectContains(onlyWarning(extra("  <simplegravty fx=\"0\" fy=\"-9.81\"/>")),
                 {kFile + ":8: <simplegravty>: unknown element ignored; did you mean <simplegravity>?"});
  expectContains(onlyWarning(extra("  <Particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>")),
                 {"did you mean <particle>?"});
  expectContains(
      onlyWarning(replaced(4, "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" raduis=\"1\"/>")),
      {located(4, "particle", "raduis"), "did you mean 'radius'?"});
  expectContains(onlyWarning(extra("  <collision type=\"simple\" cor=\"0.5\"/>")), {"did you mean 'COR'?"});
  // Far from every name: the valid names instead (elements: the first unknown one only).
  expectContains(onlyWarning(extra("  <wobble/>")), {"unknown element ignored (valid: ", "particlepath"});
}

TEST(UnusedInput, SpellingSuggestsOnlyCloseUniqueNames) {
  const std::vector<std::string> attributes = {"m", "px", "py", "vx", "vy", "fixed", "radius"};
  EXPECT_EQ(io::closestName("raduis", attributes), "radius");  // a swap of neighbours
  EXPECT_EQ(io::closestName("radus", attributes), "radius");   // a letter left out
  EXPECT_EQ(io::closestName("fixd", attributes), "fixed");
  EXPECT_EQ(io::closestName("PX", attributes), "px");          // another case
  EXPECT_EQ(io::closestName("x", attributes), "");             // px or vx: no guess
  EXPECT_EQ(io::closestName("q", attributes), "");             // a whole replacement is no misspelling
  EXPECT_EQ(io::closestName("colour", attributes), "");
  EXPECT_EQ(io::editDistance("raduis", "radius"), 1);
  EXPECT_EQ(io::editDistance("", "abc"), 3);
  EXPECT_EQ(io::editDistance("kitten", "sitting"), 3);
}

TEST(UnusedInput, EveryErrorOfAFileInOnePassInLineOrder) {
  std::vector<std::string> lines = baseLines();
  lines.at(2) = "  <integrator type=\"verlet\" dt=\"-1\"/>";                                // 3: two errors
  lines.at(3) = "  <particle m=\"0\" px=\"a\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>";     // 4: two errors
  lines.at(5) = "  <edge i=\"0\" j=\"5\"/>";                                               // 6: no particle 5
  lines.insert(lines.end() - 1, "  <springforce edge=\"3\" k=\"1\" l0=\"1\" kk=\"1\"/>");  // 8: warning, error
  SceneFile file;
  const Status s = parseScene(join(lines), kFile, file);
  ASSERT_FALSE(s.isOk());
  EXPECT_EQ(file.errorCount, 6);
  EXPECT_NE(s.message().find("(and 5 more errors)"), std::string::npos) << s.message();
  std::vector<std::string> texts;
  for (const SceneMessage& m : file.messages) texts.push_back(m.text);
  const std::vector<std::string> expected = {
      located(3, "integrator", "type") + ": unknown integrator \"verlet\"",
      located(3, "integrator", "dt") + ": must be > 0",
      located(4, "particle", "m") + ": must be > 0",
      located(4, "particle", "px") + ": expected a number",
      located(6, "edge", "j") + ": particle 5 does not exist",
      located(8, "springforce", "kk") + ": unknown attribute ignored; did you mean 'k'?",
      located(8, "springforce", "edge") + ": edge 3 does not exist"};
  ASSERT_EQ(texts.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k) EXPECT_EQ(texts[k].rfind(expected[k], 0), 0u) << texts[k];
  EXPECT_FALSE(file.messages[5].isError());
}

TEST(UnusedInput, AMisspeltRequiredElementIsNamedInTheError) {
  expectError(
      replaced(2, "  <durration time=\"1\"/>"),
      {kFile + ": the scene has no <duration time=...> element (required)", "<durration> on line 2 is ignored"});
}

TEST(UnusedInput, RepeatedWarningsAreCountedAfterAFew) {
  std::string many;
  for (int k = 0; k < 10000; ++k) many += "<foo/>\n";
  SceneFile file = loaded(extra(many));
  EXPECT_EQ(file.warningCount, 10000);
  ASSERT_EQ(file.warnings.size(), 4u);
  EXPECT_EQ(file.warnings.back(), kFile + ": ... and 9,997 more unknown elements <foo> (lines 11-10,007)");
  // Many kinds: a bounded number of lines whatever the file holds.
  std::string kinds;
  for (int k = 0; k < 5000; ++k) kinds += "<foo" + std::to_string(k) + "/><bar x=\"1\"/>\n";
  file = loaded(extra(kinds));
  EXPECT_EQ(file.warningCount, 10000);
  EXPECT_LE(file.warnings.size(), 61u);
  EXPECT_NE(file.warnings.back().find("more warnings of"), std::string::npos) << file.warnings.back();
  // Errors too.
  std::string bad;
  for (int k = 0; k < 500; ++k) bad += "<particle m=\"-1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";
  SceneFile failed;
  ASSERT_FALSE(parseScene(extra(bad), kFile, failed).isOk());
  EXPECT_EQ(failed.errorCount, 500);
  EXPECT_LE(failed.messages.size(), 51u);
  EXPECT_EQ(failed.messages.back().text, kFile + ": ... and 450 more errors");
}

TEST(UnusedInput, LineEndsOfEveryKindAreCounted) {
  // The particle on line 4 has a bad mass; with \r (old Mac), \r\n (Windows) and \n line ends.
  const std::string text = replaced(4, "  <particle m=\"-1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>");
  for (const std::string end : {"\r", "\r\n", "\n"}) {
    std::string converted;
    for (char c : text) converted += c == '\n' ? end : std::string(1, c);
    expectError(converted, {located(4, "particle", "m"), "> 0"});
  }
  std::string crOnly = replaced(7, "  <halfplane px=\"0\" py=\"-1\" nx=\"0\" ny=\"1\" extra=\"1\"/>");
  std::replace(crOnly.begin(), crOnly.end(), '\n', '\r');
  expectContains(onlyWarning(crOnly), {located(7, "halfplane", "extra")});
}

TEST(UnusedInput, XmlSyntaxErrorsSayWhatIsWrongAndWhere) {
  std::vector<std::string> lines = baseLines();
  lines.pop_back();  // no </scene>
  expectError(join(lines),
              {kFile + ":7: not well-formed XML: the file ends with <scene> (line 1) still open: </scene> is missing"});
  const std::string message = loadError(join(lines));
  EXPECT_EQ(message.find("XML_ERROR"), std::string::npos) << message;
  expectError(replaced(4, "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" px=\"2\"/>"),
              {kFile + ":4: not well-formed XML: <particle> attribute 'px' is given twice"});
  expectError(replaced(3, "  <integrator type=explicit-euler dt=\"0.01\"/>"),
              {kFile + ":3: not well-formed XML: <integrator> attribute 'type': the value must be in quotes"});
  expectError(replaced(8, "</scen>"),
              {kFile + ":8: not well-formed XML: </scen> does not match the open <scene> (line 1)"});
  expectError(replaced(5, "  <!-- a comment"),
              {kFile + ":5: not well-formed XML: a comment (<!--) opened here never ends"});
}

TEST(UnusedInput, MessagesWriteNumbersShort) {
  // 1e300 s at dt 0.01: the step count in %g, not 300 digits.
  const std::string message = loadError(replaced(2, "  <duration time=\"1e300\"/>"));
  EXPECT_NE(message.find("asks for 1e+302 steps"), std::string::npos) << message;
  EXPECT_LT(message.size(), 300u) << message;
}

TEST(UnusedInput, ParticlePathsAreCutToTheRunAndBoundedInAll) {
  // A trail longer than the run keeps what the run has (ceil(1 / 0.01) + 1 positions at most).
  std::string paths;
  for (int k = 0; k < 40; ++k) paths += "  <particlepath i=\"0\" duration=\"1e300\" r=\"0\" g=\"0\" b=\"0\"/>\n";
  const SceneFile file = loaded(extra(paths));
  ASSERT_EQ(file.look.paths.size(), 40u);
  for (const ParticlePath& p : file.look.paths) EXPECT_LE(p.duration / file.scene.dt, 102.0);
  // A long run: 1e6 steps, ten trails of the whole run are more than 1e7 positions.
  std::string longRun = replaced(2, "  <duration time=\"1e4\"/>");
  std::string ten;
  for (int k = 0; k < 11; ++k) ten += "  <particlepath i=\"1\" duration=\"1e4\" r=\"0\" g=\"0\" b=\"0\"/>\n";
  longRun.insert(longRun.find("</scene>"), ten);
  expectError(longRun,
              {kFile + ":18: <particlepath> attribute 'duration': the trails would keep more than 1e+07 positions"});
}

}  // namespace
}  // namespace fosssim::testing
