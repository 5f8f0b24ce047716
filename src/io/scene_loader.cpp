// The XML scene loader: reads the file, walks the document once through the element table
// (scene_elements.cpp), then resolves cross references and assembles the Scene
// (scene_assembly.cpp). Every problem of a file is reported in one pass (scene_messages.h), and
// everything in the file that is not used is reported too: unknown elements and attributes,
// elements nested where nothing reads them, stray text, CDATA, declarations.
#include "fosssim/io/scene_file.h"

#include "input_path.h"
#include "scene_elements.h"
#include "scene_messages.h"
#include "fosssim/io/spelling.h"
#include "xml_reader.h"
#include "xml_syntax.h"
#include "xml_wellformed.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <new>

namespace fosssim {
namespace {

using io::Builder;
using io::ElementSpec;
using io::SceneMessages;

/// The text trimmed and cut to 30 characters, on one line.
std::string clipped(const char* value) {
  const std::string all = io::trimXmlSpace(value);
  std::string s;
  for (size_t k = 0; k < all.size() && s.size() < 30; ++k) s += (all[k] == '\n' || all[k] == '\t') ? ' ' : all[k];
  if (all.size() > 30) s += "...";
  return s;
}

std::string shortText(const char* value) { return "\"" + clipped(value) + "\""; }

std::string elementNames() {
  std::string list;
  for (const ElementSpec& e : io::elementTable()) list += (list.empty() ? "" : ", ") + std::string(e.name);
  return list;
}

/// Reports what lies inside a known element: the format's elements take attributes only.
void reportContent(const tinyxml2::XMLElement& e, SceneMessages& m) {
  const std::string parent = e.Name();  // a known element's: short
  for (const tinyxml2::XMLNode* c = e.FirstChild(); c; c = c->NextSibling()) {
    if (c->ToComment()) continue;
    const int line = c->GetLineNum();
    if (const tinyxml2::XMLElement* child = c->ToElement())
      m.warn(line, "element inside <" + parent + ">", "elements inside <" + parent + ">",
             m.at(line) + "<" + io::clip(child->Name()) + "> inside <" + parent +
                 "> ignored (elements are read only directly inside <scene>; <" + parent + "> takes attributes only)");
    else if (const tinyxml2::XMLText* text = c->ToText())
      m.warn(line, "text inside <" + parent + ">", "texts inside <" + parent + ">",
             m.at(line) + (text->CData() ? "CDATA section " : "text ") + shortText(text->Value()) + " inside <" +
                 parent + "> ignored (<" + parent + "> takes attributes only)");
    else
      m.warn(line, "declaration", "declarations",
             m.at(line) + "<!" + clipped(c->Value()) + "> inside <" + parent + "> ignored");
  }
}

/// Reports the format's elements anywhere inside an unknown element (<forces><simplegravity/>):
/// the unknown one's warning alone did not say that the gravity written in it is not used.
void reportKnownInside(const tinyxml2::XMLElement& unknown, SceneMessages& m) {
  for (const tinyxml2::XMLElement* c = unknown.FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (io::findElement(c->Name())) {
      const int line = c->GetLineNum();
      m.warn(line, "element inside an unknown element", "elements inside unknown elements",
             m.at(line) + "<" + c->Name() + "> inside <" + io::clip(unknown.Name()) +
                 "> ignored (elements are read only directly inside <scene>)");
    }
    reportKnownInside(*c, m);
  }
}

/// Reports a child of <scene> that is not an element.
void reportOther(const tinyxml2::XMLNode& node, SceneMessages& m) {
  const int line = node.GetLineNum();
  if (const tinyxml2::XMLText* text = node.ToText()) {
    if (text->CData())
      m.warn(line, "CDATA", "CDATA sections",
             m.at(line) + "CDATA section " + shortText(text->Value()) +
                 " ignored (a scene is read from its elements only)");
    else
      m.warn(
          line, "stray text", "pieces of stray text",
          m.at(line) + "stray text " + shortText(text->Value()) + " ignored (a scene is read from its elements only)");
  } else if (!node.ToComment()) {
    m.warn(line, "declaration", "declarations",
           m.at(line) + "<!" + clipped(node.Value()) + "> ignored (FOSSSim reads no document type declarations)");
  }
}

void readElement(const tinyxml2::XMLElement& e, Builder& b, std::vector<const ElementSpec*>& seen,
                 const std::string& name) {
  SceneMessages& m = b.messages;
  const int line = e.GetLineNum();
  const ElementSpec* spec = io::findElement(e.Name());
  if (!spec) {
    static const std::vector<std::string> names = [] {
      std::vector<std::string> v;
      for (const ElementSpec& s : io::elementTable()) v.emplace_back(s.name);
      return v;
    }();
    // The list of valid names comes with the first unknown element only (it is long).
    const bool first = b.unknownElements.empty();
    // Floods repeat a few names: each name's suggestion is worked out once, and its first line kept.
    auto known = b.suggestions.find(e.Name());
    if (known == b.suggestions.end()) {
      known = b.suggestions.emplace(e.Name(), io::closestName(e.Name(), names)).first;
      b.unknownElements.emplace_back(e.Name(), line);
    }
    const std::string& guess = known->second;
    const std::string shown = io::clip(e.Name());
    m.warn(line, "unknown element <" + shown + ">", "unknown elements <" + shown + ">",
           m.at(line) + "<" + shown + ">: unknown element ignored" +
               (!guess.empty() ? "; did you mean <" + guess + ">?"
                : first        ? " (valid: " + elementNames() + ")"
                               : ""));
    reportKnownInside(e, m);
    return;
  }
  if (spec->repeat == io::Repeat::FirstCounts) {
    if (std::find(seen.begin(), seen.end(), spec) != seen.end()) {
      m.warn(line, "second <" + std::string(spec->name) + ">", "more <" + std::string(spec->name) + "> elements",
             m.at(line) + "<" + spec->name + ">: ignored, only the first <" + spec->name + "> counts");
      return;
    }
    seen.push_back(spec);
  }
  io::ElementReader reader(e, *spec, m, name);
  spec->read(reader, b);
  reader.reportUnknownAttributes();
  reportContent(e, m);
}

Status parseDocument(const std::string& raw, const std::string& name, SceneFile& out) {
  SceneMessages messages(name);
  // A NUL byte ends tinyxml2's reading: whatever follows would be dropped without a word.
  if (const size_t nul = raw.find('\0'); nul != std::string::npos)
    return Status::error(messages.at(io::lineOf(raw, nul)) + "a NUL byte (at byte " +
                         io::withThousands(static_cast<long>(nul)) +
                         "): a scene file is XML text, and nothing after it could be read");
  // A control character would reach the terminal with the description or a message quoting a
  // value (an escape sequence acts there), and XML does not allow one, even written as &#27;.
  if (io::ControlCharacter control; io::findControlCharacter(raw, control)) {
    const std::string at = ", at byte " + io::withThousands(static_cast<long>(control.offset));
    if (control.code >= 0x20)
      return Status::error(messages.at(io::lineOf(raw, control.offset)) + "the reference " + io::clip(control.written) +
                           " names no character XML allows (surrogate halves, U+FFFE, U+FFFF and code points beyond "
                           "U+10FFFF are none)" + at);
    return Status::error(messages.at(io::lineOf(raw, control.offset)) + "a control character, " +
                         io::codePointName(control.code) +
                         (control.written.empty() ? "" : " (written " + io::clip(control.written) + ")") + at +
                         ": XML allows none but tab and line ends, and a scene file is text");
  }
  // Bytes that are no UTF-8 (a file saved as Latin-1): tinyxml2 passed them through as they were.
  if (io::InvalidUtf8 bad; io::findInvalidUtf8(raw, bad))
    return Status::error(
        messages.at(io::lineOf(raw, bad.offset)) + "column " + std::to_string(io::columnOf(raw, bad.offset)) + ": " +
        bad.why + ", at byte " + io::withThousands(static_cast<long>(bad.offset)) +
        (bad.utf8 ? std::string(": a scene file is XML text")
                  : std::string(": a scene file is UTF-8 text (a file saved as Latin-1 or Windows-1252 "
                                "has such bytes for accented letters; save it as UTF-8)")));
  // What tinyxml2 lets through although XML does not (xml_wellformed.h): "&h;" kept as text.
  if (io::MarkupFault fault; io::findMarkupFault(raw, fault))
    return Status::error(messages.at(io::lineOf(raw, fault.offset)) + "column " +
                         std::to_string(io::columnOf(raw, fault.offset)) + ": not well-formed XML: " + fault.what);
  const std::string text = io::normalizeLineEnds(raw);
  // Before tinyxml2, whose check for repeated attributes makes a flood of them on one element
  // take minutes (xml_syntax.h).
  if (io::CrowdedElement crowded; io::findCrowdedElement(text, crowded)) {
    return Status::error(
        messages.at(crowded.line) + "<" + io::clip(crowded.name) + ">: " + io::withThousands(crowded.attributes) +
        " attributes, more than the " + io::withThousands(io::kMaxAttributes) +
        " an element may have (the scene format's take at most " + std::to_string(io::mostAttributes()) + ")");
  }
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLError parsed = doc.Parse(text.data(), text.size());
  if (parsed == tinyxml2::XML_ERROR_EMPTY_DOCUMENT)
    return Status::error(name + ": the file is empty (expected an XML document with root <scene>)");
  if (parsed != tinyxml2::XML_SUCCESS) {
    const io::XmlProblem problem = io::explainXmlError(text, parsed, doc.ErrorLineNum());
    return Status::error(messages.at(problem.line) + problem.what);
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) return Status::error(name + ": the file holds no XML element (expected <scene>)");
  if (std::string(root->Name()) != "scene")
    return Status::error(messages.at(root->GetLineNum()) + "the root element is <" + io::clip(root->Name()) +
                         ">, expected <scene>");
  if (const tinyxml2::XMLElement* second = root->NextSiblingElement())
    return Status::error(messages.at(second->GetLineNum()) + "unexpected element <" + io::clip(second->Name()) +
                         "> after </scene>");

  for (const tinyxml2::XMLNode* n = doc.FirstChild(); n; n = n->NextSibling())
    if (n != root && !n->ToDeclaration()) reportOther(*n, messages);
  for (const tinyxml2::XMLAttribute* a = root->FirstAttribute(); a; a = a->Next())
    messages.warn(root->GetLineNum(), "attribute on <scene>", "attributes on <scene>",
                  messages.at(root->GetLineNum()) + "<scene> attribute '" + io::clip(a->Name()) +
                      "': ignored (<scene> takes no attributes)");
  Builder builder(out, messages);
  std::vector<const ElementSpec*> seen;
  for (const tinyxml2::XMLNode* n = root->FirstChild(); n; n = n->NextSibling()) {
    if (const tinyxml2::XMLElement* e = n->ToElement()) readElement(*e, builder, seen, name);
    else reportOther(*n, messages);
  }
  io::assemble(builder, name);
  return messages.finish(out);
}

}  // namespace

Status parseScene(const std::string& text, const std::string& name, SceneFile& out) {
  out = SceneFile{};
  out.path = name;
  try {
    return parseDocument(text, name, out);
  } catch (const std::bad_alloc&) {
    out = SceneFile{};
    out.path = name;
    return Status::error(name + ": not enough memory to load the scene (" +
                         io::withThousands(static_cast<long>(text.size())) + " bytes)");
  }
}

Status loadScene(const std::string& path, SceneFile& out) {
  out = SceneFile{};
  out.path = path;
  if (Status st = io_detail::checkInputPath(path, "scene file"); !st) return st;
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::error(path + ": cannot open the scene file (" + std::strerror(errno) + ")");
  // Read in chunks up to a limit, so that a device such as /dev/zero cannot exhaust the memory.
  constexpr std::streamsize kMaxBytes = 256 << 20, kChunk = 1 << 16;
  std::string text;
  try {
    while (in) {
      const size_t used = text.size();
      text.resize(used + kChunk);
      in.read(&text[used], kChunk);
      text.resize(used + static_cast<size_t>(in.gcount()));
      if (static_cast<std::streamsize>(text.size()) > kMaxBytes)
        return Status::error(path + ": the scene file is larger than 256 MiB; is it a scene file?");
    }
  } catch (const std::bad_alloc&) {
    return Status::error(path + ": not enough memory to read the scene file");
  }
  if (in.bad()) return Status::error(path + ": cannot read the scene file (" + std::strerror(errno) + ")");
  return parseScene(text, path, out);
}

}  // namespace fosssim
