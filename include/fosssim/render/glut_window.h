// The interactive window (freeglut): shows a running simulation and lets the user pause, step,
// zoom and pan, with the reference's keys. The window draws with the same painter as the
// off-screen frames; only the context (this backend) differs.
#pragma once

#include "fosssim/core/state.h"
#include "fosssim/core/status.h"
#include "fosssim/io/scene_file.h"

#include <functional>
#include <string>

namespace fosssim::render {

/// True when a window can be opened: DISPLAY is set, the X server answers and offers GLX with a
/// double-buffered RGBA visual. Checked with Xlib before glutInit, which would otherwise end the
/// process on failure. Otherwise `why` says what is missing.
bool windowAvailable(std::string& why);

struct WindowSettings {
  std::string sceneName;        ///< shown in the title and the status line
  int width = 512, height = 512;
  bool startPaused = true;      ///< -p
  double stepsPerSecond = 100;  ///< <maxsimfreq>: the pace of a running simulation
  long totalSteps = 0;          ///< stepping stops after this many
  /// --keep-open: the window stays open when the scene ends or fails. Otherwise it closes after
  /// the last step's picture (as the course's did, so a scripted -p 0 run returns), or 3 s after
  /// showing a failed step's error.
  bool keepOpen = false;
  /// The r key: puts the caller's state back to the initial one (and whatever else a fresh run
  /// needs); a failure is shown like a failed step. Empty when a restart is not possible, and then
  /// `noRestart` says why (shown when r is pressed).
  std::function<Status()> restart;
  std::string noRestart;
  /// The step function draws off-screen frames (OffscreenRenderer) on this thread: the window
  /// then re-binds its own context after every step.
  bool stepsRenderOffscreen = false;
  /// Asked between steps and every timer tick (10 ms), paused or not: true closes the window as
  /// q does (the caller's SIGINT/SIGTERM flag). May be empty.
  std::function<bool()> stopRequested;
};

/// Opens the window and runs its event loop until the user quits (q, Esc or closing it) or, without
/// keepOpen, the scene ends. `state` is what is shown; `step` advances it by one step (and does
/// whatever else the caller wants per step, e.g. write frames). A failing step stops the stepping,
/// is shown in the window and returned.
/// The camera follows the particles (FollowCamera) until the user zooms or pans.
/// Keys (windowKeys() in window_overlay.h): space pause/resume, s single step (and pause), r
/// restart, c re-centre (the scene's viewport, or follow the particles again), +/- zoom, arrows
/// pan, i save an SVG and p a PNG screenshot (into the current folder), h or ? help, q/Esc quit;
/// mouse: drag pans, wheel zooms.
Status runWindow(const WindowSettings& settings, const SceneFile& file, const State& state,
                 const std::function<Status()>& step);

}  // namespace fosssim::render
