#include "fosssim/render/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fosssim::render {

Camera fitParticles(const State& state, int width, int height) {
  double minX = std::numeric_limits<double>::infinity(), maxX = -minX, minY = minX, maxY = -minX;
  for (int i = 0; i < state.numParticles(); ++i) {
    const Vec2 p = at(state.x, i);
    if (!p.allFinite()) continue;  // a blown-up particle must not take the camera with it
    minX = std::min(minX, p.x());
    maxX = std::max(maxX, p.x());
    minY = std::min(minY, p.y());
    maxY = std::max(maxY, p.y());
  }
  Camera c;
  if (!(minX <= maxX)) return c;  // no (finite) particles: the unit view around the origin
  c.cx = 0.5 * (minX + maxX);
  c.cy = 0.5 * (minY + maxY);
  double rx = maxX - c.cx, ry = maxY - c.cy;
  if (rx == 0) rx = 1;
  if (ry == 0) ry = 1;
  const double ratio = static_cast<double>(height) / static_cast<double>(width);
  c.size = 1.2 * std::max(ratio * rx, ry);
  return c;
}

Camera initialCamera(const Appearance& look, const State& state, int width, int height) {
  if (look.viewport) return Camera{look.viewport->cx, look.viewport->cy, look.viewport->size};
  return fitParticles(state, width, height);
}

namespace {

constexpr double kEdgeMargin = 0.02;  // of the visible height: closer to the edge grows the goal
constexpr double kPush = 0.2;         // of the visible height: how far beyond a crossed side the goal goes
constexpr double kEaseTime = 0.3;     // seconds of scene time: the camera's time constant

Box unite(const Box& a, const Box& b) { return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)}; }

/// The smallest camera whose picture contains `box`: centred on it, the shorter side widened
/// (symmetrically) to the picture's aspect ratio.
Camera enclosing(const Box& box, int width, int height) {
  const double ratio = static_cast<double>(height) / static_cast<double>(width);
  Camera c;
  c.cx = 0.5 * (box.lo.x() + box.hi.x());
  c.cy = 0.5 * (box.lo.y() + box.hi.y());
  c.size = std::max(0.5 * (box.hi.y() - box.lo.y()), ratio * 0.5 * (box.hi.x() - box.lo.x()));
  // Rounding in the centre and half-size may leave the box's ends a few ulps outside.
  c.size *= 1 + 4 * std::numeric_limits<double>::epsilon();
  if (!(c.size > 0)) c.size = 1;
  return c;
}

}  // namespace

Box visibleBox(const Camera& camera, int width, int height) {
  const double halfWidth = camera.size * static_cast<double>(width) / static_cast<double>(height);
  return {Vec2(camera.cx - halfWidth, camera.cy - camera.size), Vec2(camera.cx + halfWidth, camera.cy + camera.size)};
}

bool particleBox(const Scene& scene, const State& state, Box& out) {
  bool any = false;
  for (int i = 0; i < state.numParticles(); ++i) {
    const Vec2 p = at(state.x, i);
    const double r = i < scene.numParticles() ? scene.radius[i] : 0.0;
    if (!p.allFinite() || !std::isfinite(r)) continue;
    const Box disk{p - Vec2(r, r), p + Vec2(r, r)};
    out = any ? unite(out, disk) : disk;
    any = true;
  }
  return any;
}

void FollowCamera::reset(const Camera& camera, const Scene& scene, const State& state, int width, int height,
                         bool follow) {
  camera_ = camera;
  following_ = follow;
  time_ = state.time;
  Box particles;
  const bool any = particleBox(scene, state, particles);
  Box view = visibleBox(camera_, width, height);
  // A disk poking out at the start is taken in at once: the first frame shows every particle.
  if (follow && any && !view.contains(particles)) {
    camera_ = enclosing(unite(view, particles), width, height);
    view = visibleBox(camera_, width, height);
  }
  goal_ = camera_;
  const double margin = kEdgeMargin * (view.hi.y() - view.lo.y());
  calm_ = {view.lo + Vec2(margin, margin), view.hi - Vec2(margin, margin)};
  if (any) calm_ = unite(calm_, particles);  // particles already that close to the edge are not moving out
}

void FollowCamera::start(const SceneFile& file, const State& initial, int width, int height) {
  reset(initialCamera(file.look, initial, width, height), file.scene, initial, width, height, !file.look.viewport);
}

void FollowCamera::refit(const SceneFile& file, const State& state, int width, int height) {
  start(file, state, width, height);
}

void FollowCamera::take(const Camera& camera) {
  camera_ = camera;
  following_ = false;
}

const Camera& FollowCamera::update(const Scene& scene, const State& state, int width, int height) {
  Box particles;
  if (!following_ || !particleBox(scene, state, particles)) return camera_;
  const double elapsed = std::max(0.0, state.time - time_);
  time_ = state.time;

  // The goal grows past every side that a particle came close to, by a fifth of the view, so
  // that the camera moves in a few smooth glides rather than a creep every frame.
  Box goal = visibleBox(goal_, width, height);
  if (!calm_.contains(particles)) {
    const double push = kPush * (goal.hi.y() - goal.lo.y());
    for (int k = 0; k < 2; ++k) {
      if (particles.lo[k] < calm_.lo[k]) goal.lo[k] = std::min(goal.lo[k], particles.lo[k] - push);
      if (particles.hi[k] > calm_.hi[k]) goal.hi[k] = std::max(goal.hi[k], particles.hi[k] + push);
    }
    goal_ = enclosing(goal, width, height);
    goal = visibleBox(goal_, width, height);
    const double margin = kEdgeMargin * (goal.hi.y() - goal.lo.y());
    calm_ = unite(calm_, Box{goal.lo + Vec2(margin, margin), goal.hi - Vec2(margin, margin)});
  }

  // Ease every side of the view towards the goal's (both have the picture's aspect ratio, so
  // the blend has it too), then take in any disk that is still outside.
  const Box view = visibleBox(camera_, width, height);
  const double alpha = 1.0 - std::exp(-elapsed / kEaseTime);
  Box eased{view.lo + alpha * (goal.lo - view.lo), view.hi + alpha * (goal.hi - view.hi)};
  eased = unite(eased, view);  // never shrinks, whatever the rounding or a reshaped window
  if (eased.lo == view.lo && eased.hi == view.hi && view.contains(particles)) return camera_;  // at rest
  camera_ = eased.contains(particles) ? enclosing(eased, width, height)
                                      : enclosing(unite(eased, particles), width, height);
  // Enclosing widens symmetrically, so the view may now reach past the goal: the goal takes it
  // in, or the next blend would pull that side back.
  const Box now = visibleBox(camera_, width, height);
  if (!goal.contains(now)) goal_ = enclosing(unite(goal, now), width, height);
  return camera_;
}

}  // namespace fosssim::render
