// Internal header: numbers in grading messages, each in its shortest form that reads back to the
// same double, so that two values printed differently really differ and equal-looking ones do not.
#pragma once

#include "fosssim/core/types.h"

#include <charconv>
#include <string>

namespace fosssim::grade_text {

inline std::string num(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

inline std::string vec(const Vec2& v) { return "(" + num(v.x()) + ", " + num(v.y()) + ")"; }

inline std::string list(const double* c, int n) {
  std::string s = "(";
  for (int k = 0; k < n; ++k) s += (k ? ", " : "") + num(c[k]);
  return s + ")";
}

}  // namespace fosssim::grade_text
