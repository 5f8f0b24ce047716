// FOSSSim's command line on CLI11. CLI11 splits the words ("-d 0", "-d0", "--threads 2",
// "--threads=2") and lays out -h; the values, repeats and combinations are judged here, after
// parsing, so that every message names the option and says what is wrong in the project's words
// (CLI11's own messages name its types, e.g. "1 required TEXT missing").
#include "options.h"

#include "cli_values.h"
#include "option_judge.h"
#include "option_words.h"
#include "fosssim/core/collision_handler.h"
#include "fosssim/core/integrator.h"

#include <memory>
#include <sstream>

#ifndef FOSSSIM_VERSION
#define FOSSSIM_VERSION "unknown"
#endif
#ifndef FOSSSIM_GIT_COMMIT
#define FOSSSIM_GIT_COMMIT ""
#endif

namespace fosssim::app {
namespace {

constexpr int kMaxThreads = 1024;      // far beyond any machine's cores; more would only exhaust the process

/// The words given for each value option, in order (an option given twice has two).
struct Given {
  std::vector<std::string> scene, display, paused, pngs, output, input, svgDir;
  std::vector<std::string> threads, frameSize, frameEvery, pngDir, movie, fps, stats;
};

/// -h's layout: the usage line first, names as "-h, --help", descriptions wrapped at 100 columns.
class HelpFormatter : public CLI::Formatter {
 public:
  HelpFormatter() { column_width(kColumn); }
  static constexpr size_t kColumn = 22, kWidth = 100;

  static std::string wrap(const std::string& text, size_t width) {
    std::string out, line, word;
    std::istringstream words(text);
    while (words >> word) {
      if (!line.empty() && line.size() + 1 + word.size() > width) {
        out += line + "\n";
        line.clear();
      }
      line += (line.empty() ? "" : " ") + word;
    }
    return out + line;
  }
  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override {
    return app->get_description() + make_groups(app, mode) + "\n" + make_footer(app);
  }
  std::string make_group(std::string group, bool positional, std::vector<const CLI::Option*> opts) const override {
    return CLI::Formatter::make_group(group, positional, opts).substr(1);  // one blank line between groups, not two
  }
  std::string make_option_name(const CLI::Option* opt, bool) const override {
    std::string names = opt->get_name(false, true);
    for (size_t k = names.find(','); k != std::string::npos; k = names.find(',', k + 2)) names.insert(k + 1, " ");
    return names;
  }
  std::string make_option_desc(const CLI::Option* opt) const override {
    return wrap(opt->get_description(), kWidth - kColumn);
  }
};

/// A footer table: "  keyword   summary" rows (the keywords are longer than option names).
std::string keywordRows(const std::vector<std::pair<std::string, std::string>>& rows) {
  constexpr size_t column = 29;
  std::ostringstream out;
  for (const auto& [keyword, summary] : rows)
    CLI::detail::format_help(out, keyword, HelpFormatter::wrap(summary, HelpFormatter::kWidth - column), column);
  return out.str();
}

std::string footer() {
  std::vector<std::pair<std::string, std::string>> collisions, integrators;
  for (const CollisionEntry& e : collisionTable()) collisions.emplace_back(e.keyword, e.summary);
  for (const IntegratorEntry& e : integratorTable()) integrators.emplace_back(e.keyword, e.summary);
  return "Collision handling, <collision type=\"...\"> in the scene file:\n" + keywordRows(collisions) +
         "\nIntegrators, <integrator type=\"...\" dt=\"...\"> in the scene file:\n" + keywordRows(integrators) +
         "\nEvery element and attribute of the scene format: docs/scene-format.md.\n\n" +
         HelpFormatter::wrap("Window keys: space pause/resume, s single step, r restart, c re-centre (follow the "
                             "particles), +/- zoom, arrows or mouse drag pan, i save an SVG, p save a PNG "
                             "screenshot, h or ? help, q/Esc quit.", HelpFormatter::kWidth) +
         "\n" +
         HelpFormatter::wrap("Exit status: 0 success (and a passed grade), 1 a bad scene, a failed run or a failed "
                             "grade, 2 a bad command line.", HelpFormatter::kWidth);
}

/// The whole command line. `o` receives the flags, `g` the values of the options that take one.
void define(CLI::App& app, Options& o, Given& g) {
  app.formatter(std::make_shared<HelpFormatter>());
  app.set_help_flag();  // -h is an ordinary flag: main prints usage() (so -h never hides a bad value)
  app.allow_extras();   // unknown words are named by parseOptions, with a suggestion
  app.description(
      "usage: FOSSSim -s scene.xml [options]\n\n"
      "Runs a FOSSSim scene (2D particles, edges and half-planes) from an XML scene file. Options take\n"
      "their value as the next word or after '=': \"-d 0\", \"--threads 2\", \"--threads=2\". An option given\n"
      "twice, or with options it cannot work with, is an error (exit 2) that says why.\n\n");
  const auto value = [&](const std::string& names, std::vector<std::string>& into, const std::string& text,
                         const std::string& group, const std::string& description) {
    app.add_option(names, into, description)
        ->expected(1)
        ->allow_extra_args(false)                            // "-s a b": b is not a second scene
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)  // repeats are judged by parseOptions
        ->option_text(text)
        ->group(group);
  };
  const auto flag = [&](const std::string& names, bool& into, const std::string& group,
                        const std::string& description) {
    app.add_flag(names, into, description)->group(group)->disable_flag_override();  // "--compat=2" is no flag
  };

