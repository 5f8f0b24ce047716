// Internal header: numbers in the core's messages.
#pragma once

#include <cstdio>
#include <string>

namespace fosssim {

/// printf's %g: "last update 3.2e-07" and "t = 0.01", neither to_string's "0.000000" nor a
/// 300-digit time.
inline std::string shortNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

}  // namespace fosssim
