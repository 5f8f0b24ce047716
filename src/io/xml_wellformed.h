// Internal header: well-formedness that tinyxml2 does not check.
//
// tinyxml2 is lenient where XML 1.0 is not, and the file then loaded as something other than what
// it says: an undefined entity ("&h;") was kept as the text "&h;", a bare '&' or '<' inside an
// attribute value was taken as a character, and a declaration of another XML version or encoding
// (<?xml version="2.0" encoding="UTF-16"?>) was ignored while the bytes were read as UTF-8 XML 1.0.
// Two attributes without a space between them (a="1"b="2") stay accepted: the course's scenes
// have them (SceneLoader.LenientAttributeSyntaxOfTheCourseScenes).
// This scan finds the first such fault, before tinyxml2 parses, in time linear in the text.
// Control characters and bytes that are no UTF-8 are found by xml_syntax.h; what this scan does not
// understand (an unterminated tag or comment) it leaves to the parser and explainXmlError.
#pragma once

#include <string>

namespace fosssim::io {

struct MarkupFault {
  size_t offset = 0;  ///< the byte where the fault begins (for lineOf and columnOf)
  std::string what;   ///< "an undefined entity &h; (...)"
};

/// Finds the first fault above in `text` (the file as read; a UTF-8 byte-order mark is skipped).
bool findMarkupFault(const std::string& text, MarkupFault& found);

}  // namespace fosssim::io