  const std::string reference = "Reference options (the course simulator's, same meanings and defaults)";
  value("-s", g.scene, "FILE", reference, "the scene file (required)");
  value("-d", g.display, "0|1", reference,
        "open a window (default 1); without a display FOSSSim says so and runs headless");
  value("-p", g.paused, "0|1", reference, "start the window paused (default 1; no effect without a window)");
  value("-g", g.pngs, "0|1", reference,
        "write a PNG frame after every step into pngs/frame00001.png, ... (default 0; folder: --png-dir)");
  value("-o", g.output, "FILE", reference, "write the trajectory to FILE (the reference's binary format)");
  value("-i", g.input, "FILE", reference,
        "grade the trajectory in FILE against this simulator; prints \"Overall success: ...\". Grading runs no "
        "window and writes nothing: -o, -g 1, -m, --movie, --verify, --compact, --keep-open and --check are "
        "errors with it; --compat, --threads, --strict and -q apply");
  value("-m", g.svgDir, "DIR", reference,
        "write an SVG picture of every step into DIR/frame00000000000000000001.svg, ...");

  const std::string run = "How the scene runs";
  flag("--compat", o.compat, run,
       "reproduce the reference's own formulas where they differ from exact mathematics (the particle-edge "
       "approach quintic); needed to write or grade files for the course (README, \"Course compatibility\")");
  flag("--no-sleep", o.noSleep, run,
       "default mode: particles at rest do not sleep (by default a particle still for 30 steps sleeps, costing "
       "nothing, until a contact or a moving neighbour wakes it; --compat never sleeps)");
  flag("--verify", o.verify, run,
       "after every step check that no pair is left colliding and the state is finite; report violations and "
       "exit 1 when there was any");
  value("--threads", g.threads, "N", run,
        "threads for the per-particle phases (forces, integration, broad phase, detection, sleeping), 1 to " +
            std::to_string(kMaxThreads) +
            " (default 1); the results are the same for every N (scenes of a few thousand particles and up use "
            "them)");
  value("--stats", g.stats, "FILE", run,
        "write per-step diagnostics to FILE as CSV: time, kinetic and potential energy (per force), momentum, "
        "angular momentum, contacts, failsafe zones and the step's cost by phase (README, \"Per-step "
        "diagnostics\")");
  flag("--strict", o.strict, run, "warnings about the scene file are errors (exit 1)");
  flag("--check", o.check, run,
       "load and check the scene, report its warnings and errors, run nothing; no output options with it");
  flag("--compact", o.compact, run,
       "write -o without the polynomial log (positions, velocities and impulses stay): far smaller for "
       "continuous-time and hybrid scenes; for reading positions, not for grading with -i (needs -o)");

