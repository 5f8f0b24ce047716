#include "xml_syntax.h"

#include "scene_messages.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace fosssim::io {
namespace {

std::string excerpt(const std::string& text, size_t from) {
  std::string s;
  for (size_t k = from; k < text.size() && text[k] != '\n' && s.size() < 30; ++k) s += text[k];
  return "\"" + s + (s.size() >= 30 ? "...\"" : "\"");
}

/// The scanner: finds the first problem it can name, or none.
class Scanner {
 public:
  explicit Scanner(const std::string& text) : t_(text) {}

  bool scan(XmlProblem& problem) {
    if (t_.compare(0, 3, "\xEF\xBB\xBF") == 0) p_ = 3;
    while (p_ < t_.size()) {
      const bool ok = t_[p_] != '<' ? text() : starts("<!--") ? until("-->", "a comment (<!--)")
                                               : starts("<![CDATA[") ? until("]]>", "a CDATA section")
                                               : starts("<!") ? until(">", "a declaration (<!...>)")
                                               : starts("<?") ? declaration()
                                               : starts("</") ? closingTag() : openingTag();
      if (!ok) {
        problem = problem_;
        return true;
      }
    }
    if (stack_.empty()) return false;
    std::string open, missing;
    for (size_t k = stack_.size(); k-- > 0;) {
      open += (open.empty() ? ""
               : k == 0     ? " and "
                            : ", ") +
              ("<" + clip(stack_[k].name) + "> (line " + std::to_string(stack_[k].line) + ")");
      missing += "</" + clip(stack_[k].name) + ">";
    }
    int last = line_;
    if (!t_.empty() && t_.back() == '\n') --last;
    problem = {std::max(last, 1), "not well-formed XML: the file ends with " + open + " still open: " + missing +
                                       " is missing"};
    return true;
  }

 private:
  struct Open {
    std::string name;
    int line;
  };

  bool starts(const char* s) const { return t_.compare(p_, std::char_traits<char>::length(s), s) == 0; }
  void advanceTo(size_t q) {
    q = std::min(q, t_.size());
    line_ += static_cast<int>(std::count(t_.begin() + static_cast<long>(p_), t_.begin() + static_cast<long>(q), '\n'));
    p_ = q;
  }
  bool fail(const std::string& what) {
    problem_ = {line_, "not well-formed XML: " + what};
    return false;
  }

  bool text() {
    size_t q = t_.find('<', p_);
    if (q == std::string::npos) q = t_.size();
    if (stack_.empty()) {
      const size_t k = t_.find_first_not_of(kXmlSpace, p_);
      if (k < q) {
        advanceTo(k);
        return fail("text " + excerpt(t_, k) +
                    (rootClosed_ ? " after the root element's end" : " outside any element"));
      }
    }
    advanceTo(q);
    return true;
  }

  bool until(const char* end, const char* what) {
    const size_t q = t_.find(end, p_ + 2);
    if (q == std::string::npos) return fail(std::string(what) + " opened here never ends (" + end + " is missing)");
    advanceTo(q + std::char_traits<char>::length(end));
    return true;
  }

  bool declaration() {
    if (!stack_.empty())
      return fail("a <?...?> declaration inside <" + clip(stack_.back().name) +
                  ">: declarations may only open the file");
    return until("?>", "a declaration (<?)");
  }

  std::string name(size_t& q) const {
    const size_t from = q;
    while (q < t_.size() && isXmlNameChar(t_[q])) ++q;
    return t_.substr(from, q - from);
  }

