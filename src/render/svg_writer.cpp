#include "fosssim/render/svg_writer.h"

#include "fosssim/io/staged_file.h"

#include "fosssim/render/stroke_font.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace fosssim::render {
namespace {

/// Appends numbers and colours without iostreams (an SVG per step adds up for long runs).
class SvgText {
 public:
  SvgText(int width, int height) : width_(width), height_(height) {}
  SvgText& operator<<(const char* s) {
    out_ += s;
    return *this;
  }
  SvgText& operator<<(const std::string& s) {
    out_ += s;
    return *this;
  }
  /// Pixels this far from the picture lie millions of pictures away. A particle at px="1e50", or
  /// any particle under a viewport of size 1e-300, is up to 1e308 pixels out: "%.2f" would write
  /// 300 digits, and viewers, computing in single precision, could not draw it anyway.
  static constexpr double kFarPixels = 1e9;

  /// `p` (pixels), moved towards the picture's centre onto the square kFarPixels around it when it
  /// lies beyond: a segment from a point in view towards it keeps its direction (to within the
  /// picture's size / kFarPixels radians) and still leaves the picture.
  Vec2 near(Vec2 p) const {
    const Vec2 centre(width_ / 2.0, height_ / 2.0);
    const double far = (p - centre).lpNorm<Eigen::Infinity>();
    if (far > kFarPixels && std::isfinite(far)) p = centre + (p - centre) * (kFarPixels / far);
    return p;
  }

  /// A coordinate or length with two decimals (a hundredth of a pixel), trailing zeros dropped.
  /// Points come through near(); lengths (radii, stroke widths) are cut to twice kFarPixels, so
  /// that every number fits the buffer ("-2000000000.00": 14 characters): snprintf returns what
  /// it would have written, not what it wrote.
  SvgText& num(double v) {
    if (!std::isfinite(v)) v = 0;
    v = std::clamp(v, -2 * kFarPixels, 2 * kFarPixels);
    char buf[32];
    int n = std::snprintf(buf, sizeof buf, "%.2f", v);
    while (n > 0 && buf[n - 1] == '0') --n;
    if (n > 0 && buf[n - 1] == '.') --n;
    if (n == 2 && buf[0] == '-' && buf[1] == '0') n = 1, buf[0] = '0';  // "-0" -> "0"
    out_.append(buf, static_cast<std::size_t>(n));
    return *this;
  }
  /// A point in pixel coordinates (y up) as SVG's "x,y" (y down).
  SvgText& point(const Vec2& pixel) {
    const Vec2 p = near(pixel);
    num(p.x());
    out_ += ',';
    return num(height_ - p.y());
  }
  SvgText& x(double v) { return num(v); }
  SvgText& y(double v) { return num(height_ - v); }
  SvgText& color(const Rgb& c) {
    auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); };
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    out_ += buf;
    return *this;
  }
  SvgText& escaped(const std::string& s) {
    for (char c : s) {
      if (c == '<') out_ += "&lt;";
      else if (c == '>') out_ += "&gt;";
      else if (c == '&') out_ += "&amp;";
      else if (c == '"') out_ += "&quot;";
      else out_ += c;
    }
    return *this;
  }
  std::string take() { return std::move(out_); }

 private:
  int width_, height_;
  std::string out_;
};

}  // namespace

