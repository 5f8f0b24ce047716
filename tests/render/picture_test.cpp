// The picture model without OpenGL: camera, trails, frame schedule, shapes, tessellation, font.
#include "render_test_support.h"

#include "fosssim/render/camera.h"
#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/path_trails.h"
#include "fosssim/render/picture.h"
#include "fosssim/render/stroke_font.h"
#include "fosssim/render/tessellator.h"

#include <cmath>

namespace fosssim::render {
namespace {

using testing::kShapesScene;
using testing::parsed;

State positions(std::vector<Vec2> xs) {
  State s;
  s.x.resize(2 * static_cast<Eigen::Index>(xs.size()));
  s.v = VecX::Zero(s.x.size());
  for (std::size_t i = 0; i < xs.size(); ++i) at(s.x, static_cast<int>(i)) = xs[i];
  return s;
}

TEST(Camera, FitsTheParticlesBoundingBoxWithMargin) {
  const Camera c = fitParticles(positions({{-1, 0}, {3, 1}}), 512, 512);
  EXPECT_DOUBLE_EQ(c.cx, 1);
  EXPECT_DOUBLE_EQ(c.cy, 0.5);
  EXPECT_DOUBLE_EQ(c.size, 1.2 * 2);  // rx = 2 dominates ry = 0.5
}

TEST(Camera, ZeroExtentsCountAsOne) {
  const Camera c = fitParticles(positions({{2, 3}}), 512, 512);
  EXPECT_DOUBLE_EQ(c.cx, 2);
  EXPECT_DOUBLE_EQ(c.cy, 3);
  EXPECT_DOUBLE_EQ(c.size, 1.2);
}

TEST(Camera, EveryParticleIsVisibleWhateverTheAspectRatio) {
  const State s = positions({{-5, -1}, {5, 1}, {0, 0.5}});
  for (auto [w, h] : {std::pair{512, 512}, {200, 600}, {800, 100}}) {
    View v;
    v.width = w;
    v.height = h;
    v.camera = fitParticles(s, w, h);
    for (int i = 0; i < 3; ++i) {
      const Vec2 p = v.toPixel(at(s.x, i));
      EXPECT_GE(p.x(), 0) << w << "x" << h;
      EXPECT_LE(p.x(), w) << w << "x" << h;
      EXPECT_GE(p.y(), 0) << w << "x" << h;
      EXPECT_LE(p.y(), h) << w << "x" << h;
    }
  }
}

TEST(Camera, ViewportWinsOverFitting) {
  Appearance look;
  look.viewport = Viewport{1, 2, 3};
  const Camera c = initialCamera(look, positions({{100, 100}}), 512, 512);
  EXPECT_EQ(c.cx, 1);
  EXPECT_EQ(c.cy, 2);
  EXPECT_EQ(c.size, 3);
}

TEST(View, MapsWorldToPixelsAndBack) {
  View v;
  v.width = 100;
  v.height = 80;
  v.camera = {0, 0, 1};
  EXPECT_DOUBLE_EQ(v.scale(), 40);
  const Vec2 p = v.toPixel({0.5, 0.25});
  EXPECT_DOUBLE_EQ(p.x(), 70);
  EXPECT_DOUBLE_EQ(p.y(), 50);
  EXPECT_TRUE(v.toWorld(p).isApprox(Vec2(0.5, 0.25)));
}

TEST(PathTrails, KeepTheLastCeilDurationOverDtPositions) {
  ParticlePath path;
  path.particle = 0;
  path.duration = 0.025;  // ceil(0.025 / 0.01) = 3 positions
  PathTrails trails({path}, 0.01);
  ASSERT_EQ(trails.trails().size(), 1u);
  EXPECT_EQ(trails.trails()[0].capacity(), 3u);
  for (int k = 0; k < 5; ++k) trails.record(positions({{double(k), 0}}));
  const Trail& t = trails.trails()[0];
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].x(), 2);  // oldest kept
  EXPECT_EQ(t[2].x(), 4);  // newest
}

TEST(FrameSequence, NumbersFramesFromOneEveryKthStep) {
  const SceneFile file = parsed(kShapesScene);
  FrameSequence seq(64, 64, 3);
  seq.start(file, file.initial);
  std::vector<long> due;
  for (long step = 1; step <= 10; ++step)
    if (seq.advance(file.initial)) {
      due.push_back(step);
      EXPECT_EQ(seq.frameNumber(), static_cast<long>(due.size()));
    }
  EXPECT_EQ(due, (std::vector<long>{3, 6, 9}));
}

