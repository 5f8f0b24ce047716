// Internal header: what is wrong with a file that tinyxml2 would not parse, in words.
//
// tinyxml2 reports an error code and a line, and for some errors the wrong line (a missing
// </scene> is "XML_ERROR_PARSING" on line 1). When it fails, this scanner walks the text itself
// and names the first problem it understands: an element left open at the end of the file (and
// where it was opened), a closing tag that does not match, an attribute given twice or without
// quotes, a comment that never ends. What it does not recognise keeps tinyxml2's code, in words.
#pragma once

#include <string>

namespace fosssim::io {

/// The text with every line end (\r\n, \r, \n) made \n, as XML prescribes: tinyxml2 counts lines
/// by \n only, so a file with old Mac line ends (\r) would report every problem on line 1.
std::string normalizeLineEnds(const std::string& text);

/// The 1-based line of byte `offset` in `text`, counting \r\n, \r and \n as line ends.
int lineOf(const std::string& text, size_t offset);

/// XML's white space: space, tab and the line ends.
inline constexpr const char* kXmlSpace = " \t\n\r";
/// Whether c is one of kXmlSpace's characters.
inline bool isXmlSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
/// Whether c may start an XML name (ASCII letters, '_', ':', and every byte of a multi-byte
/// UTF-8 character, which the scans take as name characters without decoding them) ...
inline bool isXmlNameStart(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':' ||
         static_cast<unsigned char>(c) >= 0x80;
}
/// ... or continue one (digits, '-' and '.' too).
inline bool isXmlNameChar(char c) { return isXmlNameStart(c) || (c >= '0' && c <= '9') || c == '-' || c == '.'; }

/// `text` without the XML white space around it.
inline std::string trimXmlSpace(const std::string& text) {
  const size_t from = text.find_first_not_of(kXmlSpace);
  return from == std::string::npos ? std::string() : text.substr(from, text.find_last_not_of(kXmlSpace) + 1 - from);
}

struct XmlProblem {
  int line = 0;
  std::string what;  ///< "not well-formed XML: ..."
};

/// Explains why tinyxml2 rejected `text` (line ends normalised) with `errorId` on `errorLine`.
XmlProblem explainXmlError(const std::string& text, int errorId, int errorLine);

/// The most attributes one element may have. tinyxml2 compares each attribute with the element's
/// earlier ones (it refuses repeats), so parsing takes time growing with the square of their
/// number: 40,000 on one element took 8 s, 200,000 over a minute. The scene format's elements
/// take at most 7.
inline constexpr long kMaxAttributes = 1000;

struct CrowdedElement {
  int line = 0;
  std::string name;
  long attributes = 0;  ///< how many it has (all of them, counted)
};

/// Finds the first element of `text` with more than kMaxAttributes attributes, in time linear in
/// the text, before tinyxml2 parses it. Comments, CDATA, declarations and quoted values are
/// skipped; a tag it cannot read is left to the parser (and explainXmlError).
bool findCrowdedElement(const std::string& text, CrowdedElement& found);

/// A control character XML 1.0 forbids: U+0000 to U+001F other than tab, line feed and carriage
/// return (the loader refuses them, and the writer does not write them).
inline bool isForbiddenControl(unsigned code) { return code < 0x20 && code != '\t' && code != '\n' && code != '\r'; }

/// "U+001B": a code point as messages name it.
std::string codePointName(unsigned code);

struct ControlCharacter {
  size_t offset = 0;   ///< where it (or its reference) begins
  unsigned code = 0;   ///< U+0000 to U+001F; from a reference also a surrogate, U+FFFE, U+FFFF or 0x110000 (beyond)
  std::string written; ///< the reference as written ("&#27;"), empty for the byte itself
};

/// Finds the first character XML 1.0 forbids in a document, U+0000 to U+001F other than tab, line
/// feed and carriage return, as a byte or as a character reference ("&#27;", "&#x1B;"; those in
/// comments and CDATA are text, not references), and a reference to what is no character at all
/// (a surrogate half, U+FFFE, U+FFFF, beyond U+10FFFF). tinyxml2 accepts them, and a description
/// with an escape sequence reached the terminal as one.
bool findControlCharacter(const std::string& text, ControlCharacter& found);

struct InvalidUtf8 {
  size_t offset = 0;     ///< the first byte of the sequence that is no UTF-8
  std::string why;       ///< "bytes that are not UTF-8, 0xE9 followed by 0x20 (not a UTF-8 character)"
  bool utf8 = false;     ///< UTF-8, but a character XML does not allow (U+FFFE, U+FFFF)
};

/// Finds the first bytes of `text` that are not UTF-8 (XML's encoding unless declared otherwise,
/// and the only one the loader reads): a byte that begins no character (0x80 to 0xC1, 0xF5 to
/// 0xFF), a character cut short or written with more bytes than it needs, a surrogate half, or
/// U+FFFE and U+FFFF, which XML does not allow. tinyxml2 passed such bytes through: a Latin-1
/// "é" (0xE9) reached the window and the terminal as garbage.
bool findInvalidUtf8(const std::string& text, InvalidUtf8& found);

/// The 1-based column of byte `offset` in `text`, in characters (UTF-8 continuation bytes do not
/// count, nor a byte-order mark), from the line's start (after \n or \r).
int columnOf(const std::string& text, size_t offset);

}  // namespace fosssim::io