  bool closingTag() {
    size_t q = p_ + 2;
    const std::string n = name(q);
    while (q < t_.size() && isXmlSpace(t_[q])) ++q;
    if (n.empty() || q >= t_.size() || t_[q] != '>')
      return fail("a closing tag </" + clip(n) + " must be a name followed by '>'");
    if (stack_.empty()) return fail("</" + clip(n) + "> closes no open element");
    const Open& top = stack_.back();
    if (top.name != n) {
      // The fix belongs where the unclosed element opens: report it there.
      for (const Open& o : stack_)
        if (o.name == n) {
          problem_ = {top.line, "not well-formed XML: <" + clip(top.name) + "> is never closed (</" + clip(n) +
                                    "> on line " + std::to_string(line_) + " comes first): end it with /> or add </" +
                                    clip(top.name) + ">"};
          return false;
        }
      return fail("</" + clip(n) + "> does not match the open <" + clip(top.name) + "> (line " +
                  std::to_string(top.line) + ")");
    }
    stack_.pop_back();
    if (stack_.empty()) rootClosed_ = true;
    advanceTo(q + 1);
    return true;
  }

  bool openingTag() {
    size_t q = p_ + 1;
    if (q >= t_.size() || !isXmlNameStart(t_[q]))
      return fail("'<' does not begin an element (a name must follow it; write &lt; for a '<' in text)");
    const int tagLine = line_;
    const std::string element = name(q);
    std::vector<std::string> attributes;
    for (;;) {
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      advanceTo(q);
      if (q >= t_.size())
        return fail("the file ends inside the tag <" + clip(element) + "> (line " + std::to_string(tagLine) + ")");
      if (t_[q] == '/') {
        if (q + 1 >= t_.size() || t_[q + 1] != '>')
          return fail("'/' in the tag <" + clip(element) + "> must be followed by '>'");
        advanceTo(q + 2);
        return true;
      }
      if (t_[q] == '>') {
        stack_.push_back({element, tagLine});
        advanceTo(q + 1);
        return true;
      }
      if (!isXmlNameStart(t_[q]))
        return fail("unexpected character '" + std::string(1, t_[q]) + "' in the tag <" + clip(element) + ">");
      const std::string attribute = name(q);
      const std::string who = "<" + clip(element) + "> attribute '" + clip(attribute) + "'";
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || t_[q] != '=') return fail(who + " has no value (write " + clip(attribute) + "=\"...\")");
      ++q;
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || (t_[q] != '"' && t_[q] != '\''))
        return fail(who + ": the value must be in quotes (" + clip(attribute) + "=\"...\")");
      const size_t close = t_.find(t_[q], q + 1);
      if (close == std::string::npos)
        return fail(who + ": the value's closing quote (" + std::string(1, t_[q]) + ") is missing");
      if (std::find(attributes.begin(), attributes.end(), attribute) != attributes.end())
        return fail(who + " is given twice (an attribute may appear once)");
      attributes.push_back(attribute);
      q = close + 1;
    }
  }

  const std::string& t_;
  size_t p_ = 0;
  int line_ = 1;
  std::vector<Open> stack_;
  bool rootClosed_ = false;
  XmlProblem problem_;
};

std::string inWords(int errorId) {
  switch (errorId) {
    case tinyxml2::XML_ERROR_PARSING_ELEMENT: return "an element is malformed";
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
      return "an attribute is malformed (write name=\"value\", each name once)";
    case tinyxml2::XML_ERROR_PARSING_TEXT: return "text where it cannot be";
    case tinyxml2::XML_ERROR_PARSING_CDATA: return "a CDATA section is malformed";
    case tinyxml2::XML_ERROR_PARSING_COMMENT: return "a comment is malformed";
    case tinyxml2::XML_ERROR_PARSING_DECLARATION: return "a <?...?> declaration is malformed or misplaced";
    case tinyxml2::XML_ERROR_PARSING_UNKNOWN: return "a <!...> declaration is malformed";
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT: return "a closing tag does not match the element it closes";
    case tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED: return "elements are nested too deeply";
    default: return "the document cannot be parsed";
  }
}

}  // namespace

std::string normalizeLineEnds(const std::string& text) {
  if (text.find('\r') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size());
  for (size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '\r') out += text[k];
    else {
      out += '\n';
      if (k + 1 < text.size() && text[k + 1] == '\n') ++k;
    }
  }
  return out;
}

