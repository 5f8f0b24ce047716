// What the interactive window draws over the scene: the status line, a transient note (e.g. "saved
// scene_step00042.svg"), the run's error and the key help. Each sits on a panel of its own, so it
// stays readable over anything the scene draws beneath it (a black half-plane under the status line
// on a white background, say). Plain Picture shapes, so this is tested without a window.
#pragma once

#include "fosssim/render/picture.h"

#include <string>
#include <vector>

namespace fosssim::render {

struct WindowOverlay {
  std::string status;  ///< the status line along the bottom
  std::string note;    ///< a short-lived note above it, or empty
  std::string error;   ///< why the run stopped, or empty: a red panel across the middle
  bool help = false;   ///< the key help, centred
};

/// The key help, one key per line (the same text as the README's and -h's).
const std::vector<std::string>& windowKeys();

/// Adds `overlay`'s panels and labels to `picture` (sized by its view). Text in the colour
/// 1 - background on panels of the background colour; the error in white on dark red. Lines
/// too long for the picture get smaller letters, never cut off.
void addWindowOverlay(Picture& picture, const WindowOverlay& overlay);

}  // namespace fosssim::render
