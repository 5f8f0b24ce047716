// Pictures of a simulator's current state: an RGB NumPy array or PNG file (OpenGL through OSMesa,
// when FOSSSim was built with its renderer), SVG (always), and movies through ffmpeg.
#include "arrays.h"
#include "bindings.h"
#include "interrupt_check.h"
#include "py_simulator.h"
#include "simulator_lock.h"
#include "staged_output.h"

#include "fosssim/io/scene_writer.h"
#include "fosssim/render/picture.h"
#include "fosssim/render/movie_writer.h"  // its limits and name checks work without the renderer
#include "fosssim/render/svg_writer.h"
#ifdef FOSSSIM_HAVE_RENDER
#include "fosssim/render/offscreen_renderer.h"
#include "fosssim/render/png_writer.h"
#endif

#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <map>

namespace fosssim::py {
namespace {

void checkSize(int width, int height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw SceneError("picture size must be 1 .. 16384 pixels each way, got " + std::to_string(width) + " x " +
                     std::to_string(height));
}

/// The picture of the current state. The camera is the scene's viewport, or one that fits the
/// initial state's particles, so that successive frames share one camera.
render::Picture picture(const PySimulator& s, int width, int height) {
  checkSize(width, height);
  SimulatorLock lock(s);  // the state and trails, which another thread's step may change
  render::View view;
  view.width = width;
  view.height = height;
  view.camera = render::initialCamera(s.scene().file.look, s.scene().file.initial, width, height);
  return render::makePicture(s.scene().file, s.state(), s.trails(), view);
}

#ifdef FOSSSIM_HAVE_RENDER
/// One OSMesa context per picture size, made on first use and kept for the process.
render::OffscreenRenderer& renderer(int width, int height) {
  static std::map<std::pair<int, int>, std::unique_ptr<render::OffscreenRenderer>> renderers;
  auto& r = renderers[{width, height}];
  // Out of memory, the advice names this call's arguments, not the command line's --frame-size.
  if (!r) check<SimulationError>(render::OffscreenRenderer::create(width, height, r, "width and height"));
  return *r;
}

render::Image frame(const PySimulator& s, int width, int height) {
  render::Image image;
  check<SimulationError>(renderer(width, height).render(picture(s, width, height), image));
  return image;
}
#else
[[noreturn]] void noRenderer() {
  throw SimulationError("this fosssim was built without its renderer (FOSSSIM_RENDER=OFF): no raster frames; "
                        "svg() and save_svg() work");
}
#endif

}  // namespace

void bindPictures(nb::module_& m) {
  nb::class_<PySimulator> cls = nb::borrow<nb::class_<PySimulator>>(m.attr("Simulator"));
  cls.def("render", [](const PySimulator& s, int width, int height) {
        checkSize(width, height);  // a ValueError, as svg()'s, not the renderer's own failure
#ifdef FOSSSIM_HAVE_RENDER
        const render::Image image = frame(s, width, height);
        const size_t shape[3] = {static_cast<size_t>(image.height), static_cast<size_t>(image.width), 3};
        auto* copy = new std::uint8_t[image.rgb.size()];
        std::copy(image.rgb.begin(), image.rgb.end(), copy);
        nb::capsule owner(copy, [](void* p) noexcept { delete[] static_cast<std::uint8_t*>(p); });
        return toPython(nb::ndarray<nb::numpy, std::uint8_t>(copy, 3, shape, owner));
#else
        (void)s, (void)width, (void)height;
        noRenderer();
#endif
      }, nb::arg("width") = 512, nb::arg("height") = 512,
      "The current state drawn as an (height, width, 3) uint8 RGB array, top row first.");
  cls.def("save_png", [](const PySimulator& s, const std::string& path, int width, int height) {
        checkSize(width, height);
#ifdef FOSSSIM_HAVE_RENDER
        StagedOutput out(path, "save_png", s.scene().file.path);
        const render::Image image = frame(s, width, height);
        // A device or a named pipe is written directly (writeWholeFile never removes one).
        if (Status written = render::writePng(out.writePath(), image); !written) {
          out.discard();
          throw FileError(written.message() + (out.staged() ? " (\"" + path + "\" was not written)" : ""));
        }
        out.commit();
#else
        (void)s, (void)path, (void)width, (void)height;
        noRenderer();
#endif
      }, nb::arg("path"), nb::arg("width") = 512, nb::arg("height") = 512);
  cls.def(
      "svg", [](const PySimulator& s, int width, int height) { return render::svgDocument(picture(s, width, height)); },
      nb::arg("width") = 512, nb::arg("height") = 512, "The current state as an SVG document.");
  cls.def("save_svg", [](const PySimulator& s, const std::string& path, int width, int height) {
        StagedOutput out(path, "save_svg", s.scene().file.path);
        const render::Picture p = picture(s, width, height);
        if (Status written = render::writeSvg(out.writePath(), p); !written) {
          out.discard();  // a cut SVG is of no use
          throw FileError(written.message() + (out.staged() ? " (\"" + path + "\" was not written)" : ""));
        }
        out.commit();
      }, nb::arg("path"), nb::arg("width") = 512, nb::arg("height") = 512);
  cls.def("record_movie", [](PySimulator& s, const std::string& path, std::optional<long> steps, long every, double fps,
                             int width, int height) {
        // The arguments first, in every build: before the movie's file is made or a step taken.
        checkArgument(every >= 1, "every must be >= 1, got " + std::to_string(every));
        checkArgument(fps >= render::kMinMovieFps && fps <= render::kMaxMovieFps,
                      "fps must be from " + formatNumber(render::kMinMovieFps) + " to " +
                          formatNumber(render::kMaxMovieFps) + " (frames a second, as --fps), got " +
                          formatNumber(fps));
        if (steps) checkSteps(*steps);
        checkSize(width, height);
#ifdef FOSSSIM_HAVE_RENDER
        // As --movie: "run.partial.mp4" (ffmpeg picks the format by the ending), renamed when complete.
        StagedOutput out(path, "record_movie", s.scene().file.path);
        SimulatorLock lock(s);  // the movie's steps and frames follow one another, no other thread's between
        std::unique_ptr<render::MovieWriter> movie;
        check<FileError>(render::MovieWriter::open(out.writePath(), width, height, fps, movie));
        out.keepingPartial("the movie so far", [&] {
          check<FileError>(movie->write(frame(s, width, height)));
          const long total = steps ? *steps : std::max(0L, s.numSteps() - s.stepsTaken());
          for (long k = 1; k <= total; ++k) {
            {
              nb::gil_scoped_release release;
              s.step();
            }
            // The GIL is back between steps here: Ctrl-C's KeyboardInterrupt now, not at the end
            // (MovieWriter's destructor ends the movie so far, in the partial file).
            if (PyErr_CheckSignals() != 0) throw nb::python_error();
            if (k % every == 0) check<FileError>(movie->write(frame(s, width, height)));
          }
          check<FileError>(movie->close());
        }, [&] { movie.reset(); });  // waits for ffmpeg, which may make its file only as it ends
        out.commit();
        return movie->frames();
#else
        (void)s, (void)path, (void)steps, (void)every, (void)fps, (void)width, (void)height;
        noRenderer();
#endif
      }, nb::arg("path"), nb::arg("steps") = nb::none(), nb::arg("every") = 1, nb::arg("fps") = 30.0,
      nb::arg("width") = 512, nb::arg("height") = 512,
      "Steps the simulator (default: to the end of the scene), writing a frame of the current state and then "
      "every `every` steps into a movie through ffmpeg. Returns the number of frames.");
}

}  // namespace fosssim::py
