// fosssim._fosssim: the extension module. Exceptions first, so that every binding can raise them.
#include "bindings.h"
#include "errors.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/integrator.h"

#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

namespace nb = nanobind;

NB_MODULE(_fosssim, m) {
  m.doc() = "FOSSSim's C++ core: scenes, simulators, diagnostics, pictures and trajectory files";
  nb::exception<fosssim::py::SceneError>(m, "SceneError", PyExc_ValueError);
  nb::exception<fosssim::py::SimulationError>(m, "SimulationError", PyExc_RuntimeError);
  nb::exception<fosssim::py::FileError>(m, "FileError", PyExc_OSError);

  m.def("collision_types", [] {
    std::vector<std::string> out;
    for (const auto& e : fosssim::collisionTable()) out.emplace_back(e.keyword);
    return out;
  }, "The keywords of <collision type=...>.");
  m.def("integrators", [] {
    std::vector<std::string> out;
    for (const auto& e : fosssim::integratorTable()) out.emplace_back(e.keyword);
    return out;
  }, "The keywords of <integrator type=...>.");
  m.attr("has_renderer") =
#ifdef FOSSSIM_HAVE_RENDER
      true;
#else
      false;
#endif

  fosssim::py::bindScene(m);
  fosssim::py::bindSimulator(m);
  fosssim::py::bindPictures(m);
  fosssim::py::bindTrajectories(m);
}