int lineOf(const std::string& text, size_t offset) {
  int line = 1;
  for (size_t k = 0; k < offset && k < text.size(); ++k)
    if (text[k] == '\n' || (text[k] == '\r' && (k + 1 >= text.size() || text[k + 1] != '\n'))) ++line;
  return line;
}

bool findCrowdedElement(const std::string& text, CrowdedElement& found) {
  const size_t size = text.size();
  auto skipSpace = [&](size_t q) {
    while (q < size && isXmlSpace(text[q])) ++q;
    return q;
  };
  auto skipPast = [&](size_t from, const char* end) {  // npos when `end` never comes
    const size_t q = text.find(end, from);
    return q == std::string::npos ? q : q + std::char_traits<char>::length(end);
  };
  size_t p = 0;
  while ((p = text.find('<', p)) != std::string::npos) {
    const size_t tag = p;
    if (text.compare(p, 4, "<!--") == 0) p = skipPast(p + 4, "-->");
    else if (text.compare(p, 9, "<![CDATA[") == 0) p = skipPast(p + 9, "]]>");
    else if (text.compare(p, 2, "<?") == 0) p = skipPast(p + 2, "?>");
    else if (p + 1 < size && isXmlNameStart(text[p + 1])) {
      size_t q = p + 1;
      while (q < size && isXmlNameChar(text[q])) ++q;
      long count = 0;
      // name = "value" pairs up to the tag's end; anything else ends the count (the parser reports it).
      for (;;) {
        q = skipSpace(q);
        if (q >= size || !isXmlNameStart(text[q])) break;
        while (q < size && isXmlNameChar(text[q])) ++q;
        q = skipSpace(q);
        if (q >= size || text[q] != '=') break;
        q = skipSpace(q + 1);
        if (q >= size || (text[q] != '"' && text[q] != '\'')) break;
        const size_t close = text.find(text[q], q + 1);
        if (close == std::string::npos) break;
        ++count;
        q = close + 1;
      }
      if (count > kMaxAttributes) {
        size_t n = tag + 1;
        while (n < size && isXmlNameChar(text[n])) ++n;
        found = {lineOf(text, tag), text.substr(tag + 1, n - tag - 1), count};
        return true;
      }
      p = q;
    } else {
      p = tag + 1;  // "</name>", "<!DOCTYPE ...>", or a stray '<': nothing to count
    }
    if (p == std::string::npos) return false;  // the file ends in a comment: the parser says so
  }
  return false;
}

std::string codePointName(unsigned code) {
  char name[16];
  std::snprintf(name, sizeof name, "U+%04X", code);
  return name;
}

bool findControlCharacter(const std::string& text, ControlCharacter& found) {
  const auto forbidden = isForbiddenControl;
  const size_t size = text.size();
  size_t verbatimEnd = 0;  // inside a comment or CDATA section up to here: '&' is text there
  for (size_t p = 0; p < size; ++p) {
    const auto byte = static_cast<unsigned char>(text[p]);
    if (forbidden(byte)) {
      found = {p, byte, ""};
      return true;
    }
    if (p < verbatimEnd || (byte != '<' && byte != '&')) continue;
    if (byte == '<') {
      const char* end = text.compare(p, 4, "<!--") == 0        ? "-->"
                        : text.compare(p, 9, "<![CDATA[") == 0 ? "]]>"
                                                               : nullptr;
      if (end) verbatimEnd = std::min(size, text.find(end, p + 4));  // unclosed: the rest (the parser reports it)
      continue;
    }
    if (p + 2 >= size || text[p + 1] != '#') continue;
    const bool hex = text[p + 2] == 'x';
    size_t q = p + (hex ? 3 : 2);
    unsigned long code = 0;  // held at 0x110000 once beyond Unicode (no overflow for any number of digits)
    const size_t digitsFrom = q;
    for (; q < size; ++q) {
      const char c = text[q];
      const int digit = c >= '0' && c <= '9' ? c - '0'
                        : hex && c >= 'a' && c <= 'f' ? c - 'a' + 10
                        : hex && c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
      if (digit < 0) break;
      code = std::min(code * (hex ? 16 : 10) + static_cast<unsigned long>(digit), 0x110000UL);
    }
    if (q == digitsFrom || q >= size || text[q] != ';') continue;
    // XML's characters besides the controls: no surrogate halves, U+FFFE or U+FFFF, nothing beyond
    // U+10FFFF. tinyxml2 wrote a reference to one as bytes that are no UTF-8, or as nothing.
    const bool noCharacter =
        code < 0x20 ? forbidden(static_cast<unsigned>(code))
                    : (code >= 0xD800 && code <= 0xDFFF) || code == 0xFFFE || code == 0xFFFF || code > 0x10FFFF;
    if (!noCharacter) continue;
    found = {p, static_cast<unsigned>(code), text.substr(p, q + 1 - p)};
    return true;
  }
  return false;
}

