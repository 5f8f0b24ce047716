// Frontends of a build without the renderer (FOSSSIM_RENDER=OFF): no window, no PNG or movie.
#include "frontends.h"

namespace fosssim::app {

Status addPictureOutputs(const Options& options, const SceneFile&, ObserverList&) {
  if (options.pngs || !options.movie.empty() || !options.svgDir.empty())
    return Status::error("this FOSSSim was built without the renderer (FOSSSIM_RENDER=OFF): -g, -m and --movie are unavailable");
  return Status::ok();
}

bool windowAvailable(std::string& why) {
  why = "this FOSSSim was built without the renderer (FOSSSIM_RENDER=OFF)";
  return false;
}

int runWindow(const Options&, SceneFile&, Simulator&, ObserverList&) { return 1; }

}  // namespace fosssim::app
