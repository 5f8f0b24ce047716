// A tiny built-in stroke font, so that text (the time in the corner, the window's status line)
// needs neither GLUT nor a font library: OSMesa frames and SVG files draw the same strokes.
#pragma once

#include "fosssim/core/types.h"

#include <string>
#include <vector>

namespace fosssim::render {

/// A straight stroke of a glyph, in pixels.
struct StrokeSegment {
  Vec2 a, b;
};

/// The strokes of `text` set on a baseline starting at `origin` (pixels, y up) with capital
/// letters `capHeight` pixels tall. Covers printable ASCII letters, digits and common
/// punctuation; other characters show as '?'.
std::vector<StrokeSegment> layoutText(const std::string& text, const Vec2& origin, double capHeight);

/// Horizontal advance of `text`, pixels.
double textWidth(const std::string& text, double capHeight);

/// Stroke width that suits a cap height, pixels.
double strokeWidth(double capHeight);

}  // namespace fosssim::render
