#include "xml_reader.h"
#include "xml_syntax.h"

#include "fosssim/core/scene_values.h"
#include "fosssim/io/spelling.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace fosssim::io {
namespace {


/// Characters that look like a space or like nothing in a terminal, named: "1" followed by a
/// no-break space was shown as "1 ", which reads as a number with a space the reader allows.
const std::pair<const char*, const char*> kInvisible[] = {
    {"\xC2\xA0", "U+00A0 no-break space"},      {"\xE2\x80\xAF", "U+202F narrow no-break space"},
    {"\xE2\x80\x8B", "U+200B zero-width space"}, {"\xEF\xBB\xBF", "U+FEFF zero-width no-break space"},
    {"\xE2\x80\x89", "U+2009 thin space"},       {"\xE3\x80\x80", "U+3000 ideographic space"}};

std::string quoted(const char* value) {
  std::string s(value);
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  std::string shown;
  for (std::size_t k = 0; k < s.size();) {
    bool named = false;
    for (const auto& [bytes, name] : kInvisible)
      if (s.compare(k, std::strlen(bytes), bytes) == 0) {
        shown += std::string("<") + name + ">";
        k += std::strlen(bytes);
        named = true;
        break;
      }
    if (named) continue;
    const unsigned char c = static_cast<unsigned char>(s[k++]);
    if (c < 0x20 || c == 0x7F) {  // a control character (a tab or a line break inside the value)
      char code[16];
      std::snprintf(code, sizeof code, "<U+%04X>", c);
      shown += code;
    } else {
      shown += static_cast<char>(c);
    }
  }
  return "\"" + shown + "\"";
}

/// True when the number `text` (read by strtod as 0) is written with a digit other than 0 in its
/// significand: "1e-400" underflowed, "0.0e5" is zero.
bool underflowed(const char* text) {
  for (const char* p = text; *p && *p != 'e' && *p != 'E'; ++p)
    if (*p >= '1' && *p <= '9') return true;
  return false;
}

bool numeric(Kind kind) { return kind != Kind::Text; }

/// The value of an attribute already reported (unreadable or missing): one that upsets no later
/// check, as after the range checks below. An index of -1 is one already reported (the element's
/// and the assembly's checks skip it; 1 made <edge i="O" j="1"/> "i = j = 1"), a flag 0 (1 made
/// <particle m="1"/>, fixed and velocity missing, warn of a moving fixed particle).
double placeholder(Kind kind) { return kind == Kind::Index ? -1.0 : kind == Kind::Flag ? 0.0 : 1.0; }

}  // namespace

ElementReader::ElementReader(const tinyxml2::XMLElement& element, const ElementSpec& spec, SceneMessages& messages,
                             const std::string& file)
    : element_(element), spec_(spec), messages_(messages), file_(file) {}

std::string ElementReader::where() const { return file_ + ":" + std::to_string(line()) + ": <" + name() + ">"; }

std::string ElementReader::where(const char* attribute) const {
  return where() + " attribute '" + attribute + "'";
}

void ElementReader::fail(const char* attribute, const std::string& what) {
  ok_ = false;
  messages_.error(line(), where(attribute) + ": " + what);
}

void ElementReader::fail(const std::string& what) {
  ok_ = false;
  messages_.error(line(), where() + ": " + what);
}

const AttributeSpec& ElementReader::declared(const char* attributeName, bool isNumeric) const {
  const AttributeSpec* a = spec_.attribute(attributeName);
  // The table is the format's definition: reading an attribute it does not declare (or as
  // another kind) would make docs/scene-format.md wrong. The element-table test loads every
  // element, so this cannot reach a user.
  if (!a || numeric(a->kind) != isNumeric)
    throw std::logic_error(std::string("element table: <") + spec_.name + "> attribute '" + attributeName +
                           "' is read but not declared as such");
  return *a;
}

const tinyxml2::XMLAttribute* ElementReader::find(const char* attributeName) {
  if (std::find(asked_.begin(), asked_.end(), attributeName) == asked_.end()) asked_.emplace_back(attributeName);
  const tinyxml2::XMLAttribute* a = element_.FindAttribute(attributeName);
  if (!a && !spec_.attribute(attributeName)->fallback) {
    std::string hint;
    std::vector<std::string> wanted = {attributeName};
    for (const tinyxml2::XMLAttribute* other = element_.FirstAttribute(); other; other = other->Next())
      if (!spec_.attribute(other->Name()) && !closestName(other->Name(), wanted).empty())
        hint = "; is '" + clip(other->Name()) + "' a misspelling of it?";
    missing_.emplace_back(attributeName);
    fail(attributeName, "missing (required)" + hint);
  }
  return a;
}

bool ElementReader::parseNumber(const tinyxml2::XMLAttribute& attribute, double& value) {
  // Stricter than the reference's stream extraction: surrounding whitespace is allowed (the course
  // scenes have px=" 1.0"), trailing junk is not ("1.5abc" would silently read 1.5 there).
  const char* text = attribute.Value();
  const char* p = text;
  while (isXmlSpace(*p)) ++p;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(p, &end);
  const char* rest = end;
  while (rest && isXmlSpace(*rest)) ++rest;
  if (end == p || *rest != '\0') {
    fail(attribute.Name(), "expected a number, got " + quoted(text));
    return false;
  }
  // strtod also reads C99 hexadecimal ("0x10" is 16, "0x1p-3" 0.125), which the course's stream
  // extraction read as 0 followed by ignored junk: a value the two would read differently, and no
  // scene means, so only decimal numbers are numbers.
  if (std::find_if(p, static_cast<const char*>(end), [](char c) { return c == 'x' || c == 'X'; }) != end) {
    fail(attribute.Name(), "expected a number (decimal; hexadecimal is not read), got " + quoted(text));
    return false;
  }
  // ERANGE also flags underflow ("1e-400" reads as 0 or a denormal), which is a fine value.
  if (!std::isfinite(value) || (errno == ERANGE && std::fabs(value) > 1.0)) {
    fail(attribute.Name(), "expected a finite number, got " + quoted(text));
    return false;
  }
  return true;
}

