// render_cost: what pictures cost next to the simulation. Not a test (timings vary by machine);
// a tool for the measurements quoted in docs and reports:
//   build/tests/render/render_cost scene.xml [WxH]
// Runs the scene once without pictures, then again drawing every step off-screen, and prints
// the time per step of the simulation and of each phase of a frame.
#include "fosssim/core/simulator.h"
#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/offscreen_renderer.h"
#include "fosssim/render/png_writer.h"
#include "fosssim/render/svg_writer.h"
#include "fosssim/render/tessellator.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

using namespace fosssim;
using Clock = std::chrono::steady_clock;

namespace {
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: render_cost scene.xml [WxH]\n");
    return 2;
  }
  int w = 512, h = 512;
  if (argc > 2 && std::sscanf(argv[2], "%dx%d", &w, &h) != 2) return 2;
  SceneFile file;
  if (Status s = loadScene(argv[1], file); !s) {
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return 1;
  }
  std::unique_ptr<Simulator> sim;
  if (Status s = Simulator::create(file.scene, SimulatorOptions{}, sim); !s) return 1;
  const long steps = file.scene.numSteps();

  // 1. The simulation alone (best of three runs).
  double simSeconds = 1e300;
  for (int run = 0; run < 3; ++run) {
    State state = file.initial;
    const auto t0 = Clock::now();
    for (long k = 0; k < steps; ++k)
      if (!sim->step(file.scene, state)) return 1;
    simSeconds = std::min(simSeconds, since(t0));
  }

  // 2. The same run with a frame after every step, phase by phase.
  std::unique_ptr<render::OffscreenRenderer> renderer;
  if (Status s = render::OffscreenRenderer::create(w, h, renderer); !s) {
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return 1;
  }
  const std::string dir = (std::filesystem::temp_directory_path() / "fosssim_render_cost").string();
  std::filesystem::create_directories(dir);
  render::FrameSequence seq(w, h, 1);
  State state = file.initial;
  seq.start(file, state);
  render::Image image;
  render::Mesh mesh;
  double picture = 0, tessellate = 0, draw = 0, png = 0, svg = 0, svgText = 0, fileCreate = 0;
  std::size_t triangles = 0;
  for (long k = 0; k < steps; ++k) {
    if (!sim->step(file.scene, state)) return 1;
    seq.advance(state);
    auto t = Clock::now();
    const render::Picture pic = seq.picture(file, state);
    picture += since(t);
    t = Clock::now();
    mesh.clear();
    render::tessellate(pic, mesh);
    triangles += mesh.vertexCount() / 3;
    tessellate += since(t);
    t = Clock::now();
    if (!renderer->render(pic, image)) return 1;  // tessellates again, draws, reads back
    draw += since(t);
    t = Clock::now();
    if (!render::writePng(dir + "/frame.png", image)) return 1;
    png += since(t);
    t = Clock::now();
    {  // the same bytes into a file that stays open: the cost of creating files on this disk
      std::FILE* f = std::fopen((dir + "/frame.raw").c_str(), "wb");
      if (!f) return 1;
      std::fwrite(image.rgb.data(), 1, 4096, f);
      std::fclose(f);
    }
    fileCreate += since(t);
    t = Clock::now();
    const std::string text = render::svgDocument(pic);
    svgText += since(t);
    t = Clock::now();
    if (!render::writeSvg(dir + "/frame.svg", pic)) return 1;
    svg += since(t);
  }
  std::filesystem::remove_all(dir);
  // The fixed cost of a frame: an empty picture (clear and read back only).
  render::Picture empty;
  empty.view.width = w;
  empty.view.height = h;
  auto t = Clock::now();
  for (int k = 0; k < 200; ++k)
    if (!renderer->render(empty, image)) return 1;
  const double emptyFrame = since(t) / 200;
  const double n = static_cast<double>(steps);
  std::printf("%s: %ld steps, %d particles, %dx%d, %.0f triangles per frame\n", argv[1], steps,
              file.scene.numParticles(), w, h, static_cast<double>(triangles) / n);
  std::printf("  simulation            %9.1f us/step\n", 1e6 * simSeconds / n);
  std::printf("  picture (shapes)      %9.1f us/frame\n", 1e6 * picture / n);
  std::printf("  tessellation          %9.1f us/frame\n", 1e6 * tessellate / n);
  std::printf("  OSMesa draw+readback  %9.1f us/frame (includes tessellation)\n", 1e6 * draw / n);
  std::printf("  OSMesa empty frame    %9.1f us/frame (clear and read back only)\n", 1e6 * emptyFrame);
  std::printf("  PNG encode+write      %9.1f us/frame\n", 1e6 * png / n);
  std::printf("  create a 4 KB file    %9.1f us/frame (the file system's share of the above)\n", 1e6 * fileCreate / n);
  std::printf("  SVG text              %9.1f us/frame\n", 1e6 * svgText / n);
  std::printf("  SVG text+write        %9.1f us/frame\n", 1e6 * svg / n);
  return 0;
}
