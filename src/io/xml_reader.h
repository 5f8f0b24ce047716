// Internal header: reading one XML element's attributes with located, precise error messages.
#pragma once

#include <tinyxml2.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace fosssim::io {

/// Thrown inside the loader only; loadScene turns it into a Status.
struct LoadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads the attributes of one element. Every attribute asked for is remembered, so that
/// attributes nobody asked for can be reported as unknown afterwards.
class ElementReader {
 public:
  ElementReader(const tinyxml2::XMLElement& element, const std::string& file);

  /// A required finite number.
  double number(const char* name);
  /// An optional finite number.
  double number(const char* name, double fallback);
  /// A required number > 0 (or >= 0 when allowZero).
  double positive(const char* name, bool allowZero = false);
  double positive(const char* name, double fallback, bool allowZero = false);
  /// A required integer (an integral number, e.g. "3" or "3.0").
  int integer(const char* name);
  /// A required index in [0, count) ... checked later by the caller when count is not yet known.
  int index(const char* name);
  /// A required 0 or 1.
  bool boolean(const char* name);
  /// A required string.
  std::string text(const char* name);
  std::string text(const char* name, const std::string& fallback);
  /// A colour channel in [0, 1].
  double channel(const char* name);
  bool has(const char* name) const;

  /// "file:line: <element>" for messages about the whole element.
  std::string where() const;
  /// "file:line: <element> attribute 'name'" for messages about one attribute.
  std::string where(const char* attribute) const;
  [[noreturn]] void fail(const char* attribute, const std::string& what) const;
  [[noreturn]] void fail(const std::string& what) const;
  int line() const { return element_.GetLineNum(); }
  const char* name() const { return element_.Name(); }

  /// Attributes present on the element that no call above asked for.
  std::vector<std::string> unknownAttributes() const;
  /// The attribute names asked for, comma separated (for "valid attributes are ..." messages).
  std::string knownAttributes() const;

 private:
  const tinyxml2::XMLAttribute* find(const char* name);
  const tinyxml2::XMLAttribute& require(const char* name);
  double parseNumber(const tinyxml2::XMLAttribute& attribute) const;

  const tinyxml2::XMLElement& element_;
  const std::string& file_;
  std::vector<std::string> asked_;
};

}  // namespace fosssim::io
