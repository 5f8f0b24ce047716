#include "options.h"

#include <cerrno>
#include <cstdlib>
#include <vector>

namespace fosssim::app {
namespace {

bool parseFlag(const std::string& value, bool& out) {
  if (value == "0" || value == "1") {
    out = value == "1";
    return true;
  }
  return false;
}

bool parsePositiveInt(const std::string& value, int& out) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(value.c_str(), &end, 10);
  if (end == value.c_str() || *end != '\0' || errno == ERANGE || v <= 0 || v > 1000000) return false;
  out = static_cast<int>(v);
  return true;
}

}  // namespace

std::string usage() {
  return R"(usage: FOSSSim -s scene.xml [options]

Runs a FOSSSim scene (2D particles, edges and half-planes) from an XML scene file.

Reference options (same meanings and defaults as the course simulator):
  -s FILE        the scene file (required)
  -d 0|1         open a window (default 1); without a display FOSSSim says so and runs headless
  -p 0|1         start the window paused (default 1)
  -g 0|1         write a PNG frame after every step into pngs/frame00001.png, ... (default 0)
  -o FILE        write the trajectory to FILE (the reference's binary format)
  -i FILE        grade the trajectory in FILE against this simulator; prints "Overall success: ..."
  -m DIR         write an SVG picture of every step into DIR/frame00000000000000000001.svg, ...

FOSSSim options:
  --compat       reproduce the reference's own formulas where they differ from exact mathematics
                 (the particle-edge approach quintic); see the README, "Course compatibility"
  --verify       after every step check that no pair is left colliding and the state is finite;
                 report violations and exit non-zero when there was any
  --frame-size WxH   size of PNG and SVG frames, movies and the window (default 512x512)
  --frame-every K    write a frame (-g, -m, --movie) only after steps K, 2K, 3K, ...; frames are
                     still numbered 1, 2, 3, ... (default 1: after every step)
  --png-dir DIR      folder for -g frames (default pngs; created if needed)
  --movie FILE.mp4   pipe frames straight into ffmpeg (no PNG files); needs ffmpeg
  --fps N            frame rate of --movie (default 30)
  --threads N        threads for collision detection and the penalty force (default 1); the
                     results are the same for every N (scenes of a few thousand particles and up
                     use them)
  -q             no progress output
  -h, --help     this text

Window keys: space pause/resume, s single step, q/Esc quit, c re-centre, +/- zoom, arrows or mouse drag pan.
)";
}

bool parseOptions(int argc, char** argv, Options& o, std::string& error) {
  std::vector<std::string> args(argv + 1, argv + argc);
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    auto value = [&](std::string& out) {
      if (k + 1 >= args.size()) {
        error = "option " + a + " needs a value";
        return false;
      }
      out = args[++k];
      if (out.empty()) {  // an empty path would silently mean "not given" (e.g. no -o file written)
        error = "option " + a + " needs a value, got an empty one";
        return false;
      }
      return true;
    };
    auto flag = [&](bool& out) {
      std::string v;
      if (!value(v)) return false;
      if (!parseFlag(v, out)) {
        error = "option " + a + " takes 0 or 1, got \"" + v + "\"";
        return false;
      }
      return true;
    };
    auto positive = [&](int& out) {
      std::string v;
      if (!value(v)) return false;
      if (!parsePositiveInt(v, out)) {
        error = "option " + a + " takes a positive integer, got \"" + v + "\"";
        return false;
      }
      return true;
    };
    bool ok = true;
    if (a == "-h" || a == "--help") o.help = true;
    else if (a == "-s") ok = value(o.scene);
    else if (a == "-d") ok = flag(o.display);
    else if (a == "-p") ok = flag(o.paused);
    else if (a == "-g") ok = flag(o.pngs);
    else if (a == "-o") ok = value(o.output);
    else if (a == "-i") ok = value(o.input);
    else if (a == "-m") ok = value(o.svgDir);
    else if (a == "-q") o.quiet = true;
    else if (a == "--compat") o.compat = true;
    else if (a == "--verify") o.verify = true;
    else if (a == "--title-card") o.titleCard = true;
    else if (a == "--keep-open") o.keepOpen = true;
    else if (a == "--strict") o.strict = true;
    else if (a == "--check") o.check = true;
    else if (a == "--compact") o.compact = true;
    else if (a == "--version") o.version = true;
    else if (a == "--frame-every") ok = positive(o.frameEvery);
    else if (a == "--threads") ok = positive(o.threads);
    else if (a == "--png-dir") ok = value(o.pngDir);
    else if (a == "--movie") ok = value(o.movie);
    else if (a == "--fps") {
      int fps = 0;
      ok = positive(fps);
      o.fps = fps;
    } else if (a == "--frame-size") {
      std::string v;
      ok = value(v);
      const size_t x = v.find('x');
      if (ok && (x == std::string::npos || !parsePositiveInt(v.substr(0, x), o.frameWidth) ||
                 !parsePositiveInt(v.substr(x + 1), o.frameHeight) || o.frameWidth > 16384 || o.frameHeight > 16384)) {
        error = "option --frame-size takes WxH with sizes from 1 to 16384, got \"" + v + "\"";
        ok = false;
      }
    } else {
      error = "unknown option \"" + a + "\" (FOSSSim -h lists the options)";
      ok = false;
    }
    if (!ok) return false;
  }
  if (o.help || o.version) return true;
  if (o.scene.empty()) {
    error = "no scene file given: use -s scene.xml (FOSSSim -h lists the options)";
    return false;
  }
  if (!o.output.empty() && !o.input.empty()) {
    error = "-o (write a trajectory) and -i (grade one) cannot be used together";
    return false;
  }
  return true;
}

}  // namespace fosssim::app