std::string svgDocument(const Picture& pic) {
  const View& view = pic.view;
  const double scale = view.scale();
  SvgText s(view.width, view.height);
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << std::to_string(view.width) << "\" height=\""
    << std::to_string(view.height) << "\" viewBox=\"0 0 " << std::to_string(view.width) << " "
    << std::to_string(view.height) << "\">\n";
  s << "<rect id=\"background\" x=\"0\" y=\"0\" width=\"" << std::to_string(view.width) << "\" height=\""
    << std::to_string(view.height) << "\" fill=\"";
  s.color(pic.background) << "\"/>\n";

  s << "<g id=\"paths\" fill=\"none\" stroke-width=\"1.5\" stroke-linejoin=\"round\">\n";
  for (const PathShape& path : pic.paths) {
    s << "<polyline stroke=\"";
    s.color(path.color) << "\" points=\"";
    for (std::size_t k = 0; k < path.points.size(); ++k) {
      if (k) s << " ";
      s.point(view.toPixel(path.points[k]));
    }
    s << "\"/>\n";
  }
  s << "</g>\n";

  s << "<g id=\"edges\" stroke-linecap=\"round\">\n";
  for (const CapsuleShape& e : pic.edges) {
    const Vec2 a = s.near(view.toPixel(e.a)), b = s.near(view.toPixel(e.b));
    s << "<line x1=\"";
    s.x(a.x()) << "\" y1=\"";
    s.y(a.y()) << "\" x2=\"";
    s.x(b.x()) << "\" y2=\"";
    s.y(b.y()) << "\" stroke-width=\"";
    s.num(2 * e.radius * scale) << "\" stroke=\"";
    s.color(e.color) << "\"/>\n";
  }
  s << "</g>\n";

  s << "<g id=\"halfplanes\">\n";
  for (const HalfPlaneShape& h : pic.halfplanes) {
    const std::vector<Vec2> poly = solidSideInView(h, view, 2.0, 0.0);
    if (poly.empty()) continue;
    s << "<polygon fill=\"";
    s.color(h.color) << "\" points=\"";
    for (std::size_t k = 0; k < poly.size(); ++k) {
      if (k) s << " ";
      s.point(poly[k]);
    }
    s << "\"/>\n";
  }
  s << "</g>\n";

  s << "<g id=\"particles\">\n";
  for (const DiskShape& p : pic.particles) {
    const Vec2 c = s.near(view.toPixel(p.center));
    s << "<circle cx=\"";
    s.x(c.x()) << "\" cy=\"";
    s.y(c.y()) << "\" r=\"";
    s.num(p.radius * scale) << "\" fill=\"";
    s.color(p.color) << "\"/>\n";
  }
  s << "</g>\n";

  if (!pic.panels.empty()) {
    s << "<g id=\"panels\">\n";
    for (const PanelShape& panel : pic.panels) {
      s << "<rect x=\"";
      s.x(panel.lo.x()) << "\" y=\"";
      s.y(panel.hi.y()) << "\" width=\"";
      s.num(panel.hi.x() - panel.lo.x()) << "\" height=\"";
      s.num(panel.hi.y() - panel.lo.y()) << "\" fill=\"";
      s.color(panel.color) << "\" fill-opacity=\"";
      s.num(panel.alpha) << "\"/>\n";
    }
    s << "</g>\n";
  }

  // Labels use the built-in stroke font rather than <text>, so the SVG looks like the PNG
  // whatever fonts the viewer has; the text itself is kept in a <title> for search and screen readers.
  s << "<g id=\"labels\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (const LabelShape& label : pic.labels) {
    s << "<path stroke=\"";
    s.color(label.color) << "\" stroke-width=\"";
    s.num(strokeWidth(label.capHeight)) << "\" d=\"";
    bool first = true;
    Vec2 last(NAN, NAN);
    for (const StrokeSegment& seg : layoutText(label.text, label.origin, label.capHeight)) {
      if (first || seg.a != last) {
        s << (first ? "M" : " M");
        s.point(seg.a);
      }
      s << " L";
      s.point(seg.b);
      last = seg.b;
      first = false;
    }
    s << "\"><title>";
    s.escaped(label.text) << "</title></path>\n";
  }
  s << "</g>\n</svg>\n";
  return s.take();
}

Status writeSvg(const std::string& path, const Picture& picture) {
  // A frame cut short (a full disk) is no picture and would pass for one among whole frames
  // (-m said "frames 1 to 16" next to an empty frame 17): writeWholeFile removes it.
  return io::writeWholeFile(path, svgDocument(picture), "SVG");
}

std::string svgFrameName(const std::string& dir, long number) {
  char name[40];
  std::snprintf(name, sizeof name, "frame%020ld.svg", number);
  return dir.empty() ? std::string(name) : dir + "/" + name;
}

}  // namespace fosssim::render
