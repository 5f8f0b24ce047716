// Bad attribute values: every numeric attribute of every element, given text that is not a
// number, junk after a number, NaN or infinity, or left out when required, must be rejected with
// a message naming the file, the line, the element and the attribute. Values outside their
// range (masses, dt, radii, flags, colours, COR, ...) likewise.
#include "scene_text.h"

namespace fosssim::testing {
namespace {

struct Attr {
  const char* name;
  const char* good;
  bool required;
};

/// One element of the format with valid values, and where it goes in the base scene.
struct ElementSpec {
  const char* name;
  const char* fixedText;  ///< non-numeric attributes written as they are (e.g. type="...")
  std::vector<Attr> numeric;
  int line;  ///< the base scene's line it replaces, or 0: inserted at kExtraLine
};

// Required attributes as listed in the format's element table (spec section 1).
const std::vector<ElementSpec>& elements() {
  static const std::vector<ElementSpec> specs = {
      {"duration", "", {{"time", "1", true}}, 2},
      {"integrator", "type=\"explicit-euler\"", {{"dt", "0.01", true}}, 3},
      {"particle", "", {{"m", "1", true}, {"px", "0", true}, {"py", "0", true}, {"vx", "0", true},
                        {"vy", "0", true}, {"fixed", "0", true}, {"radius", "0.1", false}}, 4},
      {"edge", "", {{"i", "0", true}, {"j", "1", true}, {"radius", "0.02", false}}, 6},
      {"halfplane", "", {{"px", "0", true}, {"py", "-1", true}, {"nx", "0", true}, {"ny", "1", true}}, 7},
      {"maxsimfreq", "", {{"max", "100", true}}, 0},
      {"viewport", "", {{"cx", "0", true}, {"cy", "0", true}, {"size", "2", true}}, 0},
      {"backgroundcolor", "", {{"r", "1", true}, {"g", "1", true}, {"b", "1", true}}, 0},
      {"springforce", "", {{"edge", "0", true}, {"k", "1", true}, {"l0", "1", true}, {"b", "0", false}}, 0},
      {"simplegravity", "", {{"fx", "0", true}, {"fy", "-9.81", true}}, 0},
      {"constantforce", "", {{"fx", "1", true}, {"fy", "0", true}}, 0},
      {"gravitationalforce", "", {{"i", "0", true}, {"j", "1", true}, {"G", "1", true}}, 0},
      {"dragdamping", "", {{"b", "0.1", true}}, 0},
      {"vortexforce", "", {{"i", "0", true}, {"j", "1", true}, {"kbs", "1", true}, {"kvc", "1", true}}, 0},
      {"collision", "type=\"penalty\"",
       {{"COR", "0.5", false}, {"maxiters", "10", false}, {"k", "100", false}, {"thickness", "0.01", false}}, 0},
      {"particlecolor", "", {{"i", "1", true}, {"r", "0", true}, {"g", "0", true}, {"b", "0", true}}, 0},
      {"edgecolor", "", {{"i", "0", true}, {"r", "0", true}, {"g", "0", true}, {"b", "0", true}}, 0},
      {"halfplanecolor", "", {{"i", "0", true}, {"r", "0", true}, {"g", "0", true}, {"b", "0", true}}, 0},
      {"particlepath", "", {{"i", "1", true}, {"duration", "1", true}, {"r", "0", true}, {"g", "0", true},
                            {"b", "0", true}}, 0},
  };
  return specs;
}

/// The element's text with attribute `changed` set to `value` (or left out when value is null).
std::string elementText(const ElementSpec& e, const std::string& changed, const char* value) {
  std::string text = std::string("  <") + e.name + " " + e.fixedText;
  for (const Attr& a : e.numeric) {
    if (a.name == changed && !value) continue;
    text += std::string(" ") + a.name + "=\"" + (a.name == changed ? value : a.good) + "\"";
  }
  return text + "/>";
}

std::string sceneWith(const ElementSpec& e, const std::string& changed, const char* value) {
  const std::string element = elementText(e, changed, value);
  return e.line ? replaced(e.line, element) : extra(element);
}

int lineOf(const ElementSpec& e) { return e.line ? e.line : kExtraLine; }

TEST(BadInput, EveryElementLoadsWithItsGoodValues) {
  // The sweeps below change one attribute at a time; the unchanged scene must load.
  for (const ElementSpec& e : elements()) EXPECT_EQ(loadError(sceneWith(e, "", nullptr)), "") << e.name;
}

TEST(BadInput, TextThatIsNotANumberIsLocated) {
  // Hexadecimal ("0x10"): strtod reads 16 where the course's stream extraction read 0 and junk.
  for (const char* bad : {"abc", "1.5abc", "", "  ", "1,5", "0x", "--1", "1 2", "one", "1.0.0", "\"1\"", "0x10",
                          "0x1p3", "-0X1", " 0x0 ", "1x"}) {
    for (const ElementSpec& e : elements())
      for (const Attr& a : e.numeric) {
        SCOPED_TRACE(std::string(e.name) + " " + a.name + "=\"" + bad + "\"");
        const std::string value = bad == std::string("\"1\"") ? "&quot;1&quot;" : bad;
        expectError(sceneWith(e, a.name, value.c_str()),
                    {located(lineOf(e), e.name, a.name), "expected a number", "got \"" + std::string(bad) + "\""});
      }
  }
}

TEST(BadInput, NonFiniteNumbersAreRejected) {
  for (const char* bad : {"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999", "-1e400"}) {
    for (const ElementSpec& e : elements())
      for (const Attr& a : e.numeric) {
        SCOPED_TRACE(std::string(e.name) + " " + a.name + "=\"" + bad + "\"");
        expectError(sceneWith(e, a.name, bad), {located(lineOf(e), e.name, a.name), "finite", bad});
      }
  }
}

TEST(BadInput, MissingRequiredAttributesAreNamed) {
  for (const ElementSpec& e : elements())
    for (const Attr& a : e.numeric) {
      SCOPED_TRACE(std::string(e.name) + " without " + a.name);
      if (a.required)
        expectError(sceneWith(e, a.name, nullptr), {located(lineOf(e), e.name, a.name), "missing"});
      else
        EXPECT_EQ(loadError(sceneWith(e, a.name, nullptr)), "");
    }
  expectError(replaced(3, "  <integrator dt=\"0.01\"/>"), {located(3, "integrator", "type"), "missing"});
  expectError(extra("  <collision COR=\"1\"/>"), {located(kExtraLine, "collision", "type"), "missing"});
  expectError(extra("  <description/>"), {located(kExtraLine, "description", "text"), "missing"});
}

struct RangeCase {
  const char* element;  ///< the element under test
  const char* attribute;
  const char* text;     ///< the whole element
  int line;             ///< the base line it replaces, 0 to insert it
  const char* why;      ///< a fragment the message must contain
};

TEST(BadInput, ValuesOutOfRangeAreRejected) {
  const char* particle = "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\" ";
  const std::vector<RangeCase> cases = {
      {"particle", "m", "  <particle m=\"0\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>", 4, "> 0"},
      {"particle", "m", "  <particle m=\"-1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>", 4, "> 0"},
      {"particle", "m", "  <particle m=\"1e-400\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>", 4, "rounds to 0"},
      // Subnormal: > 0, but 1/m is infinite.
      {"particle", "m", "  <particle m=\"1e-320\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>", 4,
       "1/m is not finite"},
      {"particle", "radius", "radius=\"4e-309\"/>", 4, "1/radius is not finite"},
      {"integrator", "dt", "  <integrator type=\"explicit-euler\" dt=\"1e-310\"/>", 3, "1/dt is not finite"},
      {"edge", "radius", "  <edge i=\"0\" j=\"1\" radius=\"1e-315\"/>", 6, "1/radius is not finite"},
      {"viewport", "size", "  <viewport cx=\"0\" cy=\"0\" size=\"5e-324\"/>", 0, "1/size is not finite"},
      {"maxsimfreq", "max", "  <maxsimfreq max=\"2e-320\"/>", 0, "1/max is not finite"},
      {"particle", "radius", "radius=\"0\"/>", 4, "> 0"},
      {"particle", "radius", "radius=\"-0.1\"/>", 4, "> 0"},
      {"particle", "fixed", "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"2\"/>", 4, "0 or 1"},
      {"particle", "fixed", "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0.5\"/>", 4, "0 or 1"},
      {"particle", "fixed", "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"-1\"/>", 4, "0 or 1"},
      {"integrator", "dt", "  <integrator type=\"explicit-euler\" dt=\"0\"/>", 3, "> 0"},
      {"integrator", "dt", "  <integrator type=\"explicit-euler\" dt=\"-0.01\"/>", 3, "> 0"},
      {"duration", "time", "  <duration time=\"-1\"/>", 2, ">= 0"},
      {"edge", "radius", "  <edge i=\"0\" j=\"1\" radius=\"0\"/>", 6, "> 0"},
      {"edge", "radius", "  <edge i=\"0\" j=\"1\" radius=\"-1\"/>", 6, "> 0"},
      {"halfplane", "nx", "  <halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"0\"/>", 7, "must not be zero"},
      {"halfplane", "nx", "  <halfplane px=\"0\" py=\"0\" nx=\"-0\" ny=\"0.0\"/>", 7, "must not be zero"},
      {"maxsimfreq", "max", "  <maxsimfreq max=\"0\"/>", 0, "> 0"},
      {"viewport", "size", "  <viewport cx=\"0\" cy=\"0\" size=\"0\"/>", 0, "> 0"},
      {"viewport", "size", "  <viewport cx=\"0\" cy=\"0\" size=\"-2\"/>", 0, "> 0"},
      {"springforce", "k", "  <springforce edge=\"0\" k=\"-1\" l0=\"1\"/>", 0, ">= 0"},
      {"springforce", "l0", "  <springforce edge=\"0\" k=\"1\" l0=\"-1\"/>", 0, ">= 0"},
      {"springforce", "b", "  <springforce edge=\"0\" k=\"1\" l0=\"1\" b=\"-0.5\"/>", 0, ">= 0"},
      {"dragdamping", "b", "  <dragdamping b=\"-0.1\"/>", 0, ">= 0"},
      {"particlepath", "duration", "  <particlepath i=\"0\" duration=\"-1\" r=\"0\" g=\"0\" b=\"0\"/>", 0, ">= 0"},
      {"collision", "COR", "  <collision type=\"simple\" COR=\"1.5\"/>", 0, "[0, 1]"},
      {"collision", "COR", "  <collision type=\"simple\" COR=\"-0.1\"/>", 0, "[0, 1]"},
      {"collision", "k", "  <collision type=\"penalty\" k=\"-100\"/>", 0, ">= 0"},
      {"collision", "thickness", "  <collision type=\"penalty\" thickness=\"-0.01\"/>", 0, ">= 0"},
      {"collision", "maxiters", "  <collision type=\"simple\" maxiters=\"1e10\"/>", 0, "at most 10000,"},
      {"collision", "maxiters", "  <collision type=\"hybrid\" maxiters=\"10001\"/>", 0, "12 minutes per step"},
  };
  for (const RangeCase& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string text = c.text[0] == 'r' ? particle + std::string(c.text) : c.text;
    const std::string scene = c.line ? replaced(c.line, text) : extra(text);
    expectError(scene, {located(c.line ? c.line : kExtraLine, c.element, c.attribute), c.why});
  }
  // Small but normal: 1/m = 1e308 is finite.
  EXPECT_EQ(loadError(replaced(4, "  <particle m=\"1e-308\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>")), "");
}

TEST(BadInput, ColourChannelsOutsideZeroOneAreRejected) {
  for (const char* element : {"backgroundcolor", "particlecolor", "edgecolor", "halfplanecolor", "particlepath"})
    for (const char* channel : {"r", "g", "b"})
      for (const char* bad : {"1.0001", "-0.01", "255", "2"}) {
        std::string text = std::string("  <") + element + (element[0] == 'b' ? "" : " i=\"0\"") +
                           (element == std::string("particlepath") ? " duration=\"1\"" : "");
        for (const char* c : {"r", "g", "b"})
          text += std::string(" ") + c + "=\"" + (c == channel ? bad : "0.5") + "\"";
        SCOPED_TRACE(text);
        expectError(extra(text + "/>"), {located(kExtraLine, element, channel), "[0, 1]", bad});
      }
}

// An integer beyond an int is no "expected an integer" (it is one): it is too large to name anything.
TEST(BadInput, AnIndexBeyondAnyCountIsTooLarge) {
  for (const char* big : {"2147483648", "2e9 ", "1e300", "99999999999999999999"}) {
    SCOPED_TRACE(big);
    const std::string v = std::string("\"") + big + "\"";
    for (const std::string& text : {"  <particlecolor i=" + v + " r=\"0\" g=\"0\" b=\"0\"/>",
                                    "  <springforce edge=" + v + " k=\"1\" l0=\"1\"/>"}) {
      const std::string message = loadError(extra(text));
      EXPECT_NE(message.find(located(kExtraLine, text[3] == 'p' ? "particlecolor" : "springforce",
                                     text[3] == 'p' ? "i" : "edge")),
                std::string::npos)
          << message;
      EXPECT_EQ(message.find("expected an integer"), std::string::npos) << message;
      EXPECT_TRUE(message.find("too large") != std::string::npos || message.find("does not exist") != std::string::npos)
          << message;
    }
  }
}

TEST(BadInput, IndicesMustBeNonNegativeIntegers) {
  for (const char* bad : {"-1", "0.5", "1e10", "-2147483649"}) {
    SCOPED_TRACE(bad);
    const std::string v = std::string("\"") + bad + "\"";
    expectError(replaced(6, "  <edge i=" + v + " j=\"1\"/>"), {located(6, "edge", "i")});
    expectError(extra("  <springforce edge=" + v + " k=\"1\" l0=\"1\"/>"),
                {located(kExtraLine, "springforce", "edge")});
    expectError(extra("  <particlecolor i=" + v + " r=\"0\" g=\"0\" b=\"0\"/>"),
                {located(kExtraLine, "particlecolor", "i")});
    expectError(extra("  <vortexforce i=\"0\" j=" + v + " kbs=\"1\" kvc=\"1\"/>"),
                {located(kExtraLine, "vortexforce", "j")});
  }
}

// A value that is no number is one error, and nothing follows from it: the failed read's
// placeholder must not trip the element's own checks (an edge's i = j, a fixed particle with a
// velocity) or the assembly's (an index naming nothing). The base scene has particles 0 and 1
// and edge 0, so a placeholder index of 1 would do both.
TEST(BadInput, AValueThatIsNoNumberIsOneMessage) {
  const std::vector<RangeCase> cases = {
      {"edge", "i", "  <edge i=\"O\" j=\"1\"/>", 6, ""},
      {"edge", "j", "  <edge i=\"1\" j=\"I\"/>", 6, ""},
      {"gravitationalforce", "i", "  <gravitationalforce i=\"O\" j=\"1\" G=\"1\"/>", 0, ""},
      {"vortexforce", "j", "  <vortexforce i=\"1\" j=\"one\" kbs=\"1\" kvc=\"1\"/>", 0, ""},
      {"springforce", "edge", "  <springforce edge=\"first\" k=\"1\" l0=\"1\"/>", 0, ""},
      {"edgecolor", "i", "  <edgecolor i=\"O\" r=\"0\" g=\"0\" b=\"0\"/>", 0, ""},
      {"particlecolor", "i", "  <particlecolor i=\"x\" r=\"0\" g=\"0\" b=\"0\"/>", 0, ""},
      {"particlepath", "i", "  <particlepath i=\"x\" duration=\"1\" r=\"0\" g=\"0\" b=\"0\"/>", 0, ""},
      {"particle", "fixed", "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"1\" vy=\"0\" fixed=\"yes\"/>", 4, ""},
  };
  for (const RangeCase& c : cases) {
    SCOPED_TRACE(c.text);
    SceneFile file;
    const Status s = parseScene(c.line ? replaced(c.line, c.text) : extra(c.text), kFile, file);
    ASSERT_FALSE(s.isOk());
    EXPECT_EQ(file.errorCount, 1) << s.message();
    EXPECT_EQ(file.warningCount, 0) << s.message();
    EXPECT_EQ(file.messages.size(), 1u) << s.message();
    if (file.messages.empty()) continue;
    EXPECT_EQ(file.messages[0].line, c.line ? c.line : kExtraLine);
    EXPECT_EQ(file.messages[0].text.rfind(located(c.line ? c.line : kExtraLine, c.element, c.attribute) +
                                          ": expected a number", 0), 0u)
        << file.messages[0].text;
  }
}

// Missing attributes read as placeholders: <particle m="1"/> (fixed and the velocity missing) was
// also warned of as "a fixed particle with a velocity", from the placeholders 1; and a velocity
// that is no number, on a fixed particle, likewise. Only the errors remain.
TEST(BadInput, PlaceholdersOfMissingValuesDrawNoWarning) {
  for (const char* particle : {"  <particle m=\"1\"/>",
                               "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"fast\" vy=\"0\" fixed=\"1\"/>",
                               "  <particle m=\"1\" px=\"0\" py=\"0\" fixed=\"1\"/>"}) {
    SCOPED_TRACE(particle);
    SceneFile file;
    const Status s = parseScene(replaced(4, particle), kFile, file);
    ASSERT_FALSE(s.isOk());
    EXPECT_EQ(file.warningCount, 0) << s.message();
    EXPECT_EQ(s.message().find("moves at it"), std::string::npos) << s.message();
  }
}

// What messages quote is shown as it is, invisible characters named: a no-break space after a
// number was shown as "1 ", which reads as a number with a space that the reader allows.
TEST(BadInput, InvisibleCharactersInAValueAreNamed) {
  expectError(replaced(4, "  <particle m=\"1\xC2\xA0\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"),
              {located(4, "particle", "m") + ": expected a number, got \"1<U+00A0 no-break space>\""});
  expectError(replaced(4, "  <particle m=\"\xE2\x80\x8B" "2\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"),
              {"got \"<U+200B zero-width space>2\""});
}

// A positive value written so small that it reads as 0 was "must be > 0", which the file
// contradicts: it says the value underflows. A zero written as zero is still "must be > 0".
TEST(BadInput, APositiveValueThatUnderflowsIsSaidToRoundToZero) {
  expectError(replaced(4, "  <particle m=\"1e-400\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>"),
              {located(4, "particle", "m") + ": too small: it rounds to 0 (underflows", "got \"1e-400\""});
  expectError(replaced(3, "  <integrator type=\"explicit-euler\" dt=\"0.5e-9999\"/>"),
              {located(3, "integrator", "dt"), "rounds to 0"});
  for (const char* zero : {"0", "0.000e-400", "-0"}) {
    SCOPED_TRACE(zero);
    const std::string message =
        loadError(replaced(3, std::string("  <integrator type=\"explicit-euler\" dt=\"") + zero + "\"/>"));
    EXPECT_NE(message.find(located(3, "integrator", "dt") + ": must be > 0"), std::string::npos) << message;
  }
}

// A spring between two particles that start at one point has no direction there: its force was
// NaN and the run stopped at step 1, without the spring's line. Refused at load, naming it; both
// ends fixed, it moves nothing and loads.
TEST(BadInput, ASpringWhoseEndsStartAtOnePointIsLocated) {
  std::vector<std::string> lines = baseLines();
  lines[4] = "  <particle m=\"2\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>";  // particle 1 onto particle 0
  lines.insert(lines.begin() + (kExtraLine - 1), "  <springforce edge=\"0\" k=\"1\" l0=\"1\"/>");
  expectError(join(lines), {located(kExtraLine, "springforce", "edge") +
                                ": edge 0 joins particles 0 and 1, which both start at (0, 0): the spring's direction, "
                                "and so its force, is undefined there; move one of them apart"});
  lines[kExtraLine - 1] = "  <springforce edge=\"0\" k=\"1\" l0=\"0\"/>";
  expectError(join(lines), {located(kExtraLine, "springforce", "edge"), "(even with l0 = 0"});
  lines[3] = "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"1\"/>";  // one end fixed: still
  expectError(join(lines), {located(kExtraLine, "springforce", "edge")});
  lines[4] = "  <particle m=\"2\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"1\"/>";  // both fixed: loads
  EXPECT_EQ(loadError(join(lines)), "");
  EXPECT_EQ(loadError(extra("  <springforce edge=\"0\" k=\"1\" l0=\"0\"/>")), "");  // apart: loads
}

}  // namespace
}  // namespace fosssim::testing
