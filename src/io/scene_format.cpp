// docs/scene-format.md, rendered from the element table (scene_elements.cpp) and the integrator
// and collision tables of the core. tests/io/scene_format_doc_test.cpp compares the committed
// page with this text; tests/io/fosssim_scene_format.cpp writes it.
#include "fosssim/io/scene_format.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/integrator.h"
#include "scene_elements.h"
#include "xml_syntax.h"

#include <sstream>

namespace fosssim {
namespace {

using io::AttributeSpec;
using io::ElementSpec;
using io::Kind;

const char* kindText(Kind kind) {
  switch (kind) {
    case Kind::Number: return "number";
    case Kind::Positive: return "number > 0";
    case Kind::NonNegative: return "number >= 0";
    case Kind::Fraction: return "number in [0, 1]";
    case Kind::Index: return "index (integer >= 0)";
    case Kind::Flag: return "0 or 1";
    case Kind::Text: return "text";
  }
  return "";
}

std::string defaultText(const AttributeSpec& a) {
  if (a.required()) return "**required**";
  if (a.computedDefault()) return std::string(a.fallback).substr(1, std::string(a.fallback).size() - 2);
  return "`" + std::string(a.fallback) + "`";
}

const char* repeatText(const ElementSpec& e) {
  switch (e.repeat) {
    case io::Repeat::Adds: return e.required ? "required, one or more" : "any number";
    case io::Repeat::FirstCounts:
      return e.required ? "required; only the first counts" : "optional; only the first counts";
    case io::Repeat::LastCounts: return "optional; the last one counts";
  }
  return "";
}

void element(std::ostringstream& md, const ElementSpec& e) {
  md << "### `<" << e.name << ">`\n\n" << e.meaning << " (" << repeatText(e) << ")\n\n";
  md << "    <" << e.name;
  for (const AttributeSpec& a : e.attributes) md << " " << a.name << "=\"" << a.example << "\"";
  md << "/>\n\n";
  md << "| attribute | value | unit | default | meaning |\n|---|---|---|---|---|\n";
  for (const AttributeSpec& a : e.attributes) {
    md << "| `" << a.name << "` | " << kindText(a.kind);
    if (a.max > 0) md << ", at most " << io::shortNumber(a.max);
    md << " | " << (*a.unit ? a.unit : "") << " | " << defaultText(a) << " | " << a.meaning;
    if (a.max > 0) md << ". At most " << io::shortNumber(a.max) << ": " << a.maxReason;
    md << " |\n";
  }
  md << "\n";
}

}  // namespace

std::string sceneFormatMarkdown() {
  std::ostringstream md;
  md << "# The scene format\n\n"
        "<!-- Generated from the loader's element table (src/io/scene_elements.cpp) by fosssim-scene-format;\n"
        "     do not edit by hand. tests/io/scene_format_doc_test.cpp fails when the two disagree. -->\n\n"
        "A scene is an XML file whose root element is `<scene>`; every element below sits directly inside\n"
        "it, in any order, and takes attributes only. Units are SI (metres, kilograms, seconds).\n\n"
        "    <scene>\n"
        "      <description text=\"A ball bounces on a floor.\"/>\n"
        "      <duration time=\"2.0\"/>\n"
        "      <integrator type=\"symplectic-euler\" dt=\"0.01\"/>\n"
        "      <collision type=\"hybrid\" COR=\"0.5\"/>\n"
        "      <particle m=\"1\" px=\"0\" py=\"1\" vx=\"0\" vy=\"0\" fixed=\"0\" radius=\"0.1\"/>\n"
        "      <halfplane px=\"0\" py=\"0\" nx=\"0\" ny=\"1\"/>\n"
        "      <simplegravity fx=\"0\" fy=\"-9.81\"/>\n"
        "    </scene>\n\n"
        "## Rules\n\n"
        "- **Numbers** are decimal (`1`, `-0.5`, `2.5e-3`); spaces around them are allowed, anything else\n"
        "  after them is an error (`1.5abc`), and so are `nan`, `inf` and hexadecimal (`0x10`, which the\n"
        "  course's reader takes for 0). A number `> 0` is divided by, so its reciprocal must be finite\n"
        "  too: below about 5.6e-309 (`m=\"1e-320\"`) it is refused. A half-plane's normal may have any\n"
        "  finite length but 0: very long or very short normals are scaled exactly, by a power of two.\n"
        "- **Keywords** (`type`, `failsafe`) are read as written: `type=\" explicit-euler\"` is refused, with a\n"
        "  message that points at the space.\n"
        "- **Text** (descriptions, names) may not hold control characters other than tab and line ends,\n"
        "  written raw or as references (`&#27;`), nor references to what is no character (`&#xD800;`,\n"
        "  `&#xFFFE;`), as XML 1.0 requires; messages cut names longer than 40 characters.\n"
        "- A scene file is **UTF-8** (a byte-order mark is allowed): bytes that are not UTF-8, such as\n"
        "  Latin-1's `0xE9` for an `é`, are refused with their line, column and value.\n"
        "- **Indices** count from 0 in file order, per kind: the first `<particle>` is particle 0, the first\n"
        "  `<edge>` edge 0. An index may name an element that comes later in the file.\n"
        "- **Errors** (a bad value, a missing required attribute or element, an index that names nothing)\n"
        "  stop the load; all of a file's errors are reported together, each with file, line, element and\n"
        "  attribute, and FOSSSim exits with status 1.\n"
        "- **Warnings** report everything that is read but not used: unknown elements and attributes (with\n"
        "  \"did you mean\" for near misses), elements nested inside others, text, CDATA, attributes on\n"
        "  `<scene>`, ignored repeats. Repeats of one kind are shown three times and then counted.\n"
        "  `--strict` makes warnings errors; `-q` shows a one-line count instead.\n"
        "- `FOSSSim -s scene.xml --check` checks a scene without running it.\n"
        "- An element may have at most "
     << io::withThousands(io::kMaxAttributes) << " attributes (the elements below take at most " << io::mostAttributes()
     << "): parsing\n  more takes time growing with the square of their number, so a file with more is refused "
        "unparsed.\n"
        "- A run may take at most "
     << io::shortNumber(io::kMaxSteps)
     << " steps (ceil(duration / dt)); all `<particlepath>` trails together keep at most "
     << io::withThousands(static_cast<long>(io::kMaxTrailPoints)) << " positions.\n\n";
  const char* section = "";
  for (const ElementSpec& e : io::elementTable()) {
    if (std::string(section) != e.section) {
      section = e.section;
      md << "## " << section << "\n\n";
    }
    element(md, e);
    if (std::string(e.name) == "integrator") {
      md << "Integrators (`type`):\n\n| type | what it does |\n|---|---|\n";
      for (const IntegratorEntry& i : integratorTable()) md << "| `" << i.keyword << "` | " << i.summary << " |\n";
      md << "\n";
    }
    if (std::string(e.name) == "collision") {
      md << "Collision types (`type`):\n\n| type | what it does | penalty `k` | penalty `thickness` |\n"
            "|---|---|---|---|\n";
      for (const CollisionEntry& c : collisionTable()) {
        md << "| `" << c.keyword << "` | " << c.summary << " | ";
        if (c.addsPenaltyForce)
          md << io::shortNumber(c.defaultK) << " | " << io::shortNumber(c.defaultThickness) << " |\n";
        else md << "not used | not used |\n";
      }
      md << "\n";
    }
  }
  return md.str();
}

}  // namespace fosssim
