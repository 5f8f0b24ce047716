// Frontends of a build without the renderer (FOSSSIM_RENDER=OFF): no window, no PNG or movie;
// -m still writes SVG frames, which need no OpenGL (fosssim_picture).
#include "frontends.h"
#include "picture_outputs.h"

#include "fosssim/render/frame_outputs.h"

namespace fosssim::app {

Status addPictureOutputs(const Options& options, const SceneFile&, ObserverList& observers) {
  if (options.pngs || !options.movie.empty())
    return Status::error("this FOSSSim was built without the renderer (FOSSSIM_RENDER=OFF): -g and --movie are "
                         "unavailable (-m SVG frames work)");
  if (options.svgDir.empty()) return Status::ok();
  render::FrameOutputs outputs(options.frameWidth, options.frameHeight, options.frameEvery);
  std::unique_ptr<render::SvgFrames> svg;
  if (Status s = render::SvgFrames::open(options.svgDir, svg); !s) return Status::error("-m: " + s.message());
  outputs.add(std::move(svg));
  // The summary names where the frames went, as the renderer's build does.
  observers.items.push_back(std::make_unique<PictureOutputs>(
      std::move(outputs), std::vector<std::string>{"SVG in \"" + options.svgDir + "\""}));
  return Status::ok();
}

bool windowAvailable(std::string& why) {
  why = "this FOSSSim was built without the renderer (FOSSSIM_RENDER=OFF)";
  return false;
}

int runWindow(const Options&, SceneFile&, Simulator&, ObserverList&) { return 1; }

}  // namespace fosssim::app
