#include "pile.h"

namespace fosssim::study {

SceneBuilder pileScene(const Method& method, double dt, int columns, int rows) {
  constexpr double r = 0.1, spacing = 2 * r + 0.02;
  const double halfWidth = 0.5 * (columns * spacing + 0.1);
  SceneBuilder x;
  x.duration(1.5).method(method, dt).gravity(Vec2(0, -9.81));
  x.halfplane(Vec2(0, 0), Vec2(0, 1));
  x.halfplane(Vec2(-halfWidth, 0), Vec2(1, 0));
  x.halfplane(Vec2(halfWidth, 0), Vec2(-1, 0));
  unsigned seed = 12345;  // a fixed linear congruential sequence: the same pile every run
  auto jitter = [&seed] {
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 16) % 2001) / 1000.0 - 1.0;  // in [-1, 1]
  };
  for (int row = 0; row < rows; ++row)
    for (int c = 0; c < columns; ++c) {
      const Vec2 p(-halfWidth + 0.05 + r + 0.01 + c * spacing, r + 0.05 + row * spacing);
      x.particle(p, Vec2(0.5 * jitter(), 0.5 * jitter()), 1.0, false, r);
    }
  return x;
}

}  // namespace fosssim::study
