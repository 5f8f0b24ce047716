// Frontends of the build with the renderer: -g PNG frames and --movie (OSMesa), -m SVG, and the
// GLUT window for -d 1. The drawing itself is in fosssim_render; this only wires options to it.
#include "frontends.h"
#include "picture_outputs.h"
#include "signals.h"

#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/glut_window.h"
#include "fosssim/render/raster_frames.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

namespace fosssim::app {
namespace {

/// The render library's messages name what failed (a folder, ffmpeg, the movie file); the command
/// line adds the option that asked for it.
Status flagged(const std::string& option, Status s) {
  return s ? s : Status::error(option + ": " + s.message());
}

/// One line saying what movieTiming() chose, e.g. "movie.mp4: 50 fps, a frame every 2 steps
/// (0.02 s of the scene): real time; 203 frames from t = 0, 4.06 s".
std::string describeMovie(const std::string& path, const render::MovieTiming& timing, double requestedFps, double dt,
                          int frameEvery, long steps, bool titleCard) {
  const long stepsPerFrame = std::max(frameEvery, 1) * timing.every;
  const long scene = 1 + steps / stepsPerFrame;  // t = 0, then every stepsPerFrame steps
  const long card = titleCard ? std::max(1L, std::lround(render::kTitleSeconds * timing.fps)) : 0;
  char text[512];
  char pace[96];
  if (timing.realTime && timing.every > 1)
    std::snprintf(pace, sizeof pace, "real time (frames left out to stay at most %g fps)", render::kMaxRealTimeFps);
  else if (timing.realTime)
    std::snprintf(pace, sizeof pace, "real time");
  else if (requestedFps > 0)
    std::snprintf(pace, sizeof pace, "%.3g x real time (--fps; leave it out for real time)", timing.speed);
  else
    std::snprintf(pace, sizeof pace, "%.3g x real time (real time would be under %g fps)", timing.speed,
                  render::kMinRealTimeFps);
  char cardText[64] = "";
  if (card > 0)
    std::snprintf(cardText, sizeof cardText, " after a %.3g s title card", static_cast<double>(card) / timing.fps);
  std::snprintf(text, sizeof text,
                "%s: %.4g fps, a frame every %ld step%s (%.4g s of the scene): %s; %ld frames from t = 0, %.3g s%s",
                path.c_str(), timing.fps, stepsPerFrame, stepsPerFrame == 1 ? "" : "s",
                dt * static_cast<double>(stepsPerFrame), pace, scene, static_cast<double>(scene) / timing.fps,
                cardText);
  return text;
}

/// --movie's ffmpeg, started on `writePath` (the staged name) once the frames can be drawn.
Status openMovie(const Options& options, const std::string& writePath, const render::RasterSettings& raster,
                 std::unique_ptr<render::MovieWriter>& out) {
  if (render::findOnPath("ffmpeg").empty())
    return Status::error("--movie needs ffmpeg, which is not on PATH: install it (scripts/setup does, or "
                         "apt-get install ffmpeg), or write PNG frames with -g 1 instead");
  const std::string folder = std::filesystem::path(writePath).parent_path().string();
  if (Status s = render::createDirectory(folder, "the movie \"" + options.movie + "\""); !s)
    return flagged("--movie", s);
  return flagged("--movie", render::MovieWriter::open(writePath, raster.width, raster.height, raster.fps, out));
}

}  // namespace

Status addPictureOutputs(const Options& options, const SceneFile& file, ObserverList& observers) {
  render::FrameOutputs outputs(options.frameWidth, options.frameHeight, options.frameEvery);
  std::vector<std::string> places;
  std::optional<io::StagedFile> movie;
  if (!options.svgDir.empty()) {
    std::unique_ptr<render::SvgFrames> svg;
    if (Status s = render::SvgFrames::open(options.svgDir, svg); !s) return flagged("-m", s);
    outputs.add(std::move(svg));
    places.push_back("SVG in \"" + options.svgDir + "\"");
  }
  if (options.pngs || !options.movie.empty()) {
    render::RasterSettings raster;
    raster.width = options.frameWidth;
    raster.height = options.frameHeight;
    if (options.pngs) raster.pngDir = options.pngDir.empty() ? "." : options.pngDir;
    if (options.pngs) places.push_back("PNG in \"" + raster.pngDir + "\"");
    if (!options.movie.empty()) {
      movie.emplace();
      if (Status s = io::StagedFile::prepare(options.movie, "--movie", *movie); !s) return s;
      // --fps 0 (the default) is real time; say what the movie will be.
      const render::MovieTiming timing = render::movieTiming(options.fps, file.scene.dt, options.frameEvery);
      raster.fps = timing.fps;
      raster.movieEvery = timing.every;
      raster.titleCard = options.titleCard;
      if (!options.quiet)
        std::fprintf(stderr, "FOSSSim: movie %s\n",
                     describeMovie(options.movie, timing, options.fps, file.scene.dt, options.frameEvery,
                                   file.scene.numSteps(), options.titleCard)
                         .c_str());
    }
    std::unique_ptr<render::RasterFrames> frames;
    if (Status s = render::RasterFrames::open(raster, frames); !s) return flagged(options.pngs ? "-g" : "--movie", s);
    if (movie) {
      std::unique_ptr<render::MovieWriter> writer;
      if (Status s = openMovie(options, movie->writePath(), raster, writer); !s) return s;
      frames->setMovie(std::move(writer));
    }
    outputs.add(std::move(frames));
  }
  if (!outputs.empty())
    observers.items.push_back(
        std::make_unique<PictureOutputs>(std::move(outputs), std::move(places), std::move(movie)));
  return Status::ok();
}

bool windowAvailable(std::string& why) { return render::windowAvailable(why); }

int runWindow(const Options& options, SceneFile& file, Simulator& simulator, ObserverList& observers) {
  State state = file.initial;
  Status status = Status::ok();
  for (auto& o : observers.items)
    if (status) status = o->start(file, state, simulator.layout());

  // One step as the headless run takes it, so that -o and -g work from the window too.
  Simulator* sim = &simulator;
  const std::function<Status()> step = [&]() -> Status {
    if (Status s = sim->step(file.scene, state, &observers); !s) return s;
    for (auto& o : observers.items)
      if (Status s = o->afterStep(file, state, sim->log()); !s) return s;
    return Status::ok();
  };
  // r: the initial state and a fresh simulator (its warm starts and energy watch start over), so
  // the rerun is the run. Not while outputs record the run: a trajectory or frames cannot restart.
  std::unique_ptr<Simulator> fresh;
  const std::function<Status()> restart = [&]() -> Status {
    SimulatorOptions simOptions;
    simOptions.handler.compat = options.compat;
    simOptions.handler.threads = options.threads;
    simOptions.handler.sleep = !options.noSleep;
    std::unique_ptr<Simulator> next;
    if (Status s = Simulator::create(file.scene, simOptions, next); !s) return s;
    fresh = std::move(next);
    sim = fresh.get();
    state = file.initial;
    return Status::ok();
  };
  if (status) {
    render::WindowSettings settings;
    settings.sceneName = std::filesystem::path(file.path).filename().string();
    settings.width = options.frameWidth;
    settings.height = options.frameHeight;
    settings.startPaused = options.paused;
    settings.stepsPerSecond = file.look.maxSimFreq;
    settings.totalSteps = file.scene.numSteps();
    settings.stepsRenderOffscreen = options.pngs || !options.movie.empty();
    settings.keepOpen = options.keepOpen;
    if (observers.items.empty()) settings.restart = restart;
    else settings.noRestart = "no restart while -o, -g, -m, --movie or --verify record this run";
    settings.stopRequested = [] { return stopSignal() != 0; };  // SIGINT, SIGTERM: close like q
    status = render::runWindow(settings, file, state, step);
  }
  // Closing the window is the user's end of the run (Completed); a signal's is not (endRun).
  return endRun(observers, status, state, stopSignal() != 0 ? file.scene.numSteps() : state.step);
}

}  // namespace fosssim::app
