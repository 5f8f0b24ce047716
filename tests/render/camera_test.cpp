// FollowCamera: the camera of movies, frames and the window for scenes without a <viewport>.
// Its promises, checked on ballistic motion computed here (no simulator): every particle's disk in
// view in every frame, a view that only grows and grows smoothly, a still scene left alone, and a
// <viewport> or a user's zoom obeyed.
#include "render_test_support.h"

#include "fosssim/render/camera.h"

#include <cmath>

namespace fosssim::render {
namespace {

using testing::parsed;

/// Four disks (r = 0.1) thrown up and sideways with no floor: they leave the first view on every
/// side within a second and fall about 30 m in 2.5 s.
const char* kThrownScene = R"(<scene>
  <duration time="2.5"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="2" vy="4" fixed="0" radius="0.1"/>
  <particle m="1" px="0.5" py="0" vx="-3" vy="6" fixed="0" radius="0.1"/>
  <particle m="1" px="1" py="0.5" vx="0" vy="0" fixed="0" radius="0.1"/>
  <particle m="1" px="-0.5" py="0" vx="-2" vy="1" fixed="0" radius="0.1"/>
  <simplegravity fx="0" fy="-9.81"/>
</scene>)";

/// The scene's particles at time t under gravity alone (the exact parabolas).
State thrownAt(const SceneFile& file, double t) {
  State s = file.initial;
  for (int i = 0; i < s.numParticles(); ++i) {
    const Vec2 x0 = at(file.initial.x, i), v0 = at(file.initial.v, i);
    at(s.x, i) = x0 + t * v0 + 0.5 * t * t * Vec2(0, -9.81);
  }
  s.time = t;
  s.step = std::lround(t / file.scene.dt);
  return s;
}

/// Every disk of `state` lies inside the picture of `camera`.
::testing::AssertionResult allDisksVisible(const SceneFile& file, const State& state, const Camera& camera, int w,
                                           int h) {
  const Box view = visibleBox(camera, w, h);
  for (int i = 0; i < state.numParticles(); ++i) {
    const Vec2 p = at(state.x, i);
    const double r = file.scene.radius[i];
    if (p.x() - r < view.lo.x() || p.x() + r > view.hi.x() || p.y() - r < view.lo.y() || p.y() + r > view.hi.y())
      return ::testing::AssertionFailure() << "particle " << i << " at (" << p.x() << ", " << p.y()
                                           << ") is outside the view [" << view.lo.x() << ", " << view.hi.x()
                                           << "] x [" << view.lo.y() << ", " << view.hi.y() << "] at t = "
                                           << state.time;
  }
  return ::testing::AssertionSuccess();
}

TEST(FollowCamera, EveryDiskIsInViewInEveryFrameAndTheViewOnlyGrows) {
  const SceneFile file = parsed(kThrownScene);
  for (auto [w, h] : {std::pair{512, 512}, {640, 360}, {200, 600}}) {
    for (double frameTime : {0.01, 0.08, 0.5}) {  // every step, a movie's pace, sparse stills
      FollowCamera camera;
      camera.start(file, file.initial, w, h);
      ASSERT_TRUE(camera.following());
      ASSERT_TRUE(allDisksVisible(file, file.initial, camera.camera(), w, h));
      Box previous = visibleBox(camera.camera(), w, h);
      for (double t = frameTime; t <= 2.5 + 1e-9; t += frameTime) {
        const State s = thrownAt(file, t);
        const Camera& c = camera.update(file.scene, s, w, h);
        ASSERT_TRUE(allDisksVisible(file, s, c, w, h)) << w << "x" << h << ", a frame every " << frameTime << " s";
        const Box now = visibleBox(c, w, h);
        ASSERT_TRUE(now.contains(previous)) << "the view shrank at t = " << t << " (" << w << "x" << h << ")";
        previous = now;
      }
    }
  }
}

TEST(FollowCamera, NoSideMovesMuchFasterThanTheParticles) {
  // Smooth: in every frame each side of the view moves by at most the fastest particle's
  // displacement in that frame plus 2 % of the view's height (the glide towards the goal). A
  // camera that jumped to a newly needed view, or re-fitted each frame, would break this.
  const SceneFile file = parsed(kThrownScene);
  for (auto [w, h] : {std::pair{512, 512}, {640, 360}}) {
    FollowCamera camera;
    camera.start(file, file.initial, w, h);
    Box before = visibleBox(camera.camera(), w, h);
    State previous = file.initial;
    const double firstHeight = before.hi.y() - before.lo.y();
    for (int k = 1; k <= 250; ++k) {
      const State s = thrownAt(file, 0.01 * k);
      double fastest = 0;
      for (int i = 0; i < s.numParticles(); ++i) fastest = std::max(fastest, (at(s.x, i) - at(previous.x, i)).norm());
      const Box now = visibleBox(camera.update(file.scene, s, w, h), w, h);
      const double allowed = fastest + 0.02 * (before.hi.y() - before.lo.y());
      const double moved =
          std::max((now.lo - before.lo).cwiseAbs().maxCoeff(), (now.hi - before.hi).cwiseAbs().maxCoeff());
      ASSERT_LE(moved, allowed) << "frame " << k << " (" << w << "x" << h << ")";
      before = now;
      previous = s;
    }
    EXPECT_GT(before.hi.y() - before.lo.y(), 5 * firstHeight) << "the particles fell about 30 m: the view grew a lot";
  }
}

TEST(FollowCamera, AStillSceneKeepsTheStartingCamera) {
  const SceneFile file = parsed(kThrownScene);
  const Camera start = initialCamera(file.look, file.initial, 512, 512);
  FollowCamera camera;
  camera.start(file, file.initial, 512, 512);
  State still = file.initial;
  for (int k = 1; k <= 100; ++k) {
    still.time = 0.01 * k;
    camera.update(file.scene, still, 512, 512);
  }
  EXPECT_EQ(camera.camera().cx, start.cx);
  EXPECT_EQ(camera.camera().cy, start.cy);
  EXPECT_EQ(camera.camera().size, start.size);
}

TEST(FollowCamera, AViewportIsKeptWhateverTheParticlesDo) {
  const std::string text = std::string(kThrownScene).replace(std::string(kThrownScene).find("<particle"), 0,
                                                              "<viewport cx=\"1\" cy=\"2\" size=\"0.5\"/>\n  ");
  const SceneFile file = parsed(text.c_str());
  FollowCamera camera;
  camera.start(file, file.initial, 512, 512);
  EXPECT_FALSE(camera.following());
  const Camera& c = camera.update(file.scene, thrownAt(file, 2.0), 512, 512);
  EXPECT_EQ(c.cx, 1);
  EXPECT_EQ(c.cy, 2);
  EXPECT_EQ(c.size, 0.5);
}

TEST(FollowCamera, TheUsersCameraStaysUntilRefit) {
  const SceneFile file = parsed(kThrownScene);
  FollowCamera camera;
  camera.start(file, file.initial, 512, 512);
  const Camera zoomed{0.1, 0.2, 0.3};
  camera.take(zoomed);
  EXPECT_FALSE(camera.following());
  const State later = thrownAt(file, 1.5);
  EXPECT_EQ(camera.update(file.scene, later, 512, 512).size, 0.3);
  camera.refit(file, later, 512, 512);  // the window's c key
  EXPECT_TRUE(camera.following());
  EXPECT_TRUE(allDisksVisible(file, later, camera.camera(), 512, 512));
}

TEST(FollowCamera, ADiskPokingOutAtTheStartIsTakenIn) {
  // fitParticles frames the centres; a large disk reaches past them.
  const SceneFile file = parsed(R"(<scene>
  <duration time="1"/>
  <integrator type="symplectic-euler" dt="0.01"/>
  <particle m="1" px="0" py="0" vx="0" vy="0" fixed="0" radius="2"/>
  <particle m="1" px="1" py="0" vx="0" vy="0" fixed="0" radius="0.1"/>
</scene>)");
  ASSERT_FALSE(allDisksVisible(file, file.initial, initialCamera(file.look, file.initial, 512, 512), 512, 512));
  FollowCamera camera;
  camera.start(file, file.initial, 512, 512);
  EXPECT_TRUE(allDisksVisible(file, file.initial, camera.camera(), 512, 512));
}

}  // namespace
}  // namespace fosssim::render
