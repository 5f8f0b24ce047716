// fosssim-scenegen's files (toSceneFile, written by sceneToXml): read back by the loader they are the benchmark's scene
// exactly (every number round-trips), every number is as short as it can be and still do that,
// and the <viewport> shows every particle and every half-plane's anchor point.
#include "bench_scenes.h"

#include "fosssim/io/scene_file.h"
#include "fosssim/io/scene_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <cstdlib>
#include <regex>

namespace fosssim {
namespace {

struct Written {
  bench::BenchScene scene;
  std::string text;
  SceneFile loaded;
};

Written write(const std::string& kind, int n) {
  Written w;
  EXPECT_TRUE(bench::makeScene(kind, n, "hybrid", 3, w.scene));
  bench::BenchScene copy;  // the same scene again (the seed fixes it): toSceneFile takes its own
  EXPECT_TRUE(bench::makeScene(kind, n, "hybrid", 3, copy));
  const Status written = sceneToXml(bench::toSceneFile(std::move(copy)), w.text);
  EXPECT_TRUE(written.isOk()) << written.message();
  const Status s = parseScene(w.text, kind + ".xml", w.loaded);
  EXPECT_TRUE(s.isOk()) << s.message();
  return w;
}

TEST(SceneFile, ReadsBackAsTheSameSceneBitForBit) {
  for (const std::string& kind : bench::sceneKinds()) {
    SCOPED_TRACE(kind);
    const Written w = write(kind, 60);
    const Scene& a = w.scene.scene;
    const Scene& b = w.loaded.scene;
    ASSERT_EQ(b.numParticles(), a.numParticles());
    EXPECT_TRUE(w.loaded.initial.x == w.scene.state.x);  // exact: == on doubles, not a tolerance
    EXPECT_TRUE(w.loaded.initial.v == w.scene.state.v);
    for (int p = 0; p < a.numParticles(); ++p) {
      EXPECT_EQ(b.massOf(p), a.massOf(p));
      EXPECT_EQ(b.radius[p], a.radius[p]);
      EXPECT_EQ(b.isFixed(p), a.isFixed(p));
    }
    ASSERT_EQ(b.edges.size(), a.edges.size());
    ASSERT_EQ(b.halfplanes.size(), a.halfplanes.size());
    for (size_t h = 0; h < a.halfplanes.size(); ++h) {
      EXPECT_TRUE(b.halfplanes[h].point == a.halfplanes[h].point);
      EXPECT_TRUE(b.halfplanes[h].normal == a.halfplanes[h].normal);
    }
    EXPECT_EQ(b.dt, a.dt);
    EXPECT_EQ(b.duration, a.duration);
    EXPECT_EQ(b.collision.cor, a.collision.cor);
  }
}

// Shortest: for every number in the file, no decimal with fewer significant digits reads back as
// the same double (so 0.05 is written "0.05", not "0.050000000000000003").
TEST(SceneFile, EveryNumberIsTheShortestThatReadsBack) {
  const std::regex number("=\"(-?[0-9][0-9.e+-]*)\"");
  for (const std::string& kind : bench::sceneKinds()) {
    SCOPED_TRACE(kind);
    const Written w = write(kind, 60);
    int numbers = 0;
    for (std::sregex_iterator it(w.text.begin(), w.text.end(), number), end; it != end; ++it) {
      const std::string text = (*it)[1];
      const double value = std::strtod(text.c_str(), nullptr);
      std::string mantissa = text.substr(0, text.find('e'));
      mantissa.erase(0, mantissa.find_first_not_of("-0."));  // leading zeros are not significant
      if (mantissa.find('.') == std::string::npos)  // nor an integer's trailing ones (400 is 4e+02)
        mantissa.erase(mantissa.find_last_not_of('0') + 1);
      const int digits = static_cast<int>(mantissa.size() - (mantissa.find('.') == std::string::npos ? 0 : 1));
      for (int shorter = 1; shorter < digits; ++shorter) {
        std::ostringstream candidate;
        candidate << std::setprecision(shorter) << value;  // %g with `shorter` significant digits
        EXPECT_NE(std::strtod(candidate.str().c_str(), nullptr), value)
            << text << " could be written " << candidate.str();
      }
      ++numbers;
    }
    EXPECT_GT(numbers, 60 * 5) << "the pattern found too few numbers to check";
  }
}

TEST(SceneFile, TheViewportFramesParticlesAndHalfPlanes) {
  for (const std::string& kind : bench::sceneKinds()) {
    SCOPED_TRACE(kind);
    const Written w = write(kind, 200);
    ASSERT_TRUE(w.loaded.look.viewport.has_value()) << "no <viewport>";
    const Viewport& v = *w.loaded.look.viewport;
    // A square picture shows [cx - size, cx + size] x [cy - size, cy + size].
    const auto inside = [&](double x, double y, double r) {
      return x - r >= v.cx - v.size && x + r <= v.cx + v.size && y - r >= v.cy - v.size && y + r <= v.cy + v.size;
    };
    const Scene& s = w.loaded.scene;
    for (int p = 0; p < s.numParticles(); ++p)
      EXPECT_TRUE(inside(w.loaded.initial.x[2 * p], w.loaded.initial.x[2 * p + 1], s.radius[p])) << "particle " << p;
    for (const HalfPlane& h : s.halfplanes) EXPECT_TRUE(inside(h.point.x(), h.point.y(), 0));
    // ... and frames them: the scene's extent fills most of the view, not a corner of it.
    double lo = INFINITY, hi = -INFINITY;
    for (int p = 0; p < s.numParticles(); ++p) {
      lo = std::min(lo, w.loaded.initial.x[2 * p + 1]);
      hi = std::max(hi, w.loaded.initial.x[2 * p + 1]);
    }
    for (const HalfPlane& h : s.halfplanes) {
      lo = std::min(lo, h.point.y());
      hi = std::max(hi, h.point.y());
    }
    double left = INFINITY, right = -INFINITY;
    for (int p = 0; p < s.numParticles(); ++p) {
      left = std::min(left, w.loaded.initial.x[2 * p]);
      right = std::max(right, w.loaded.initial.x[2 * p]);
    }
    EXPECT_GT(std::max(hi - lo, right - left), v.size) << "the scene spans less than half the view";
  }
}

}  // namespace
}  // namespace fosssim
