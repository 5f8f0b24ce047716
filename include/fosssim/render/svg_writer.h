// -m: the picture as an SVG file, element for element the shapes the raster path draws, in the
// same pixel coordinates (y flipped to SVG's downward axis). Needs no OpenGL.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/render/picture.h"

#include <string>

namespace fosssim::render {

/// The SVG document of `picture`. Groups, in draw order: <rect id="background">, <g id="paths">
/// (polylines), <g id="edges"> (round-capped lines as wide as the capsule), <g id="halfplanes">
/// (polygons of the solid side within the view), <g id="particles"> (circles), <g id="panels">
/// (rectangles, only when the picture has any), <g id="labels">
/// (stroked paths of the built-in font, the text itself in a <title>).
std::string svgDocument(const Picture& picture);

/// Writes svgDocument(picture) to `path`.
Status writeSvg(const std::string& path, const Picture& picture);

/// The reference's -m file name: dir/frame%020d.svg.
std::string svgFrameName(const std::string& dir, long number);

}  // namespace fosssim::render
