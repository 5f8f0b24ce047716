// Draws a Picture with OpenGL: the one drawing routine that both backends (OSMesa frames and the
// GLUT window) share. Geometry comes from the tessellator; this only uploads and draws it.
#pragma once

#include "gl_functions.h"

#include "fosssim/render/picture.h"
#include "fosssim/render/tessellator.h"

namespace fosssim::render {

class GlPainter {
 public:
  explicit GlPainter(const GlFunctions& gl) : gl_(gl) {}
  /// Clears to the picture's background and draws it into the current context's framebuffer,
  /// whose size must be the picture's view size.
  void paint(const Picture& picture);
  /// The last OpenGL error as a Status (ok when there is none).
  Status check(const char* what) const;

 private:
  const GlFunctions& gl_;
  Mesh mesh_;  // reused from frame to frame: no allocation once it has grown
};

}  // namespace fosssim::render
