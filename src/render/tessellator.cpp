#include "fosssim/render/tessellator.h"

#include "fosssim/render/stroke_font.h"

#include <algorithm>
#include <cmath>

namespace fosssim::render {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kFeather = 0.5;  // half-width of the anti-aliasing band, pixels

struct Rgba {
  float r, g, b, a;
};

Rgba rgba(const Rgb& c, double alpha) {
  return {static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b), static_cast<float>(alpha)};
}

class MeshBuilder {
 public:
  explicit MeshBuilder(Mesh& mesh) : mesh_(mesh) {}

  void vertex(const Vec2& p, const Rgba& c) {
    mesh_.xy.push_back(static_cast<float>(p.x()));
    mesh_.xy.push_back(static_cast<float>(p.y()));
    mesh_.rgba.insert(mesh_.rgba.end(), {c.r, c.g, c.b, c.a});
  }
  void triangle(const Vec2& p0, const Rgba& c0, const Vec2& p1, const Rgba& c1, const Vec2& p2, const Rgba& c2) {
    vertex(p0, c0);
    vertex(p1, c1);
    vertex(p2, c2);
  }
  /// The quad p0 p1 p2 p3 (in order around it) as two triangles.
  void quad(const Vec2& p0, const Rgba& c0, const Vec2& p1, const Rgba& c1, const Vec2& p2, const Rgba& c2,
            const Vec2& p3, const Rgba& c3) {
    triangle(p0, c0, p1, c1, p2, c2);
    triangle(p0, c0, p2, c2, p3, c3);
  }

  /// A capsule (stadium) around segment a-b of radius r, pixels; a == b gives a disk. The solid
  /// part reaches r - feather, the rim fades out to r + feather. A shape thinner than a pixel
  /// keeps its rim but with the opacity of its coverage, so small particles stay visible.
  void capsule(const Vec2& a, const Vec2& b, double r, const Rgb& color) {
    const double len = (b - a).norm();
    const Vec2 d = len > 1e-12 ? Vec2((b - a) / len) : Vec2(1, 0);
    const Vec2 n(-d.y(), d.x());
    const double inner = std::max(r - kFeather, 0.0), outer = r + kFeather;
    const Rgba solid = rgba(color, std::min(1.0, r / kFeather));  // r < feather: partial coverage
    const Rgba clear = rgba(color, 0.0);
    const int half = std::max(4, circleSegments(outer) / 2);
    // The outline: a half circle around b from -n through d to +n, then one around a from +n
    // through -d to -n; counter-clockwise, each point with its outward (radial) direction.
    ring_.clear();
    for (int end = 0; end < 2; ++end) {
      const Vec2& centre = end == 0 ? b : a;
      for (int k = 0; k <= half; ++k) {
        const double phi = -0.5 * kPi + kPi * k / half + (end == 0 ? 0.0 : kPi);
        ring_.push_back({centre, std::cos(phi) * d + std::sin(phi) * n});
      }
    }
    const Vec2 mid = 0.5 * (a + b);
    for (std::size_t k = 0; k < ring_.size(); ++k) {
      const RingPoint& p = ring_[k];
      const RingPoint& q = ring_[(k + 1) % ring_.size()];
      const Vec2 pi = p.centre + inner * p.dir, qi = q.centre + inner * q.dir;
      if (inner > 0) triangle(mid, solid, pi, solid, qi, solid);
      quad(pi, solid, p.centre + outer * p.dir, clear, q.centre + outer * q.dir, clear, qi, solid);
    }
  }

  /// A straight line of `width` pixels from a to b with feathered sides; `extend` lengthens it
  /// by half its width at both ends so that the strokes of a glyph meet without notches.
  void line(Vec2 a, Vec2 b, double width, const Rgb& color, bool extend) {
    const double len = (b - a).norm();
    if (len < 1e-12 && !extend) return;
    const Vec2 d = len > 1e-12 ? Vec2((b - a) / len) : Vec2(1, 0);
    if (extend) {
      a -= 0.5 * width * d;
      b += 0.5 * width * d;
    }
    const Vec2 n(-d.y(), d.x());
    const double h = 0.5 * width;
    const double inner = std::max(h - kFeather, 0.0), outer = h + kFeather;
    const Rgba solid = rgba(color, std::min(1.0, h / kFeather)), clear = rgba(color, 0.0);
    quad(a - inner * n, solid, b - inner * n, solid, b + inner * n, solid, a + inner * n, solid);
    quad(a + inner * n, solid, b + inner * n, solid, b + outer * n, clear, a + outer * n, clear);
    quad(a - outer * n, clear, b - outer * n, clear, b - inner * n, solid, a - inner * n, solid);
  }

