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

Status addPictureOutputs(const Options& options, const SceneFile&, ObserverList& observers) {
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
    raster.fps = options.fps;
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
  const std::function<Status()> step = [&]() -> Status {
    if (Status s = simulator.step(file.scene, state, &observers); !s) return s;
    for (auto& o : observers.items)
      if (Status s = o->afterStep(file, state, simulator.log()); !s) return s;
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
    settings.stopRequested = [] { return stopSignal() != 0; };  // SIGINT, SIGTERM: close like q
    status = render::runWindow(settings, file, state, step);
  }
  // Closing the window is the user's end of the run (Completed); a signal's is not (endRun).
  return endRun(observers, status, state, stopSignal() != 0 ? file.scene.numSteps() : state.step);
}

}  // namespace fosssim::app
