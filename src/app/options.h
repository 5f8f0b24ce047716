// The command line, parsed. The reference's flags keep their meanings and defaults.
#pragma once

#include <string>
#include <vector>

namespace fosssim::app {

struct Options {
  std::string scene;        ///< -s: the scene file (required)
  bool display = true;      ///< -d 0|1: open a window (default 1; falls back to headless without a display)
  bool paused = true;       ///< -p 0|1: the window starts paused (default 1)
  bool pngs = false;        ///< -g 0|1: write pngs/frame%05d.png after every step
  std::string output;       ///< -o: write a trajectory file
  std::string input;        ///< -i: grade a trajectory file
  std::string svgDir;       ///< -m: write an SVG per step into this folder
  bool compat = false;      ///< --compat: reproduce the reference's formulas bit for bit
  bool noSleep = false;     ///< --no-sleep: resting particles are simulated like any other (default mode)
  bool verify = false;      ///< --verify: check every step for missed collisions and non-finite states
  bool quiet = false;       ///< -q: no progress output
  int threads = 1;          ///< --threads N: threads for the broad and narrow phase (same results for any N)
  int frameWidth = 512;     ///< --frame-size WxH
  int frameHeight = 512;
  int frameEvery = 1;       ///< --frame-every K: write only every K-th frame
  std::string pngDir = "pngs";  ///< --png-dir: where -g writes
  std::string movie;        ///< --movie out.mp4: frames piped into ffmpeg
  std::string stats;        ///< --stats FILE: per-step diagnostics as CSV (stats_output.h)
  double fps = 0;           ///< --fps for --movie; 0: real time, 1 / (dt * frameEvery) (raster_frames.h)
  bool titleCard = false;   ///< --title-card: the movie opens with the scene's description
  bool keepOpen = false;    ///< --keep-open: the window stays open when the scene ends
  bool strict = false;      ///< --strict: warnings about the scene file are errors
  bool check = false;       ///< --check: load and check the scene, run nothing
  bool compact = false;     ///< --compact: -o without the collision log (positions and velocities)
  bool version = false;     ///< --version
  bool help = false;        ///< -h / --help
  /// Options given that have no effect here (e.g. --frame-size with nothing to draw): main prints
  /// them as warnings. Options that would be silently ignored in a way a user would not expect are
  /// errors instead (parseOptions fails).
  std::vector<std::string> warnings;
};

/// Parses argv (CLI11). On error returns false and sets `error` to a one-line message naming the
/// option and what is wrong: an unknown option, a bad value, an option given twice, or options
/// that cannot work together (e.g. -i with -g 1, --fps without --movie).
bool parseOptions(int argc, char** argv, Options& options, std::string& error);

/// The usage text of -h, generated from the option definitions and the collision and integrator
/// tables' summaries.
std::string usage();

/// What --version prints: "FOSSSim <version>", and the git commit the build was configured at
/// when it was known.
std::string versionText();

}  // namespace fosssim::app
