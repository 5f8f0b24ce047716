// Large inputs: many elements, a 100 MB file, a file beyond the loader's size limit, deep
// nesting, huge attribute values and counts. They must load (or fail with a message) in
// reasonable time and memory, never crash or hang.
#include "scene_text.h"
#include "support/temp_dir_test.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fosssim::testing {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

class LargeInput : public TempDirTest {};

std::string header() {
  return "<scene>\n  <duration time=\"1\"/>\n  <integrator type=\"explicit-euler\" dt=\"0.01\"/>\n"
         "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";
}

TEST_F(LargeInput, TwoHundredThousandParticlesWithEdgesAndSprings) {
  constexpr int kN = 200000;
  std::string text = "<scene>\n<duration time=\"1\"/>\n<integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n";
  text.reserve(static_cast<size_t>(kN) * 160);
  for (int k = 0; k < kN; ++k)
    text += "<particle m=\"1\" px=\"" + std::to_string(k) + "\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>\n";
  for (int k = 0; k + 1 < kN; ++k) {
    text += "<edge i=\"" + std::to_string(k) + "\" j=\"" + std::to_string(k + 1) + "\"/>\n";
    text += "<springforce edge=\"" + std::to_string(k) + "\" k=\"1\" l0=\"1\"/>\n";
  }
  text += "</scene>\n";
  const auto start = Clock::now();
  SceneFile file;
  ASSERT_TRUE(parseScene(text, kFile, file).isOk());
  const double seconds = secondsSince(start);
  std::printf("%d particles, %d edges and springs (%.1f MB) loaded in %.2f s\n", kN, kN - 1, text.size() / 1e6,
              seconds);
  EXPECT_EQ(file.scene.numParticles(), kN);
  EXPECT_EQ(file.scene.edges.size(), static_cast<size_t>(kN - 1));
  EXPECT_EQ(file.scene.forces.size(), static_cast<size_t>(kN - 1));
  EXPECT_EQ(file.initial.x[2 * (kN - 1)], kN - 1.0);
  // Generous for a sanitizer build on a busy machine; a quadratic loader would take hours.
  EXPECT_LT(seconds, 60.0);
}

TEST_F(LargeInput, AHundredMegabyteFileLoads) {
  // A valid scene whose bulk is a 100 MB comment: read and parsed, not refused.
  const std::string p = path("big.xml");
  {
    std::ofstream out(p, std::ios::binary);
    out << header() << "<!--";
    const std::string line(1023, 'x');
    for (int k = 0; k < 100 * 1024; ++k) out << line << '\n';
    out << "-->\n</scene>\n";
  }
  ASSERT_GT(fs::file_size(p), 100u << 20);
  const auto start = Clock::now();
  SceneFile file;
  const Status s = loadScene(p, file);
  ASSERT_TRUE(s.isOk()) << s.message();
  EXPECT_EQ(file.scene.numParticles(), 1);
  EXPECT_LT(secondsSince(start), 60.0);
}

TEST_F(LargeInput, AHundredMegabytesOfJunkAfterAGoodStart) {
  const std::string p = path("junk.xml");
  {
    std::ofstream out(p, std::ios::binary);
    out << header();
    std::string block(1 << 20, '\0');
    for (size_t k = 0; k < block.size(); ++k) block[k] = static_cast<char>((k * 2654435761u) >> 13);
    for (int k = 0; k < 100; ++k) out << block;
  }
  SceneFile file;
  const Status s = loadScene(p, file);
  ASSERT_FALSE(s.isOk());
  EXPECT_EQ(s.message().rfind(p + ":", 0), 0u) << s.message();
}

TEST_F(LargeInput, AFileBeyondTheSizeLimitIsRefused) {
  // 300 MB (sparse: no disk space used) is more than any scene; the loader stops reading at its
  // limit instead of holding it all (and so also stops on endless devices).
  const std::string p = path("huge.xml");
  { std::ofstream out(p, std::ios::binary); }
  fs::resize_file(p, 300u << 20);
  SceneFile file;
  const Status s = loadScene(p, file);
  ASSERT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("larger than"), std::string::npos) << s.message();
}

TEST(LargeInputText, DeepNestingIsAnErrorNotAStackOverflow) {
  std::string text = header();
  for (int k = 0; k < 100000; ++k) text += "<a>";
  for (int k = 0; k < 100000; ++k) text += "</a>";
  text += "</scene>\n";
  EXPECT_NE(loadError(text), "");
}

/// <maxsimfreq> with `attributes` attributes: max and unknown ones.
std::string crowded(int attributes) {
  std::string element = "<maxsimfreq max=\"5\"";
  for (int k = 1; k < attributes; ++k) element += " a" + std::to_string(k) + "=\"1\"";
  return element + "/>";
}

