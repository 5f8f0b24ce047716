// A tiny program against the installed package: build a scene in code and step it, load a
// scene file and run it to its end, draw it as SVG. Exits non-zero on the first failed check.
#include "fosssim/core/forces.h"
#include "fosssim/core/simulator.h"
#include "fosssim/io/scene_file.h"
#include "fosssim/render/svg_writer.h"

#include <cmath>
#include <cstdio>
#include <memory>

using namespace fosssim;

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "downstream: FAILED: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: downstream scene.xml\n");
    return 2;
  }

  // Free fall built in code: symplectic Euler gives v = g t exactly (up to rounding) and no
  // collisions, so the velocity after k steps is known without running anything else.
  Scene scene;
  addParticle(scene, 2.0, false, 0.1);
  scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, -9.81)));
  scene.integrator = "symplectic-euler";
  scene.dt = 0.01;
  State state;
  check(state.addParticle(Vec2(0, 10), Vec2(1, 0)) == 0, "State::addParticle returns the particle's index");
  std::unique_ptr<Simulator> simulator;
  Status created = Simulator::create(scene, SimulatorOptions{}, simulator);
  check(created.isOk(), "Simulator::create on a scene built in code");
  if (!created) return 1;
  for (int k = 0; k < 100; ++k) check(simulator->step(scene, state).isOk(), "a free-fall step");
  check(std::fabs(state.v.y() + 9.81) < 1e-12, "free fall: v_y = -g after 1 s");
  check(state.v.x() == 1.0, "free fall: v_x unchanged");
  check(state.step == 100 && std::fabs(state.time - 1.0) < 1e-12, "free fall: 100 steps make 1 s");

  // A scene file, run to its end.
  SceneFile file;
  Status loaded = loadScene(argv[1], file);
  check(loaded.isOk(), loaded.message().c_str());
  if (!loaded) return 1;
  std::unique_ptr<Simulator> sim2;
  check(Simulator::create(file.scene, SimulatorOptions{}, sim2).isOk(), "Simulator::create on the file");
  State s = file.initial;
  for (long k = 0; k < file.scene.numSteps(); ++k) check(sim2->step(file.scene, s).isOk(), "a step of the file");
  check(s.step == file.scene.numSteps(), "the file ran all its steps");

  // Bad input comes back as a located message, not an exit.
  SceneFile bad;
  Status parsed = parseScene("<scene><integrator type=\"explicit-euler\" dt=\"abc\"/></scene>", "bad.xml", bad);
  check(!parsed && parsed.message().rfind("bad.xml:1:", 0) == 0, "a bad scene's message names file and line");

  // The picture as SVG (no OpenGL needed).
  render::View view;
  view.camera = render::initialCamera(file.look, s, view.width, view.height);
  const std::string svg = render::svgDocument(render::makePicture(file, s, render::PathTrails{}, view));
  check(svg.find("<svg") != std::string::npos && svg.find("<circle") != std::string::npos,
        "the SVG picture has the particles");

  if (failures == 0) std::printf("downstream: all checks passed\n");
  return failures == 0 ? 0 : 1;
}
