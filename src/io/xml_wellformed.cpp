#include "xml_wellformed.h"

#include "scene_messages.h"  // clip
#include "xml_syntax.h"     // isXmlSpace, isXmlNameStart

#include <cctype>

namespace fosssim::io {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

class Scan {
 public:
  Scan(const std::string& text, MarkupFault& found) : t_(text), found_(found) {}

  bool run() {
    size_t p = t_.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    const size_t documentStart = p;
    while (p < t_.size()) {
      if (t_[p] == '&') {
        if (!reference(p)) return true;
        ++p;
      } else if (t_[p] != '<') {
        ++p;
      } else if (starts(p, "<!--")) {
        p = past(p + 4, "-->");
      } else if (starts(p, "<![CDATA[")) {
        p = past(p + 9, "]]>");
      } else if (starts(p, "<?")) {
        if (p == documentStart && starts(p, "<?xml") && p + 5 < t_.size() && isXmlSpace(t_[p + 5]) &&
            !declaration(p + 5))
          return true;
        p = past(p + 2, "?>");
      } else if (starts(p, "<!")) {
        p = doctypeEnd(p);
      } else if (starts(p, "</")) {
        p = past(p + 2, ">");
      } else {
        p = tag(p);
        if (failed_) return true;
      }
    }
    return false;
  }

 private:
  bool starts(size_t p, const char* s) const { return t_.compare(p, std::char_traits<char>::length(s), s) == 0; }
  /// Just past the next `end`, or the end of the text (the parser reports what never ends).
  size_t past(size_t from, const char* end) const {
    const size_t q = t_.find(end, from);
    return q == std::string::npos ? t_.size() : q + std::char_traits<char>::length(end);
  }
  /// <!DOCTYPE ...> with or without an internal subset in [ ].
  size_t doctypeEnd(size_t p) const {
    const size_t close = t_.find('>', p), open = t_.find('[', p);
    if (open != std::string::npos && open < close) return past(past(open, "]"), ">");
    return close == std::string::npos ? t_.size() : close + 1;
  }
  bool fail(size_t at, const std::string& what) {
    found_ = {at, what};
    failed_ = true;
    return false;
  }

  /// '&' at p: one of XML's five entities or a character reference (whose character
  /// findControlCharacter judges), nothing else.
  bool reference(size_t p) {
    size_t q = p + 1;
    if (q < t_.size() && t_[q] == '#') {
      const bool hex = q + 1 < t_.size() && t_[q + 1] == 'x';
      q += hex ? 2 : 1;
      const size_t digits = q;
      auto digit = [hex](char c) {
        const auto u = static_cast<unsigned char>(c);
        return hex ? std::isxdigit(u) != 0 : std::isdigit(u) != 0;
      };
      while (q < t_.size() && digit(t_[q])) ++q;
      if (q > digits && q < t_.size() && t_[q] == ';') return true;
      return fail(p, "a malformed character reference " + clip(t_.substr(p, q + 1 - p)) +
                         " (write &#NNN; or &#xHHH;, or &amp; for an '&')");
    }
    while (q < t_.size() && isXmlNameChar(t_[q]) && q - p < 40) ++q;
    const std::string name = t_.substr(p + 1, q - p - 1);
    if (name.empty() || q >= t_.size() || t_[q] != ';')
      return fail(p, "a bare '&' (write &amp; for an ampersand)");
    for (const char* known : {"lt", "gt", "amp", "apos", "quot"})
      if (name == known) return true;
    return fail(p, "an undefined entity &" + clip(name) +
                       "; (XML defines &lt; &gt; &amp; &apos; &quot; and FOSSSim reads no others; write &amp;" +
                       clip(name) + "; for the text)");
  }

  /// An element's tag at p: its attributes' values. Returns where scanning goes on: past the
  /// tag's '>' when it cannot read on (the parser reports why).
  size_t tag(size_t p) {
    size_t q = p + 1;
    if (q >= t_.size() || !isXmlNameStart(t_[q])) return q;  // a stray '<': the parser reports it
    while (q < t_.size() && isXmlNameChar(t_[q])) ++q;
    const std::string element = clip(t_.substr(p + 1, q - p - 1));
    for (;;) {
      // No space between attributes (py="2.5"vx="0") is not XML either, but the course's own
      // scenes have it (conformance t2m1/CORTests/test02.xml): it stays accepted, without a word.
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || t_[q] == '>' || t_[q] == '/') return q;
      if (!isXmlNameStart(t_[q])) return past(q, ">");
      const size_t nameAt = q;
      while (q < t_.size() && isXmlNameChar(t_[q])) ++q;
      const std::string name = clip(t_.substr(nameAt, q - nameAt));
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || t_[q] != '=') return past(q, ">");
      ++q;
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || (t_[q] != '"' && t_[q] != '\'')) return past(q, ">");
      const size_t close = t_.find(t_[q], q + 1);
      if (close == std::string::npos) return t_.size();
      for (size_t k = q + 1; k < close; ++k) {
        if (t_[k] == '<') {
          fail(k, "a '<' in the value of <" + element + "> attribute '" + name + "' (write &lt;)");
          return q;
        }
        if (t_[k] == '&' && !reference(k)) return q;
      }
      q = close + 1;
    }
  }

  /// <?xml version="1.0" encoding="UTF-8" standalone="yes"?> from just after "<?xml".
  bool declaration(size_t q) {
    for (;;) {
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || !isXmlNameStart(t_[q])) return true;  // "?>" or what the parser reports
      const size_t nameAt = q;
      while (q < t_.size() && isXmlNameChar(t_[q])) ++q;
      const std::string name = t_.substr(nameAt, q - nameAt);
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || t_[q] != '=') return true;
      ++q;
      while (q < t_.size() && isXmlSpace(t_[q])) ++q;
      if (q >= t_.size() || (t_[q] != '"' && t_[q] != '\'')) return true;
      const size_t close = t_.find(t_[q], q + 1);
      if (close == std::string::npos) return true;
      const std::string value = t_.substr(q + 1, close - q - 1);
      // XML 1.0 (fifth edition) reads any 1.x document as 1.0; 2.0 is no XML at all.
      if (name == "version" && (value.size() < 3 || value.compare(0, 2, "1.") != 0 ||
                                value.find_first_not_of("0123456789", 2) != std::string::npos))
        return fail(nameAt, "the declaration's version=\"" + clip(value) + "\": a scene file is XML 1.0 (write "
                            "version=\"1.0\")");
      // The loader reads UTF-8 only (US-ASCII is part of it): a file declared otherwise was read
      // as UTF-8 anyway, whatever its bytes meant.
      if (name == "encoding" && lower(value) != "utf-8" && lower(value) != "us-ascii")
        return fail(nameAt, "the declaration's encoding=\"" + clip(value) + "\": the loader reads UTF-8 only (save the "
                            "file as UTF-8 and write encoding=\"UTF-8\", or no encoding)");
      q = close + 1;
    }
  }

  const std::string& t_;
  MarkupFault& found_;
  bool failed_ = false;
};

}  // namespace

bool findMarkupFault(const std::string& text, MarkupFault& found) { return Scan(text, found).run(); }

}  // namespace fosssim::io