TEST(LargeInputText, ManyUnknownAttributesAreWarnedAboutInReasonableTime) {
  // 1,000 attributes, the most an element may have.
  const auto start = Clock::now();
  SceneFile file;
  ASSERT_TRUE(parseScene(header() + crowded(1000) + "\n</scene>\n", kFile, file).isOk());
  EXPECT_EQ(file.warningCount, 999);
  // Shown: the first few, then one line per kind for the first kinds and one for the rest.
  EXPECT_LE(file.warnings.size(), 62u);
  EXPECT_NE(file.warnings.back().find("more warnings of"), std::string::npos) << file.warnings.back();
  EXPECT_LT(secondsSince(start), 30.0);
}

// More than 1,000 attributes on one element are refused before tinyxml2 parses them: its check
// for repeated attributes takes time growing with the square of their number (40,000 took 8 s,
// 200,000 over a minute). The message names file, line and element.
TEST_F(LargeInput, MoreThanAThousandAttributesOnAnElementAreRefusedUnparsed) {
  const std::string p = path("crowded.xml");
  std::ofstream(p, std::ios::binary) << header() << "<!-- a comment -->\n" << crowded(1001) << "\n</scene>\n";
  SceneFile file;
  const Status s = loadScene(p, file);
  ASSERT_FALSE(s.isOk());
  EXPECT_EQ(s.message().rfind(p + ":6: <maxsimfreq>: 1,001 attributes, more than the 1,000 an element may have", 0), 0u)
      << s.message();

  // A flood is refused as fast as it is read.
  const auto start = Clock::now();
  const std::string message = loadError(header() + crowded(200000) + "\n</scene>\n");
  EXPECT_NE(message.find(kFile + ":5: <maxsimfreq>: 200,000 attributes"), std::string::npos) << message.substr(0, 200);
  EXPECT_LT(secondsSince(start), 10.0);

  // The limit is per element, and tags in a comment or CDATA are no elements.
  const std::string lookalikes = header() + "<!-- " + crowded(2000) + " -->\n<![CDATA[" + crowded(2000) + "]]>\n" +
                                 crowded(800) + "\n" + crowded(800) + "\n</scene>\n";
  SceneFile loaded;
  const Status ok = parseScene(lookalikes, kFile, loaded);
  EXPECT_TRUE(ok.isOk()) << ok.message().substr(0, 300);
}

TEST(LargeInputText, HugeValuesAndCounts) {
  // A 10 MB number is still a number.
  const std::string digits = "1." + std::string(10 << 20, '0') + "1";
  SceneFile file;
  ASSERT_TRUE(parseScene(header() + "<maxsimfreq max=\"" + digits + "\"/></scene>", kFile, file).isOk());
  EXPECT_EQ(file.look.maxSimFreq, 1.0);
  // Step counts beyond any run are refused, with the integrator's location.
  expectError(replaced(2, "  <duration time=\"1e300\"/>"), {kFile + ":3: <integrator>", "steps"});
  expectError(replaced(3, "  <integrator type=\"explicit-euler\" dt=\"1e-300\"/>"),
              {kFile + ":3: <integrator>", "steps"});
  // A description of a megabyte is kept whole.
  const std::string words(1 << 20, 'w');
  ASSERT_TRUE(parseScene(extra("<description text=\"" + words + "\"/>"), kFile, file).isOk());
  EXPECT_EQ(file.description.size(), words.size());
}

// A name or word of the file is shown cut, with its length: a 3 MB integrator type or element
// name was a 3 MB line of stderr.
TEST(LargeInputText, LongNamesAndWordsAreCutInMessages) {
  const std::string longWord(1 << 20, 'z');
  const std::vector<std::string> errors = {
      replaced(3, "  <integrator type=\"" + longWord + "\" dt=\"0.01\"/>"),
      extra("  <collision type=\"" + longWord + "\"/>"),
      extra("  <collision type=\"hybrid\" failsafe=\"" + longWord + "\"/>"),
      extra("  <simtype type=\"" + longWord + "\"/>"),
      "<" + longWord + "/>\n",                                  // the root
      join(baseLines()) + "<" + longWord + "/>\n",              // a second root
      extra("  <" + longWord + ">"),                             // never closed
      extra("  <edge i=\"0\" j=\"1\" " + longWord + "=1/>"),   // unquoted
  };
  for (const std::string& text : errors) {
    const std::string message = loadError(text);
    EXPECT_FALSE(message.empty());
    EXPECT_LT(message.size(), 600u) << message.substr(0, 600);
    EXPECT_NE(message.find("(1,048,576 characters)"), std::string::npos) << message.substr(0, 600);
  }
  // Warnings: an unknown element, an unknown attribute, an element nested where nothing reads it.
  for (const std::string& element : {"  <" + longWord + "/>", "  <dragdamping b=\"0\" " + longWord + "=\"1\"/>",
                                     "  <dragdamping b=\"0\"><" + longWord + "/></dragdamping>"}) {
    SceneFile file;
    ASSERT_TRUE(parseScene(extra(element), kFile, file).isOk());
    ASSERT_EQ(file.warnings.size(), 1u);
    EXPECT_LT(file.warnings[0].size(), 600u) << file.warnings[0].substr(0, 600);
    EXPECT_NE(file.warnings[0].find("(1,048,576 characters)"), std::string::npos) << file.warnings[0].substr(0, 600);
  }
}

}  // namespace
}  // namespace fosssim::testing
