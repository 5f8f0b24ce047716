// Internal header of options.cpp: the checks of one parse's values (CLI11 has split the words;
// each option's words are judged here, so that every message names the option and says what is
// wrong in the project's words).
#pragma once

#include "cli_values.h"
#include "options.h"

#include "fosssim/render/movie_writer.h"

#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace fosssim::app {

constexpr int kMaxFrameSide = 16384;  // OSMesa's and most encoders' limit
constexpr double kMinFps = render::kMinMovieFps, kMaxFps = render::kMaxMovieFps;  // as record_movie's

inline bool parseInt(const std::string& text, long lo, long hi, int& out) {
  long v = 0;
  if (!cli::parseInteger(text, lo, hi, v)) return false;
  out = static_cast<int>(v);
  return true;
}

/// The checks of one parse: each fails with a message in `error` and returns false.
class Judge {
 public:
  Judge(Options& o, std::string& error) : o_(o), error_(error) {}

  /// The single value of an option given at most once; false (and the error) when given twice or
  /// empty. `value` is left alone when the option is absent.
  bool single(const std::string& name, const std::vector<std::string>& given, std::string& value) {
    if (given.size() > 1) {
      std::string list;
      for (const std::string& v : given) list += (list.empty() ? "\"" : ", \"") + v + "\"";
      return fail("option " + name + " given " + std::to_string(given.size()) + " times (" + list +
                  "): give it once");
    }
    if (given.empty()) return true;
    // An empty path would silently mean "not given" (e.g. no -o file written).
    if (given[0].empty()) return fail("option " + name + " needs a value, got an empty one");
    value = given[0];
    return true;
  }
  bool flag(const std::string& name, const std::vector<std::string>& given, bool& out) {
    std::string v;
    if (!single(name, given, v)) return false;
    if (given.empty()) return true;
    if (v != "0" && v != "1") return fail("option " + name + " takes 0 or 1, got \"" + v + "\"");
    out = v == "1";
    return true;
  }
  bool integer(const std::string& name, const std::vector<std::string>& given, long hi, int& out,
               const std::string& expected) {
    std::string v;
    if (!single(name, given, v)) return false;
    if (!given.empty() && !parseInt(v, 1, hi, out))
      return fail("option " + name + " takes " + expected + ", got \"" + v + "\"" + cli::numberHint(v));
    return true;
  }
  bool frameSize(const std::vector<std::string>& given) {
    std::string v;
    if (!single("--frame-size", given, v)) return false;
    if (given.empty()) return true;
    const size_t x = v.find('x');
    if (x == std::string::npos || !parseInt(v.substr(0, x), 1, kMaxFrameSide, o_.frameWidth) ||
        !parseInt(v.substr(x + 1), 1, kMaxFrameSide, o_.frameHeight))
      return fail("option --frame-size takes WxH with sizes from 1 to " + std::to_string(kMaxFrameSide) + ", got \"" +
                  v + "\"" + cli::numberHint(v));
    return true;
  }
  /// --movie: a name MovieWriter writes as a movie (render::isMovieName), checked before the run.
  bool movie(const std::vector<std::string>& given) {
    if (!single("--movie", given, o_.movie)) return false;
    if (o_.movie.empty() || render::isMovieName(o_.movie)) return true;
    std::string ext = std::filesystem::path(o_.movie).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string hint = ext == ".png" ? " (PNG frames: -g 1)" : ext == ".svg" ? " (SVG frames: -m DIR)" : "";
    return fail("option --movie takes a movie file ending in " + render::movieEndings() + ", got \"" +
                o_.movie + "\"" + hint);
  }
  bool fps(const std::vector<std::string>& given) {
    std::string v;
    if (!single("--fps", given, v)) return false;
    if (given.empty()) return true;
    if (!cli::parseNumber(v, kMinFps, kMaxFps, o_.fps)) {
      std::ostringstream range;
      range << kMinFps << " to " << kMaxFps;
      return fail("option --fps takes a frame rate from " + range.str() + " (e.g. 25 or 29.97), got \"" + v + "\"" +
                  cli::numberHint(v));
    }
    return true;
  }
  bool fail(const std::string& message) {
    error_ = message;
    return false;
  }

 private:
  Options& o_;
  std::string& error_;
};

}  // namespace fosssim::app
