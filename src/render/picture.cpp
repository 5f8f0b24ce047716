#include "fosssim/render/picture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fosssim::render {
namespace {

Rgb inverse(const Rgb& c) { return {1 - c.r, 1 - c.g, 1 - c.b}; }

template <class T>
const T& colorOr(const std::vector<T>& colors, int k, const T& fallback) {
  return k >= 0 && k < static_cast<int>(colors.size()) ? colors[k] : fallback;
}

}  // namespace

std::string timeText(double time, double dt) {
  // Enough decimals to tell consecutive steps apart (dt = 0.01 -> 2, 0.005 -> 3), at least 1.
  int decimals = 1;
  if (dt > 0 && std::isfinite(dt)) decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(dt) - 1e-9)), 1, 9);
  char text[64];
  std::snprintf(text, sizeof text, "t = %.*f", decimals, time);
  return text;
}

double labelCapHeight(int height) { return std::clamp(height / 40.0, 7.0, 48.0); }

Picture makePicture(const SceneFile& file, const State& state, const PathTrails& trails, const View& view) {
  const Scene& scene = file.scene;
  const Appearance& look = file.look;
  Picture pic;
  pic.view = view;
  pic.background = look.background;

  for (const Trail& t : trails.trails()) {
    PathShape path;
    path.color = t.color();
    path.points.reserve(t.size());
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k].allFinite()) path.points.push_back(t[k]);
    if (path.points.size() >= 2) pic.paths.push_back(std::move(path));
  }

  const int n = std::min(scene.numParticles(), state.numParticles());
  for (int e = 0; e < static_cast<int>(scene.edges.size()); ++e) {
    const Edge& edge = scene.edges[e];
    if (edge.i < 0 || edge.j < 0 || edge.i >= n || edge.j >= n) continue;
    const Vec2 a = at(state.x, edge.i), b = at(state.x, edge.j);
    if (!a.allFinite() || !b.allFinite()) continue;
    pic.edges.push_back({a, b, edge.radius, colorOr(look.edgeColors, e, kDefaultEdgeColor)});
  }

  for (int h = 0; h < static_cast<int>(scene.halfplanes.size()); ++h) {
    const HalfPlane& plane = scene.halfplanes[h];
    if (!plane.point.allFinite() || !plane.normal.allFinite() || plane.normal.squaredNorm() == 0) continue;
    pic.halfplanes.push_back({plane.point, plane.normal, colorOr(look.halfplaneColors, h, kDefaultHalfplaneColor)});
  }

  pic.particles.reserve(n);
  for (int i = 0; i < n; ++i) {
    const Vec2 c = at(state.x, i);
    if (!c.allFinite()) continue;
    pic.particles.push_back({c, scene.radius[i], colorOr(look.particleColors, i, kDefaultParticleColor)});
  }

  const double cap = labelCapHeight(view.height);
  pic.labels.push_back({timeText(state.time, scene.dt), Vec2(0.7 * cap, view.height - 1.7 * cap), cap,
                        inverse(look.background)});
  return pic;
}

std::vector<Vec2> solidSideInView(const HalfPlaneShape& h, const View& view, double margin, double offset) {
  const std::vector<Vec2> rect = {{-margin, -margin},
                                  {view.width + margin, -margin},
                                  {view.width + margin, view.height + margin},
                                  {-margin, view.height + margin}};
  // Pixel space is the world scaled uniformly (y stays up), so the normal keeps its direction.
  const Vec2 p = view.toPixel(h.point);
  const Vec2 nHat = h.normal.normalized();
  auto inside = [&](const Vec2& x) { return (x - p).dot(nHat) - offset; };  // <= 0: solid side
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < rect.size(); ++k) {  // Sutherland-Hodgman against one line
    const Vec2& a = rect[k];
    const Vec2& b = rect[(k + 1) % rect.size()];
    const double da = inside(a), db = inside(b);
    if (da <= 0) out.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  if (out.size() < 3) out.clear();
  return out;
}

}  // namespace fosssim::render
