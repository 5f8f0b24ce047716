// Turns a Picture into coloured triangles in pixel coordinates: the raster path's whole notion of
// geometry, with no OpenGL in it (so it is unit-tested without a GL library, and the GL code that
// draws the result is a dozen calls). Edges are anti-aliased with alpha-blended rims: every
// filled shape gets a one-pixel band whose alpha falls from 1 to 0 across the true boundary,
// which looks like 2x2..4x4 multisampling without needing a multisample buffer (OSMesa has none).
#pragma once

#include "fosssim/render/picture.h"

#include <vector>

namespace fosssim::render {

/// Triangles (three vertices each) in draw order, with straight (not premultiplied) alpha.
struct Mesh {
  std::vector<float> xy;    ///< 2 per vertex, pixel coordinates (y up)
  std::vector<float> rgba;  ///< 4 per vertex
  void clear() {
    xy.clear();
    rgba.clear();
  }
  std::size_t vertexCount() const { return xy.size() / 2; }
};

/// Appends the picture's shapes (not the background, which is a clear colour) to `mesh`.
void tessellate(const Picture& picture, Mesh& mesh);

/// Number of segments used for a circle of `radiusPixels` so that the polygon departs from the
/// true circle by less than 0.1 pixel.
int circleSegments(double radiusPixels);

}  // namespace fosssim::render
