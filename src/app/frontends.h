// The parts of the command line that show pictures. Implemented in render_frontends.cpp when the
// renderer is built (FOSSSIM_RENDER=ON) and in no_render_frontends.cpp otherwise.
#pragma once

#include "options.h"
#include "run_observer.h"

#include "fosssim/core/simulator.h"

namespace fosssim::app {

/// Adds the observers for -g (PNG frames), -m (SVG frames) and --movie. Fails when one of them is
/// asked for and cannot be made (e.g. this build has no renderer, or ffmpeg is missing).
Status addPictureOutputs(const Options& options, const SceneFile& file, ObserverList& observers);

/// True when an interactive window can be opened; otherwise `why` says what is missing.
bool windowAvailable(std::string& why);

/// Runs the scene in a window until the user quits; returns the process exit status.
int runWindow(const Options& options, SceneFile& file, Simulator& simulator, ObserverList& observers);

}  // namespace fosssim::app
