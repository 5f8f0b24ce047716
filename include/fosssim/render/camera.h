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

/// An axis-aligned rectangle of the world.
struct Box {
  Vec2 lo, hi;
  bool contains(const Box& b) const { return (lo.array() <= b.lo.array()).all() && (b.hi.array() <= hi.array()).all(); }
};

/// What `camera` shows in a width x height picture.
Box visibleBox(const Camera& camera, int width, int height);

/// The disks of `state`'s particles (centre +- radius; radius 0 where `scene` has none), finite
/// ones only. False when there is none.
bool particleBox(const Scene& scene, const State& state, Box& out);

/// The camera that follows a run so that a movie of a scene without a <viewport> keeps every
/// particle in view: it starts at initialCamera() and, whenever a particle's disk comes within
/// 5 % of the picture's edge, sets itself a larger goal (the sides that were crossed, pushed out by
/// a fifth of the view) and eases towards it with a time constant of 0.3 s of scene time. The
/// visible rectangle only ever grows (what was in view stays in view: no jerks back and forth,
/// no zooming in), and every particle's disk is always inside it, whatever the easing. With a
/// <viewport> the camera stays at it: the scene's author chose what to show.
class FollowCamera {
 public:
  /// Starts at initialCamera(), grown at once if a particle's disk pokes out of it.
  void start(const SceneFile& file, const State& initial, int width, int height);
  /// Moves the camera for `state` (call with every state that is shown, in time order) and
  /// returns it. A camera that does not follow returns as it is.
  const Camera& update(const Scene& scene, const State& state, int width, int height);
  const Camera& camera() const { return camera_; }
  /// Whether update() moves the camera: false with a <viewport>, or after the user took over.
  bool following() const { return following_; }
  /// The user moved the camera (zoom, pan): it stays where they put it.
  void take(const Camera& camera);
  /// Back to the start rule for `state` (the window's c key): the viewport, or the particles
  /// where they are now, followed from there.
  void refit(const SceneFile& file, const State& state, int width, int height);

 private:
  void reset(const Camera& camera, const Scene& scene, const State& state, int width, int height, bool follow);
  Camera camera_, goal_;
  Box calm_;  ///< particles inside it leave the goal alone (the goal less its margin, and the start)
  bool following_ = false;
  double time_ = 0;  ///< scene time of the last update
};

}  // namespace fosssim::render
