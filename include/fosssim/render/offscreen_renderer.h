// Headless frames: pictures drawn by OpenGL into memory through OSMesa (Mesa's off-screen,
// software renderer), so -g and --movie need no display, no window and no GPU.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/render/image.h"
#include "fosssim/render/picture.h"

#include <memory>

namespace fosssim::render {

class OffscreenRenderer {
 public:
  /// Creates an OSMesa context with a width x height colour buffer. `smaller`: what the advice of
  /// an out-of-memory message tells the caller to make smaller, in the caller's terms (the command
  /// line's option; the Python module's arguments).
  static Status create(int width, int height, std::unique_ptr<OffscreenRenderer>& out,
                       const char* smaller = "--frame-size");
  ~OffscreenRenderer();
  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

  /// Draws `picture` (whose view must have this renderer's size) and returns its pixels.
  /// Makes this renderer's context current on the calling thread (see restoreAfter in
  /// glut_window.h for sharing a thread with a window).
  Status render(const Picture& picture, Image& out);

  int width() const;
  int height() const;

 private:
  struct Impl;
  explicit OffscreenRenderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace fosssim::render
