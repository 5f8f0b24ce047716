// Internal header: the loader's messages about one scene file, collected in one pass.
//
// Every problem of a file is reported, not only the first: errors and warnings are collected as
// the document is read, then put in line order (a typo's warning before the error it causes).
// Repeated warnings of one kind (10,000 unknown <foo> elements) are shown a few times and then
// counted, so that a large bad file gives a screenful, not megabytes.
#pragma once

#include "fosssim/io/scene_file.h"

#include <map>
#include <string>
#include <vector>

namespace fosssim::io {

class SceneMessages {
 public:
  explicit SceneMessages(std::string file) : file_(std::move(file)) {}

  /// "file:line: " (or "file: " for line 0, a message about the whole file).
  std::string at(int line) const;

  /// A warning about ignored input. `kind` groups repeats ("unknown element <foo>"); `plural`
  /// names them in the summary ("unknown elements <foo>").
  void warn(int line, const std::string& kind, const std::string& plural, const std::string& text);
  /// An error: the scene will not load.
  void error(int line, const std::string& text);

  long errors() const { return errorCount_; }
  long warnings() const { return warningCount_; }

  /// Moves the messages into `out` (line order, repeats summarised) and returns the Status:
  /// ok() without errors, else the first error (and how many more there are).
  Status finish(SceneFile& out);

  static constexpr int kShownPerKind = 3;    ///< repeats of one kind shown before counting
  static constexpr int kShownWarnings = 50;  ///< warnings shown in all before counting
  static constexpr int kShownErrors = 50;    ///< errors shown before counting

 private:
  struct Held {
    SceneMessage message;
    long order;  ///< arrival, to keep equal lines stable
  };
  struct Kind {
    std::string plural;
    long count = 0;
    long hidden = 0;
    int firstHiddenLine = 0, lastHiddenLine = 0;
    long order = 0;  ///< first arrival, for the summary's order
  };

  std::string file_;
  std::vector<Held> held_;
  std::map<std::string, Kind> kinds_;
  long warningCount_ = 0, errorCount_ = 0, shownWarnings_ = 0, arrivals_ = 0;
};

/// 12345 -> "12,345" (counts in messages).
std::string withThousands(long n);
/// A number as %g (no 300-digit times in messages).
std::string shortNumber(double value);
/// A name or word from the file as a message shows it: at most 40 characters, a longer one cut
/// with its length ("sss... (3,000,000 characters)"): a 3 MB type or element name was a 3 MB line.
std::string clip(const std::string& text);

}  // namespace fosssim::io
