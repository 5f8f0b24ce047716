// Numbers as they read in the study's titles ("COR 0.5", "15 disks", "three disks"): titles are
// formatted from the constants the scenes use, so changing a constant cannot leave a title that
// tells another story (no number of the study is typed by hand).
#pragma once

#include <cstdio>
#include <string>

namespace fosssim::study {

/// Shortest plain form, up to 6 significant digits: 1 -> "1", 0.5 -> "0.5", 0.02 -> "0.02",
/// 0.4084 at 2 digits -> "0.41".
inline std::string numberText(double value, int digits = 6) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

/// A small count as a word (zero to ten), larger ones in digits.
inline std::string countWord(int n) {
  static const char* const kWords[] = {"zero", "one", "two", "three", "four", "five",
                                       "six",  "seven", "eight", "nine", "ten"};
  return n >= 0 && n <= 10 ? kWords[n] : std::to_string(n);
}

}  // namespace fosssim::study