TEST(Picture, HoldsTheShapesInDrawOrderWithTheScenesColours) {
  const SceneFile file = parsed(kShapesScene);
  PathTrails trails(file.look.paths, file.scene.dt);
  trails.record(file.initial);
  trails.record(file.initial);
  View view;
  view.width = 100;
  view.height = 80;
  view.camera = initialCamera(file.look, file.initial, 100, 80);
  const Picture pic = makePicture(file, file.initial, trails, view);
  EXPECT_EQ(pic.paths.size(), 1u);
  ASSERT_EQ(pic.edges.size(), 1u);
  EXPECT_EQ(pic.edges[0].radius, 0.05);
  EXPECT_EQ(pic.edges[0].color.g, kDefaultEdgeColor.g);
  ASSERT_EQ(pic.halfplanes.size(), 1u);
  ASSERT_EQ(pic.particles.size(), 4u);
  EXPECT_EQ(pic.particles[0].color.r, 1);
  EXPECT_EQ(pic.particles[1].color.r, kDefaultParticleColor.r);
  ASSERT_EQ(pic.labels.size(), 1u);
  EXPECT_EQ(pic.labels[0].text, "t = 0.00");
  EXPECT_NEAR(pic.labels[0].color.r, 0.8, 1e-12);  // 1 - background
  EXPECT_NEAR(pic.labels[0].color.b, 0.4, 1e-12);
}

TEST(Picture, TimeTextHasTheDecimalsOfTheStep) {
  EXPECT_EQ(timeText(1.25, 0.005), "t = 1.250");
  EXPECT_EQ(timeText(2, 0.01), "t = 2.00");
  EXPECT_EQ(timeText(2, 0.1), "t = 2.0");
  EXPECT_EQ(timeText(3, 1), "t = 3.0");
}

TEST(Picture, SolidSideIsClippedToTheView) {
  View view;
  view.width = 100;
  view.height = 80;
  view.camera = {0, 0, 1};
  // Boundary y = -0.5 (pixel row 20), normal up: the solid side is the bottom quarter.
  const HalfPlaneShape h{Vec2(0, -0.5), Vec2(0, 2), Rgb{}};
  const std::vector<Vec2> poly = solidSideInView(h, view, 0, 0);
  ASSERT_EQ(poly.size(), 4u);
  for (const Vec2& p : poly) EXPECT_LE(p.y(), 20 + 1e-9);
  // A half-plane whose solid side lies outside the view gives nothing.
  EXPECT_TRUE(solidSideInView({Vec2(0, -5), Vec2(0, 1), Rgb{}}, view, 0, 0).empty());
}

TEST(Tessellator, CirclesAreSmoothAtAnySize) {
  for (double r : {0.5, 3.0, 25.0, 300.0}) {
    const int n = circleSegments(r);
    const double sagitta = r * (1 - std::cos(3.14159265358979 / n));
    EXPECT_LE(sagitta, 0.1 + 1e-12) << r;
  }
  EXPECT_GE(circleSegments(0.01), 8);
}

TEST(Tessellator, MakesTrianglesWithFeatheredRims) {
  const SceneFile file = parsed(kShapesScene);
  View view;
  view.width = 100;
  view.height = 80;
  view.camera = initialCamera(file.look, file.initial, 100, 80);
  Mesh mesh;
  tessellate(makePicture(file, file.initial, PathTrails(), view), mesh);
  ASSERT_GT(mesh.vertexCount(), 0u);
  EXPECT_EQ(mesh.vertexCount() % 3, 0u);
  EXPECT_EQ(mesh.rgba.size(), 4 * mesh.vertexCount());
  bool opaque = false, clear = false;
  for (std::size_t k = 3; k < mesh.rgba.size(); k += 4) {
    opaque |= mesh.rgba[k] == 1.0f;
    clear |= mesh.rgba[k] == 0.0f;
  }
  EXPECT_TRUE(opaque);
  EXPECT_TRUE(clear);  // the anti-aliasing rims fade out to transparent
}

TEST(StrokeFont, EveryPrintableCharacterHasStrokesInItsCell) {
  const double cap = 12;
  for (char c = 33; c < 127; ++c) {
    const std::vector<StrokeSegment> segs = layoutText(std::string(1, c), Vec2(0, 0), cap);
    EXPECT_FALSE(segs.empty()) << "'" << c << "'";
    for (const StrokeSegment& s : segs)
      for (const Vec2& p : {s.a, s.b}) {
        EXPECT_GE(p.x(), 0) << c;
        EXPECT_LE(p.x(), 4 * cap / 6) << c;       // four grid units wide
        EXPECT_GE(p.y(), -2 * cap / 6 - 1e-9) << c;  // descenders
        EXPECT_LE(p.y(), 7 * cap / 6 + 1e-9) << c;   // '$' reaches a little above capitals
      }
  }
  EXPECT_TRUE(layoutText(" ", Vec2(0, 0), cap).empty());
  EXPECT_DOUBLE_EQ(textWidth("abc", cap), 3 * cap);
}

}  // namespace
}  // namespace fosssim::render
