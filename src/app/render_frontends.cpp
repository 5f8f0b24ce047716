// Frontends of the build with the renderer: -g PNG frames and --movie (OSMesa), -m SVG, and the
// GLUT window for -d 1. The drawing itself is in fosssim_render; this only wires options to it.
#include "frontends.h"
#include "picture_outputs.h"
#include "signals.h"

#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/glut_window.h"
#include "fosssim/render/raster_frames.h"

#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

namespace fosssim::app {

Status addPictureOutputs(const Options& options, const SceneFile& file, ObserverList& observers) {
  render::FrameOutputs outputs(options.frameWidth, options.frameHeight, options.frameEvery);
  std::vector<std::string> places;
  std::optional<StagedFile> movie;
  if (!options.svgDir.empty()) {
    std::unique_ptr<render::SvgFrames> svg;
    if (Status s = render::SvgFrames::open(options.svgDir, svg); !s) return s;
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
      if (Status s = StagedFile::prepare(options.movie, "--movie", *movie); !s) return s;
      raster.movie = movie->writePath();
    }
    if (!options.movie.empty()) {
      // --fps 0 (the default) is real time; say what the movie will be.
      const render::MovieTiming timing = render::movieTiming(options.fps, file.scene.dt, options.frameEvery);
      raster.fps = timing.fps;
      raster.movieEvery = timing.every;
      raster.titleCard = options.titleCard;
      if (!options.quiet)
        std::fprintf(stderr, "FOSSSim: movie %s\n",
                     render::describeMovie(options.movie, timing, options.fps, file.scene.dt, options.frameEvery,
                                           file.scene.numSteps(), options.titleCard)
                         .c_str());
    }
    std::unique_ptr<render::RasterFrames> frames;
    if (Status s = render::RasterFrames::open(raster, frames); !s) return s;
    outputs.add(std::move(frames));
  }
  if (!outputs.empty())
    observers.items.push_back(std::make_unique<PictureOutputs>(std::move(outputs), std::move(places), std::move(movie)));
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