  const std::string pictures = "Pictures, movies and the window";
  value("--frame-size", g.frameSize, "WxH", pictures,
        "size of PNG and SVG frames, movies and the window (default 512x512, at most " +
            std::to_string(kMaxFrameSide) + "); only a warning when nothing uses it");
  value("--frame-every", g.frameEvery, "K", pictures,
        "write a frame (-g 1, -m, --movie) only after steps K, 2K, 3K, ...; frames are still numbered 1, 2, "
        "3, ... (default 1; needs -g 1, -m or --movie)");
  value("--png-dir", g.pngDir, "DIR", pictures, "folder for -g 1 frames (default pngs; created if needed; needs -g 1)");
  value("--movie", g.movie, "FILE.mp4", pictures, "pipe frames straight into ffmpeg (no PNG files); needs ffmpeg");
  value("--fps", g.fps, "N", pictures,
        "frame rate of --movie, decimals allowed (e.g. 29.97); default: real time, 1 / (dt x K) with dt the "
        "scene's and K --frame-every's (needs --movie)");
  flag("--title-card", o.titleCard, pictures, "the movie opens with the scene's description (needs --movie)");
  flag("--keep-open", o.keepOpen, pictures,
       "the window stays open when the scene ends (by default it closes, as the course's did; not with -d 0 "
       "or -i)");

  const std::string other = "Other";
  flag("-q", o.quiet, other, "no progress output");
  flag("-h,--help", o.help, other, "this text");
  flag("--version", o.version, other, "print \"FOSSSim <version>\" and exit");
  app.footer(footer());
}

/// Options that do nothing without another, and options that cannot work together. Errors where a
/// user would otherwise believe something happened that did not (a missing -g 1 means no PNGs at
/// all); a warning where the option is harmless (a frame size with nothing to draw).
bool checkCombinations(const Options& o, const Given& g, Judge& judge, std::vector<std::string>& warnings) {
  const bool frames = o.pngs || !o.svgDir.empty() || !o.movie.empty();
  const bool window = o.display && o.input.empty() && !o.check;
  const std::vector<std::pair<bool, std::string>> outputs = {
      {!o.output.empty(), "-o"},       {o.pngs, "-g 1"},         {!o.svgDir.empty(), "-m"},
      {!o.movie.empty(), "--movie"},   {o.verify, "--verify"},   {o.compact, "--compact"},
      {o.keepOpen, "--keep-open"},     {!o.stats.empty(), "--stats"},
  };
  if (!o.output.empty() && !o.input.empty())
    return judge.fail("-o (write a trajectory) and -i (grade one) cannot be used together");
  if (!o.input.empty()) {
    if (o.check) return judge.fail("--check runs nothing, so it cannot grade: -i cannot be used with it");
    for (const auto& [given, name] : outputs)
      if (given)
        return judge.fail("-i grades a trajectory and writes nothing else: " + name + " cannot be used with it");
  }
  if (o.check)
    for (const auto& [given, name] : outputs)
      if (given)
        return judge.fail("--check loads and checks the scene and runs nothing: " + name + " cannot be used with it");
  if (o.compact && o.output.empty()) return judge.fail("--compact shapes the -o file, and no -o is given");
  if (!g.pngDir.empty() && !o.pngs)
    return judge.fail("--png-dir is where -g 1 writes PNG frames, and -g 1 is not given: add -g 1 or drop --png-dir");
  if (!g.fps.empty() && o.movie.empty())
    return judge.fail("--fps is the frame rate of --movie, and no --movie is given (it does not change the "
                      "simulation's or the window's speed)");
  if (o.titleCard && o.movie.empty()) return judge.fail("--title-card opens a --movie, and no --movie is given");
  if (!g.frameEvery.empty() && !frames)
    return judge.fail("--frame-every thins out the frames of -g 1, -m and --movie, and none of them is given");
  if (o.keepOpen && !o.display) return judge.fail("--keep-open keeps the window open, and -d 0 opens none");
  if (!g.frameSize.empty() && !frames && !window)
    warnings.push_back("--frame-size has no effect: there is no window and no -g 1, -m or --movie");
  return true;
}

}  // namespace

