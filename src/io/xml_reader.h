// Internal header: reading one XML element's attributes as its entry in the element table says,
// with located, precise messages. A bad attribute is reported and reading goes on (the caller gets
// a harmless placeholder and ok() turns false), so that one pass reports every problem of a file.
#pragma once

#include "scene_elements.h"
#include "scene_messages.h"

#include <tinyxml2.h>

#include <string>
#include <vector>

namespace fosssim::io {

/// Reads the attributes of one element. Every attribute must be declared in the element's spec
/// (asking for an undeclared one is a programming error: std::logic_error); attributes present on
/// the element that no read asked for are reported as unknown afterwards.
class ElementReader {
 public:
  ElementReader(const tinyxml2::XMLElement& element, const ElementSpec& spec, SceneMessages& messages,
                const std::string& file);

  /// A number of one of the numeric kinds, checked against the kind and the spec's bound; an
  /// optional attribute that is absent gives the spec's default.
  double number(const char* name);
  /// The same for an optional attribute whose default the reader computes (spec: "(...)").
  double number(const char* name, double computedDefault);
  /// An index (kind Index): an integer >= 0, checked against the counts later; -1 after an error.
  int index(const char* name);
  /// A 0 or 1 (kind Flag).
  bool flag(const char* name);
  /// A word (kind Text); the spec's default when optional and absent.
  std::string text(const char* name);

  /// "file:line: <element>" for messages about the whole element.
  std::string where() const;
  /// "file:line: <element> attribute 'name'" for messages about one attribute.
  std::string where(const char* attribute) const;
  /// Reports an error; reading goes on, ok() becomes false.
  void fail(const char* attribute, const std::string& what);
  void fail(const std::string& what);
  bool ok() const { return ok_; }
  bool has(const char* attribute) const { return element_.FindAttribute(attribute) != nullptr; }
  int line() const { return element_.GetLineNum(); }
  const char* name() const { return element_.Name(); }

  /// Reports the attributes no read asked for (with "did you mean" for near misses), and the
  /// required ones that were missing with the unknown attribute that may have been meant.
  void reportUnknownAttributes();

 private:
  const AttributeSpec& declared(const char* name, bool numeric) const;
  const tinyxml2::XMLAttribute* find(const char* name);
  bool parseNumber(const tinyxml2::XMLAttribute& attribute, double& value);
  double checked(const AttributeSpec& spec, const tinyxml2::XMLAttribute& attribute);

  const tinyxml2::XMLElement& element_;
  const ElementSpec& spec_;
  SceneMessages& messages_;
  const std::string& file_;
  std::vector<std::string> asked_, missing_;
  bool ok_ = true;
};

}  // namespace fosssim::io
