#include "fosssim/render/picture.h"

#include "fosssim/render/stroke_font.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

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

std::vector<std::string> wrapText(const std::string& text, std::size_t width) {
  width = std::max<std::size_t>(width, 1);
  std::vector<std::string> lines;
  std::string line;
  std::size_t k = 0;
  while (k < text.size()) {
    if (std::isspace(static_cast<unsigned char>(text[k]))) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < text.size() && !std::isspace(static_cast<unsigned char>(text[end]))) ++end;
    std::string word = text.substr(k, end - k);
    k = end;
    while (word.size() > width) {  // a word longer than a line is cut
      if (!line.empty()) lines.push_back(std::move(line)), line.clear();
      lines.push_back(word.substr(0, width));
      word.erase(0, width);
    }
    if (!line.empty() && line.size() + 1 + word.size() > width) lines.push_back(std::move(line)), line.clear();
    if (!word.empty()) line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

Picture titleCard(const SceneFile& file, const View& view) {
  Picture pic;
  pic.view = view;
  pic.background = file.look.background;
  const Rgb ink = inverse(file.look.background);
  const std::string name = std::filesystem::path(file.path).filename().string();
  const std::string title = file.description.empty() ? name : file.description;
  // Letters a 16th of the height tall (or smaller, so that a line holds at least 24 of them);
  // a long description gets smaller letters, down to the time label's size, and only then is cut.
  const double usable = 0.9 * view.width;
  const double perCap = textWidth("M", 1.0);  // advance per unit of cap height
  const double largest = std::max(4.0, std::min(view.height / 16.0, usable / (24 * perCap)));
  const double smallest = std::min(largest, labelCapHeight(view.height));
  double cap = largest;
  std::size_t perLine = 1, maxLines = 1;
  std::vector<std::string> lines;
  for (;;) {
    perLine = static_cast<std::size_t>(std::max(1.0, std::floor(usable / (perCap * cap))));
    maxLines = static_cast<std::size_t>(std::max(1.0, std::floor(0.7 * view.height / (1.8 * cap))));
    lines = wrapText(title, perLine);
    if (lines.size() <= maxLines || cap <= smallest) break;
    cap = std::max(smallest, cap * 0.9);
  }
  const double lineStep = 1.8 * cap;
  if (lines.size() > maxLines) {  // still too long: as much as fits, then an ellipsis
    lines.resize(maxLines);
    std::string& last = lines.back();
    if (last.size() + 3 > perLine) last.resize(perLine > 3 ? perLine - 3 : 0);
    last += "...";
  }
  const double small = std::max(0.5 * cap, std::min(cap, 7.0));
  const bool footer = !file.description.empty() && !name.empty();
  const double block = lineStep * (static_cast<double>(lines.size()) - 1) + cap + (footer ? 2.5 * small : 0.0);
  double baseline = 0.5 * view.height + 0.5 * block - cap;  // the block centred vertically
  for (const std::string& line : lines) {
    pic.labels.push_back({line, Vec2(0.5 * (view.width - textWidth(line, cap)), baseline), cap, ink});
    baseline -= lineStep;
  }
  if (footer) {
    const double y = baseline + lineStep - 2.5 * small;  // below the last line's descenders
    pic.labels.push_back({name, Vec2(0.5 * (view.width - textWidth(name, small)), y), small, ink});
  }
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
