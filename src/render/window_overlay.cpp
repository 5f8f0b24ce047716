#include "fosssim/render/window_overlay.h"

#include "fosssim/render/stroke_font.h"

#include <algorithm>

namespace fosssim::render {
namespace {

constexpr double kPanelAlpha = 0.85;          // the scene still shows faintly through
constexpr Rgb kErrorPanel{0.55, 0.0, 0.0};
constexpr Rgb kErrorInk{1.0, 1.0, 1.0};

Rgb inverse(const Rgb& c) { return {1 - c.r, 1 - c.g, 1 - c.b}; }

/// The cap height at which the longest of `lines` fits in `room` pixels, at most `cap`.
double fitting(const std::vector<std::string>& lines, double cap, double room) {
  for (const std::string& line : lines) {
    const double w = textWidth(line, cap);
    if (w > room && w > 0) cap *= room / w;
  }
  return std::max(cap, 4.0);
}

/// A block of lines on a panel `width` wide whose top edge is at `top`, text left-aligned.
void block(Picture& pic, const std::vector<std::string>& lines, double cap, double left, double top, double width,
           const Rgb& panel, double alpha, const Rgb& ink) {
  const double pad = 0.7 * cap, step = 1.7 * cap;
  const double height = 2 * pad + cap + step * static_cast<double>(lines.size() - 1) + 0.35 * cap;
  pic.panels.push_back({Vec2(left, top - height), Vec2(left + width, top), panel, alpha});
  double baseline = top - pad - cap;
  for (const std::string& line : lines) {
    pic.labels.push_back({line, Vec2(left + pad, baseline), cap, ink});
    baseline -= step;
  }
}

}  // namespace

const std::vector<std::string>& windowKeys() {
  static const std::vector<std::string> keys = {
      "space    run / pause",
      "s        one step (and pause)",
      "r        restart from t = 0",
      "c        re-centre: the viewport, or follow the particles",
      "+ -      zoom in / out (the camera then stays put)",
      "arrows   pan (or drag with the mouse; the wheel zooms)",
      "i        save an SVG picture of this moment",
      "p        save a PNG screenshot of the window",
      "h ?      this help (any key closes it)",
      "q Esc    quit",
  };
  return keys;
}

void addWindowOverlay(Picture& pic, const WindowOverlay& overlay) {
  const double w = pic.view.width, h = pic.view.height;
  const Rgb ink = inverse(pic.background);
  const double cap = labelCapHeight(pic.view.height);

  // The status line along the bottom, on a full-width panel; a note just above it.
  // Both in the letters the longer of them fits in.
  const double lineCap = fitting({overlay.status, overlay.note}, cap, w - 1.4 * cap);
  double bottom = 0;
  for (const std::string* line : {&overlay.status, &overlay.note}) {
    if (line->empty()) continue;
    block(pic, {*line}, lineCap, 0, bottom + 2.75 * lineCap, w, pic.background, kPanelAlpha, ink);
    bottom += 2.75 * lineCap;
  }

  if (!overlay.error.empty()) {
    const double c = std::max(cap, 9.0);
    const auto perLine = static_cast<std::size_t>(std::max(8.0, (w - 1.4 * c) / textWidth("M", c)));
    std::vector<std::string> lines = wrapText("The run stopped: " + overlay.error, perLine);
    lines.push_back("");
    lines.push_back("q closes the window (the message goes to the terminal too)");
    const double fit = fitting(lines, c, w - 1.4 * c);
    const double height = 1.4 * fit + fit + 1.7 * fit * static_cast<double>(lines.size() - 1) + 0.35 * fit;
    block(pic, lines, fit, 0, std::min(h, 0.5 * (h + height)), w, kErrorPanel, 0.92, kErrorInk);
  }

  if (overlay.help) {
    std::vector<std::string> lines = {"FOSSSim keys"};
    lines.push_back("");
    for (const std::string& k : windowKeys()) lines.push_back(k);
    const double c = fitting(lines, cap, 0.9 * w - 1.4 * cap);
    double width = 0;
    for (const std::string& line : lines) width = std::max(width, textWidth(line, c));
    width += 1.4 * c;
    const double height = 2.75 * c + 1.7 * c * static_cast<double>(lines.size() - 1);
    block(pic, lines, c, 0.5 * (w - width), std::min(h, 0.5 * (h + height)), width, pic.background, 0.93, ink);
  }
}

}  // namespace fosssim::render
