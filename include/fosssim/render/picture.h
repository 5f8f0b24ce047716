// A picture of one moment of a scene, as a list of shapes in draw order. It is what both outputs
// consume: the raster path tessellates it into triangles for OpenGL (tessellator.h), the vector
// path writes it as SVG elements (svg_writer.h). Building it once keeps the two faithful to each
// other and keeps all the "what is drawn" rules (spec section 7) in one place.
#pragma once

#include "fosssim/render/camera.h"
#include "fosssim/render/path_trails.h"

#include <string>
#include <vector>

namespace fosssim::render {

/// A particle path: a polyline in world coordinates, oldest point first.
struct PathShape {
  std::vector<Vec2> points;
  Rgb color;
};

/// An edge: the capsule of all points within `radius` of the segment a-b (world coordinates).
struct CapsuleShape {
  Vec2 a, b;
  double radius = 0;
  Rgb color;
};

/// A half-plane: the solid side, where (x - point) . normal <= 0, filled.
struct HalfPlaneShape {
  Vec2 point, normal;
  Rgb color;
};

/// A particle: a filled disk (world coordinates).
struct DiskShape {
  Vec2 center;
  double radius = 0;
  Rgb color;
};

/// Text drawn with the built-in stroke font (stroke_font.h), in pixel coordinates (y up).
struct LabelShape {
  std::string text;
  Vec2 origin;           ///< left end of the baseline, pixels
  double capHeight = 12; ///< height of a capital letter, pixels
  Rgb color;
};

/// A filled rectangle in pixel coordinates (y up), drawn over the scene and under the labels: the
/// backing that keeps a front end's text (the window's status line, its help) readable over
/// whatever the scene draws beneath it.
struct PanelShape {
  Vec2 lo, hi;  ///< corners, pixels
  Rgb color;
  double alpha = 1;  ///< opacity, 0..1
};

/// Everything drawn in one frame. Draw order: background, paths, edges, half-planes, particles,
/// panels, labels (the time in the top-left corner, and whatever a front end adds, e.g. a status
/// line on its panel).
struct Picture {
  View view;
  Rgb background{1, 1, 1};
  std::vector<PathShape> paths;
  std::vector<CapsuleShape> edges;
  std::vector<HalfPlaneShape> halfplanes;
  std::vector<DiskShape> particles;
  std::vector<PanelShape> panels;
  std::vector<LabelShape> labels;
};

/// The picture of `state`: geometry from the scene, colours and background from the appearance,
/// trails from `trails`, and the simulated time in the top-left corner in the colour
/// 1 - background. Shapes with a non-finite position are left out.
Picture makePicture(const SceneFile& file, const State& state, const PathTrails& trails, const View& view);

/// A movie's title card: the scene's <description> (or, without one, its file name) in large
/// letters, centred and wrapped to the picture's width, with the file name small below it; the
/// scene's background and the time label's colour.
Picture titleCard(const SceneFile& file, const View& view);

/// `text` broken at spaces into lines of at most `width` characters (a longer word is cut).
std::vector<std::string> wrapText(const std::string& text, std::size_t width);

/// The time label text for `time` with as many decimals as the step size needs (e.g. dt = 0.005
/// shows "t = 1.250").
std::string timeText(double time, double dt);

/// Cap height of labels for a picture `height` pixels tall (readable at 512, not huge at 4096).
double labelCapHeight(int height);

/// The polygon (pixel coordinates, counter-clockwise) covering the part of the picture, grown by
/// `margin` pixels on every side, that lies on the solid side of the half-plane offset by
/// `offset` pixels along its normal: {x : (x - p) . n_hat <= offset}. Empty when none of it does.
std::vector<Vec2> solidSideInView(const HalfPlaneShape& h, const View& view, double margin, double offset);

}  // namespace fosssim::render
