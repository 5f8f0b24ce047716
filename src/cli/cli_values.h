// Number checks for the command lines, with messages that say what was expected and what came
// (CLI11 2.1's own checks print "Value abc not in range 0.000000 to 1797693...": no help to anyone),
// and the common ending of a bad command line: exit status 2.
#pragma once

#include <CLI/CLI.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace fosssim::cli {

/// Exit status of a bad command line, for every program of the project.
constexpr int kExitUsage = 2;

/// `text` starts as a number written on a command line does: a digit, or '-' (or '.') and then
/// one. strtol and strtod skip leading spaces and take a '+', so " 5" (a quoting slip) and "+5"
/// were read as 5; a scene file allows spaces around numbers, but a word of the command line is
/// the value itself.
inline bool startsAsNumber(const std::string& text) {
  const size_t k = !text.empty() && text[0] == '-' ? 1 : 0;
  return k < text.size() && (std::isdigit(static_cast<unsigned char>(text[k])) || text[k] == '.');
}

/// " (spaces and a '+' sign are not read)" for a value that has either; "" otherwise: what a
/// message about a refused number adds.
inline std::string numberHint(const std::string& text) {
  return text.find_first_of(" \t\n\r+") != std::string::npos ? " (spaces and a '+' sign are not read)" : "";
}

/// `text` as a whole decimal integer in [lo, hi].
inline bool parseInteger(const std::string& text, long lo, long hi, long& out) {
  if (!startsAsNumber(text)) return false;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end == text.c_str() || *end != '\0' || errno == ERANGE || v < lo || v > hi) return false;
  out = v;
  return true;
}

/// `text` as a whole finite decimal number in [lo, hi] ("29.97", "1e5"). strtod also reads
/// hexadecimal ("0x10" is 16), which the scene loader refuses too: no one means it.
inline bool parseNumber(const std::string& text, double lo, double hi, double& out) {
  if (!startsAsNumber(text)) return false;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end == text.c_str() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) return false;
  if (text.find_first_of("xX") != std::string::npos) return false;
  out = v;
  return true;
}

/// A CLI11 check: an integer from lo to hi. Its message: "expected an integer from 1 to 100, got \"abc\"".
inline CLI::Validator integerIn(long lo, long hi) {
  const std::string expected = "an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [=](std::string& text) {
        long v = 0;
        return parseInteger(text, lo, hi, v) ? std::string()
                                             : "expected " + expected + ", got \"" + text + "\"" + numberHint(text);
      },
      "");  // no description: -h shows each option's own (CLI11 would append this one to the type)
}

/// "a, b, c": names for a message or -h.
inline std::string listed(const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

/// A CLI11 check: one of `names` (a scene kind, a collision type). Its message: "unknown scene
/// \"snow\" (one of rain, gas, chains, bullets)".
inline CLI::Validator oneOf(const std::string& what, const std::vector<std::string>& names) {
  const std::string list = listed(names);
  return CLI::Validator(
      [=](std::string& text) {
        for (const std::string& n : names)
          if (n == text) return std::string();
        return "unknown " + what + " \"" + text + "\" (one of " + list + ")";
      },
      "");
}

/// Parses argv into `app`. Returns -1 when the program should go on; otherwise the exit status
/// (0 after printing -h's text to stdout, kExitUsage after printing "program: what is wrong
/// (program -h lists the options)" to stderr).
inline int parseCommandLine(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
    return -1;
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);
    return 0;
  } catch (const CLI::ParseError& e) {
    const char* name = app.get_name().c_str();
    std::fprintf(stderr, "%s: %s (%s -h lists the options)\n", name, e.what(), name);
    return kExitUsage;
  }
}

}  // namespace fosssim::cli