std::string usage() {
  CLI::App app;
  Options o;
  Given g;
  define(app, o, g);
  return app.help();
}

std::string versionText() {
  const std::string commit = FOSSSIM_GIT_COMMIT;
  return std::string("FOSSSim ") + FOSSSIM_VERSION + (commit.empty() ? "" : " (git " + commit + ")");
}

bool parseOptions(int originalArgc, char** originalArgv, Options& o, std::string& error) {
  CLI::App app;
  Given g;
  define(app, o, g);
  if (error = optionTakenAsValue(app, std::vector<std::string>(originalArgv, originalArgv + originalArgc));
      !error.empty())
    return false;
  std::vector<std::string> words = splitShortValues(app, originalArgc, originalArgv);
  if (error = endOfOptions(app, words); !error.empty()) return false;
  std::vector<char*> pointers;
  for (std::string& w : words) pointers.push_back(w.data());
  const int argc = static_cast<int>(pointers.size());
  char** argv = pointers.data();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ArgumentMismatch& e) {
    const std::string what = e.what();
    if (const size_t k = what.find(" was given a disallowed flag override"); k != std::string::npos) {
      std::string name = what.substr(0, k);  // CLI11 names it without its dashes
      if (name[0] != '-') name = (name.size() == 1 ? "-" : "--") + name;
      error = "option " + name + " takes no value";
      return false;
    }
    // Otherwise thrown only when the words ran out before an option's value: the last word is it.
    const std::string last = argc > 1 ? argv[argc - 1] : "";
    error = "option " + last.substr(0, last.find('=')) + " needs a value";
    return false;
  } catch (const CLI::ParseError& e) {
    error = std::string(e.what()) + " (FOSSSim -h lists the options)";
    return false;
  }
  if (!app.remaining().empty()) {
    error = shortFlagWithValue(app.remaining().front(), argc, argv);
    if (error.empty()) error = unknownWord(app, app.remaining().front());
    return false;
  }
  Judge judge(o, error);
  const int maxFrameEvery = 1000000;
  if (!judge.single("-s", g.scene, o.scene) || !judge.flag("-d", g.display, o.display) ||
      !judge.flag("-p", g.paused, o.paused) || !judge.flag("-g", g.pngs, o.pngs) ||
      !judge.single("-o", g.output, o.output) || !judge.single("-i", g.input, o.input) ||
      !judge.single("-m", g.svgDir, o.svgDir) ||
      !judge.integer("--threads", g.threads, kMaxThreads, o.threads,
                     "an integer from 1 to " + std::to_string(kMaxThreads)) ||
      !judge.frameSize(g.frameSize) ||
      !judge.integer("--frame-every", g.frameEvery, maxFrameEvery, o.frameEvery, "a positive integer") ||
      !judge.single("--png-dir", g.pngDir, o.pngDir) || !judge.movie(g.movie) ||
      !judge.single("--stats", g.stats, o.stats) ||
      !judge.fps(g.fps))
    return false;
  if (o.help || o.version) return true;
  if (o.scene.empty()) return judge.fail("no scene file given: use -s scene.xml (FOSSSim -h lists the options)");
  return checkCombinations(o, g, judge, o.warnings);
}

}  // namespace fosssim::app
