// The camera: which part of the world a picture shows, and the world-to-pixel mapping. Shared by
// the raster (OpenGL) and vector (SVG) outputs so that both show exactly the same picture.
#pragma once

#include "fosssim/core/state.h"
#include "fosssim/core/types.h"
#include "fosssim/io/scene_file.h"

namespace fosssim::render {

/// An orthographic camera, as in the scene file's <viewport>: centred at (cx, cy), showing
/// `size` world units above and below the centre (half-height). The half-width follows from the
/// picture's aspect ratio, so a wider picture shows more, never a distorted world.
struct Camera {
  double cx = 0, cy = 0;
  double size = 1;  ///< half-height of the visible world, > 0
};

/// A camera looking at a picture of width x height pixels. Pixel coordinates have their origin in
/// the bottom-left corner of the picture with y up (OpenGL's window coordinates); pixel (i, j) is
/// the unit square [i, i+1] x [j, j+1]. Writers that need y down (SVG, PNG rows) flip themselves.
struct View {
  int width = 512;
  int height = 512;
  Camera camera;

  /// Pixels per world unit.
  double scale() const { return 0.5 * height / camera.size; }
  Vec2 toPixel(const Vec2& world) const {
    return {0.5 * width + (world.x() - camera.cx) * scale(), 0.5 * height + (world.y() - camera.cy) * scale()};
  }
  Vec2 toWorld(const Vec2& pixel) const {
    return {camera.cx + (pixel.x() - 0.5 * width) / scale(), camera.cy + (pixel.y() - 0.5 * height) / scale()};
  }
};

/// The camera that shows all particles of `state` in a width x height picture: centred on the
/// particles' bounding box, half-height 1.2 * max(ratio * rx, ry) where rx, ry are the box's
/// half-extents (an extent of 0 counts as 1) and ratio = height / width. This is the reading of
/// the reference's rule that keeps every particle centre visible whatever the aspect ratio: the
/// visible half-width is size / ratio >= 1.2 * rx and the half-height size >= 1.2 * ry.
Camera fitParticles(const State& state, int width, int height);

/// The scene's <viewport> when it has one, otherwise fitParticles() of `state`.
Camera initialCamera(const Appearance& look, const State& state, int width, int height);

}  // namespace fosssim::render
