// docs/scene-format.md is rendered from the loader's element table; the committed page must be
// exactly what the table gives today, and the table must describe what the loader reads: every
// element's example (made of the table's own example values) loads with no warning, and every
// required attribute left out is reported by name.
#include "fosssim/io/scene_format.h"
#include "scene_text.h"

#include "io/scene_elements.h"

#include <algorithm>

#include <fstream>
#include <sstream>

namespace fosssim::testing {
namespace {

std::string committedPage() {
  std::ifstream in(std::string(FOSSSIM_SOURCE_DIR) + "/docs/scene-format.md", std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(SceneFormatDoc, TheCommittedPageIsTheGeneratedOne) {
  const std::string generated = sceneFormatMarkdown(), committed = committedPage();
  if (generated == committed) return;
  size_t at = 0;
  while (at < generated.size() && at < committed.size() && generated[at] == committed[at]) ++at;
  const size_t line =
      static_cast<size_t>(std::count(generated.begin(), generated.begin() + static_cast<long>(at), '\n')) + 1;
  ADD_FAILURE() << "docs/scene-format.md differs from the loader's element table from line " << line
                << ". Regenerate it:\n  cmake --build <build> --target fosssim-scene-format && "
                   "<build>/tests/io/fosssim-scene-format docs/scene-format.md";
}

TEST(SceneFormatDoc, EveryElementAndAttributeIsOnThePage) {
  const std::string page = sceneFormatMarkdown();
  for (const io::ElementSpec& e : io::elementTable()) {
    EXPECT_NE(page.find("### `<" + std::string(e.name) + ">`"), std::string::npos) << e.name;
    EXPECT_GT(std::string(e.meaning).size(), 10u) << e.name;
    for (const io::AttributeSpec& a : e.attributes) {
      EXPECT_GT(std::string(a.meaning).size(), 2u) << e.name << " " << a.name;
      EXPECT_TRUE(a.max == 0 || (a.maxReason && *a.maxReason))
          << e.name << " " << a.name << ": a bound needs its reason";
    }
  }
  // The elements no page listed before.
  for (const char* name : {"constantforce", "viewport", "maxsimfreq", "backgroundcolor", "particlecolor", "edgecolor",
                           "halfplanecolor", "particlepath", "simtype", "scenetag"})
    EXPECT_NE(page.find("### `<" + std::string(name) + ">`"), std::string::npos) << name;
}

/// `<name a="example" ...>` with the table's examples, all attributes or all but `leftOut`.
std::string exampleElement(const io::ElementSpec& e, const std::string& leftOut = "") {
  std::string text = "  <" + std::string(e.name);
  for (const io::AttributeSpec& a : e.attributes)
    if (leftOut != a.name) text += " " + std::string(a.name) + "=\"" + a.example + "\"";
  return text + "/>";
}

/// The base scene (2 particles, 1 edge, 1 half-plane) with `element` in place of its line when
/// the element is one the base scene has once already (so "only the first counts" does not hide it).
std::string sceneWith(const io::ElementSpec& e, const std::string& element) {
  const std::string name = e.name;
  if (name == "duration") return replaced(2, element);
  if (name == "integrator") return replaced(3, element);
  return extra(element);
}

TEST(SceneFormatDoc, EveryElementsExampleLoadsWithoutWarnings) {
  for (const io::ElementSpec& e : io::elementTable()) {
    SceneFile file;
    const std::string text = sceneWith(e, exampleElement(e));
    const Status s = parseScene(text, kFile, file);
    EXPECT_TRUE(s.isOk()) << e.name << ": " << s.message();
    EXPECT_EQ(file.warningCount, 0) << e.name << ": " << (file.warnings.empty() ? "" : file.warnings.front());
  }
}

TEST(SceneFormatDoc, EveryRequiredAttributeLeftOutIsNamed) {
  for (const io::ElementSpec& e : io::elementTable())
    for (const io::AttributeSpec& a : e.attributes) {
      const std::string text = sceneWith(e, exampleElement(e, a.name));
      const int line = std::string(e.name) == "duration" ? 2 : std::string(e.name) == "integrator" ? 3 : kExtraLine;
      if (a.required()) {
        expectError(text, {located(line, e.name, a.name), "missing (required)"});
      } else {
        EXPECT_EQ(loadError(text), "") << e.name << " without its optional " << a.name;
      }
    }
}

}  // namespace
}  // namespace fosssim::testing
