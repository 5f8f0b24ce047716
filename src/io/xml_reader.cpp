#include "xml_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace fosssim::io {
namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string quoted(const char* value) {
  std::string s(value);
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return "\"" + s + "\"";
}

}  // namespace

ElementReader::ElementReader(const tinyxml2::XMLElement& element, const std::string& file)
    : element_(element), file_(file) {}

std::string ElementReader::where() const {
  return file_ + ":" + std::to_string(line()) + ": <" + name() + ">";
}

std::string ElementReader::where(const char* attribute) const {
  return where() + " attribute '" + attribute + "'";
}

void ElementReader::fail(const char* attribute, const std::string& what) const {
  throw LoadError(where(attribute) + ": " + what);
}

void ElementReader::fail(const std::string& what) const { throw LoadError(where() + ": " + what); }

const tinyxml2::XMLAttribute* ElementReader::find(const char* attributeName) {
  if (std::find(asked_.begin(), asked_.end(), attributeName) == asked_.end())
    asked_.emplace_back(attributeName);
  return element_.FindAttribute(attributeName);
}

const tinyxml2::XMLAttribute& ElementReader::require(const char* attributeName) {
  const tinyxml2::XMLAttribute* a = find(attributeName);
  if (!a) fail(attributeName, "missing (required)");
  return *a;
}

bool ElementReader::has(const char* attributeName) const {
  return element_.FindAttribute(attributeName) != nullptr;
}

double ElementReader::parseNumber(const tinyxml2::XMLAttribute& attribute) const {
  // Stricter than the reference's stream extraction: surrounding whitespace is allowed (the course
  // scenes have px=" 1.0"), trailing junk is not ("1.5abc" would silently read 1.5 there).
  const char* text = attribute.Value();
  const char* p = text;
  while (isSpace(*p)) ++p;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(p, &end);
  const char* rest = end;
  while (rest && isSpace(*rest)) ++rest;
  if (end == p || *rest != '\0')
    fail(attribute.Name(), "expected a number, got " + quoted(text));
  // ERANGE also flags underflow ("1e-400" reads as 0 or a denormal), which is a fine value.
  if (!std::isfinite(value) || (errno == ERANGE && std::fabs(value) > 1.0))
    fail(attribute.Name(), "expected a finite number, got " + quoted(text));
  return value;
}

double ElementReader::number(const char* attributeName) {
  return parseNumber(require(attributeName));
}

double ElementReader::number(const char* attributeName, double fallback) {
  const tinyxml2::XMLAttribute* a = find(attributeName);
  return a ? parseNumber(*a) : fallback;
}

double ElementReader::positive(const char* attributeName, bool allowZero) {
  const double value = number(attributeName);
  if (value < 0 || (!allowZero && value == 0))
    fail(attributeName, std::string("must be ") + (allowZero ? ">= 0" : "> 0") + ", got " +
                            quoted(element_.Attribute(attributeName)));
  return value;
}

double ElementReader::positive(const char* attributeName, double fallback, bool allowZero) {
  return has(attributeName) ? positive(attributeName, allowZero) : (find(attributeName), fallback);
}

int ElementReader::integer(const char* attributeName) {
  const double value = number(attributeName);
  if (value != std::floor(value) || std::fabs(value) > 2e9)
    fail(attributeName, "expected an integer, got " + quoted(element_.Attribute(attributeName)));
  return static_cast<int>(value);
}

int ElementReader::index(const char* attributeName) {
  const int value = integer(attributeName);
  if (value < 0) fail(attributeName, "expected an index >= 0, got " + std::to_string(value));
  return value;
}

bool ElementReader::boolean(const char* attributeName) {
  const double value = number(attributeName);
  if (value != 0 && value != 1)
    fail(attributeName, "expected 0 or 1, got " + quoted(element_.Attribute(attributeName)));
  return value == 1;
}

std::string ElementReader::text(const char* attributeName) { return require(attributeName).Value(); }

std::string ElementReader::text(const char* attributeName, const std::string& fallback) {
  const tinyxml2::XMLAttribute* a = find(attributeName);
  return a ? std::string(a->Value()) : fallback;
}

double ElementReader::channel(const char* attributeName) {
  const double value = number(attributeName);
  if (value < 0 || value > 1)
    fail(attributeName, "a colour channel must lie in [0, 1], got " +
                            quoted(element_.Attribute(attributeName)));
  return value;
}

std::vector<std::string> ElementReader::unknownAttributes() const {
  std::vector<std::string> unknown;
  for (const tinyxml2::XMLAttribute* a = element_.FirstAttribute(); a; a = a->Next())
    if (std::find(asked_.begin(), asked_.end(), a->Name()) == asked_.end()) unknown.emplace_back(a->Name());
  return unknown;
}

std::string ElementReader::knownAttributes() const {
  std::string list;
  for (const auto& a : asked_) list += (list.empty() ? "" : ", ") + a;
  return list;
}

}  // namespace fosssim::io