  void halfplane(const HalfPlaneShape& h, const View& view, const Rgb& color) {
    // The solid side up to half a pixel inside the boundary, opaque...
    const std::vector<Vec2> poly = solidSideInView(h, view, 2.0, -kFeather);
    const Rgba solid = rgba(color, 1.0), clear = rgba(color, 0.0);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) triangle(poly[0], solid, poly[k], solid, poly[k + 1], solid);
    // ...then a band across the boundary fading out, where the line crosses the view.
    const Vec2 p = view.toPixel(h.point), nHat = h.normal.normalized(), t(-nHat.y(), nHat.x());
    const Vec2 centre(0.5 * view.width, 0.5 * view.height);
    const double reach = view.width + view.height;
    if (std::abs((centre - p).dot(nHat)) > reach) return;
    const Vec2 q = p + (centre - p).dot(t) * t;
    const Vec2 q0 = q - reach * t, q1 = q + reach * t;
    quad(q0 - kFeather * nHat, solid, q1 - kFeather * nHat, solid, q1 + kFeather * nHat, clear, q0 + kFeather * nHat,
         clear);
  }

 private:
  struct RingPoint {
    Vec2 centre, dir;
  };
  Mesh& mesh_;
  std::vector<RingPoint> ring_;  // scratch, reused across shapes
};

}  // namespace

int circleSegments(double radiusPixels) {
  // A chord of angle a departs from the arc by r (1 - cos(a/2)); keep that below 0.1 pixel.
  if (!(radiusPixels > 0.1)) return 8;
  const double a = 2.0 * std::acos(1.0 - 0.1 / radiusPixels);
  return std::clamp(static_cast<int>(std::ceil(2.0 * kPi / a)), 8, 1024);
}

void tessellate(const Picture& pic, Mesh& mesh) {
  MeshBuilder out(mesh);
  const View& view = pic.view;
  const double scale = view.scale();
  // Cull whatever lies entirely outside the picture: zoomed-in windows and far-flung particles.
  auto visible = [&](const Vec2& a, const Vec2& b, double margin) {
    const Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
    return hi.x() + margin >= -1 && hi.y() + margin >= -1 && lo.x() - margin <= view.width + 1 &&
           lo.y() - margin <= view.height + 1;
  };

  const double pathWidth = 1.5;
  for (const PathShape& path : pic.paths)
    for (std::size_t k = 0; k + 1 < path.points.size(); ++k) {
      const Vec2 a = view.toPixel(path.points[k]), b = view.toPixel(path.points[k + 1]);
      if (visible(a, b, pathWidth))
        out.line(a, b, pathWidth, path.color, false);
    }

  for (const CapsuleShape& e : pic.edges) {
    const Vec2 a = view.toPixel(e.a), b = view.toPixel(e.b);
    const double r = e.radius * scale;
    if (visible(a, b, r)) out.capsule(a, b, r, e.color);
  }

  for (const HalfPlaneShape& h : pic.halfplanes) out.halfplane(h, view, h.color);

  for (const DiskShape& p : pic.particles) {
    const Vec2 c = view.toPixel(p.center);
    const double r = p.radius * scale;
    if (visible(c, c, r)) out.capsule(c, c, r, p.color);
  }

  for (const PanelShape& panel : pic.panels) {
    const Rgba c = rgba(panel.color, panel.alpha);
    out.quad(panel.lo, c, Vec2(panel.hi.x(), panel.lo.y()), c, panel.hi, c, Vec2(panel.lo.x(), panel.hi.y()), c);
  }

  for (const LabelShape& label : pic.labels) {
    const double w = strokeWidth(label.capHeight);
    for (const StrokeSegment& s : layoutText(label.text, label.origin, label.capHeight))
      out.line(s.a, s.b, w, label.color, true);
  }
}

}  // namespace fosssim::render