double ElementReader::checked(const AttributeSpec& spec, const tinyxml2::XMLAttribute& attribute) {
  double value = 0;
  if (!parseNumber(attribute, value)) return placeholder(spec.kind);
  const std::string got = ", got " + quoted(attribute.Value());
  switch (spec.kind) {
    case Kind::Positive:
      // "1e-400" is positive as written but reads as 0: "must be > 0" would contradict the file.
      if (value == 0 && underflowed(attribute.Value()))
        return fail(spec.name, "too small: it rounds to 0 (underflows; at least about 5.6e-309)" + got), 1.0;
      // The core's rules (scene_values.h), which a scene built in code is held to as well.
      if (const std::string why = valueProblem(ValueRule::Positive, value, spec.name); !why.empty())
        return fail(spec.name, why + got), 1.0;
      break;
    case Kind::NonNegative:
      if (const std::string why = valueProblem(ValueRule::NonNegative, value, spec.name); !why.empty())
        return fail(spec.name, why + got), 1.0;
      break;
    case Kind::Fraction:
      if (const std::string why = valueProblem(ValueRule::Fraction, value, spec.name); !why.empty())
        return fail(spec.name, why + got), 1.0;
      break;
    case Kind::Index:
      if (value != std::floor(value)) return fail(spec.name, "expected an integer" + got), -1.0;
      if (value < 0) return fail(spec.name, "expected an index >= 0" + got), -1.0;
      // An index is kept as an int; "2147483648" is an integer (it was "expected an integer"),
      // and names nothing: a scene file of at most 256 MiB holds far fewer elements.
      if (value > 2e9)
        return fail(spec.name, "index too large: no scene has 2e9 elements of a kind (numbered from 0)" + got), -1.0;
      break;
    case Kind::Flag:
      if (value != 0 && value != 1) return fail(spec.name, "expected 0 or 1" + got), 0.0;
      break;
    default:
      break;
  }
  if (spec.max > 0 && value > spec.max) {
    fail(spec.name, "must be at most " + shortNumber(spec.max) + got + ": " + spec.maxReason);
    return spec.max;
  }
  return value;
}

double ElementReader::number(const char* attributeName) {
  const AttributeSpec& spec = declared(attributeName, true);
  if (spec.computedDefault())
    throw std::logic_error(std::string("element table: <") + spec_.name + "> attribute '" + attributeName +
                           "' has a computed default: the reader must give it");
  const tinyxml2::XMLAttribute* a = find(attributeName);
  if (a) return checked(spec, *a);
  return spec.fallback ? std::strtod(spec.fallback, nullptr) : placeholder(spec.kind);
}

double ElementReader::number(const char* attributeName, double computedDefault) {
  const AttributeSpec& spec = declared(attributeName, true);
  if (!spec.computedDefault())
    throw std::logic_error(std::string("element table: <") + spec_.name + "> attribute '" + attributeName +
                           "' has its default in the table");
  const tinyxml2::XMLAttribute* a = find(attributeName);
  return a ? checked(spec, *a) : computedDefault;
}

int ElementReader::index(const char* attributeName) {
  if (declared(attributeName, true).kind != Kind::Index)
    throw std::logic_error(std::string("element table: <") + spec_.name + "> attribute '" + attributeName +
                           "' is no index");
  return static_cast<int>(number(attributeName));
}

bool ElementReader::flag(const char* attributeName) {
  if (declared(attributeName, true).kind != Kind::Flag)
    throw std::logic_error(std::string("element table: <") + spec_.name + "> attribute '" + attributeName +
                           "' is no flag");
  return number(attributeName) == 1;
}

std::string ElementReader::text(const char* attributeName) {
  const AttributeSpec& spec = declared(attributeName, false);
  const tinyxml2::XMLAttribute* a = find(attributeName);
  return a ? std::string(a->Value()) : spec.fallback ? std::string(spec.fallback) : std::string();
}

void ElementReader::reportUnknownAttributes() {
  std::vector<std::string> valid;
  for (const AttributeSpec& a : spec_.attributes) valid.emplace_back(a.name);
  for (const tinyxml2::XMLAttribute* a = element_.FirstAttribute(); a; a = a->Next()) {
    if (std::find(asked_.begin(), asked_.end(), a->Name()) != asked_.end()) continue;
    const std::string guess = closestName(a->Name(), valid);
    std::string list;
    for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
    const std::string name = clip(a->Name());
    const std::string text = where(name.c_str()) + ": unknown attribute ignored" +
                             (guess.empty() ? " (valid: " + list + ")" : "; did you mean '" + guess + "'?");
    messages_.warn(line(), "unknown attribute '" + name + "' of <" + spec_.name + ">",
                   "unknown attributes '" + name + "' of <" + spec_.name + ">", text);
  }
}

}  // namespace fosssim::io