bool findInvalidUtf8(const std::string& text, InvalidUtf8& found) {
  const size_t size = text.size();
  auto hex = [](unsigned b) {
    char name[8];
    std::snprintf(name, sizeof name, "0x%02X", b);
    return std::string(name);
  };
  auto notUtf8 = [&](size_t p, unsigned lead, const std::string& detail) {
    found = {p, "bytes that are not UTF-8, " + hex(lead) + detail};
    return true;
  };
  for (size_t p = 0; p < size;) {
    const auto lead = static_cast<unsigned char>(text[p]);
    if (lead < 0x80) {
      ++p;
      continue;
    }
    // Unicode's table of well-formed sequences: the lead byte fixes the length and the range of
    // the second byte (which excludes overlong forms, surrogates and code points beyond U+10FFFF).
    size_t length = 0;
    unsigned low = 0x80, high = 0xBF;
    if (lead >= 0xC2 && lead <= 0xDF) length = 2;
    else if (lead >= 0xE0 && lead <= 0xEF)
      length = 3, low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
    else if (lead >= 0xF0 && lead <= 0xF4)
      length = 4, low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
    if (length == 0)
      return notUtf8(p, lead, lead < 0xC0 ? " (a continuation byte, with no character begun before it)"
                                          : " (no UTF-8 character begins with it)");
    for (size_t k = 1; k < length; ++k) {
      if (p + k >= size)
        return notUtf8(p, lead, " at the end of the file (a UTF-8 character of " + std::to_string(length) +
                                    " bytes, cut short)");
      const auto next = static_cast<unsigned char>(text[p + k]);
      if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF))
        return notUtf8(p, lead, " followed by " + hex(next) + " (not a UTF-8 character)");
    }
    if (lead == 0xEF && static_cast<unsigned char>(text[p + 1]) == 0xBF &&
        static_cast<unsigned char>(text[p + 2]) >= 0xBE) {
      const unsigned code = static_cast<unsigned char>(text[p + 2]) == 0xBE ? 0xFFFE : 0xFFFF;
      found = {p,
               "the character " + codePointName(code) + " (bytes 0xEF 0xBF " +
                   hex(static_cast<unsigned char>(text[p + 2])) + "), which XML does not allow",
               true};
      return true;
    }
    p += length;
  }
  return false;
}

int columnOf(const std::string& text, size_t offset) {
  size_t start = offset;
  while (start > 0 && text[start - 1] != '\n' && text[start - 1] != '\r') --start;
  if (start == 0 && text.compare(0, 3, "\xEF\xBB\xBF") == 0 && offset >= 3) start = 3;  // the byte-order mark
  int column = 1;
  for (size_t p = start; p < offset && p < text.size(); ++p)
    if ((static_cast<unsigned char>(text[p]) & 0xC0) != 0x80) ++column;
  return column;
}

XmlProblem explainXmlError(const std::string& text, int errorId, int errorLine) {
  XmlProblem problem;
  if (errorId != tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED && Scanner(text).scan(problem)) return problem;
  return {std::max(errorLine, 1), "not well-formed XML: " + inWords(errorId)};
}

}  // namespace fosssim::io
