// fosssim.Simulator: stepping, the state as NumPy arrays, the diagnostics table.
#include "arrays.h"
#include "bindings.h"
#include "interrupt_check.h"
#include "py_simulator.h"
#include "simulator_lock.h"

#include <nanobind/stl/optional.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

namespace fosssim::py {
namespace {

/// A read-only (N, 2) view of a pinned buffer of the simulator, which the view keeps alive.
nb::object view(const PySimulator& s, const VecX& data) {
  const size_t shape[2] = {static_cast<size_t>(s.numParticles()), 2};
  return toPython(View2(data.data(), 2, shape, nb::find(&s)));
}

/// Steps until `steps` more are taken or the callback returns a false value; the GIL is released
/// while C++ steps, taken back for the callback. The lock is held throughout, so another thread's
/// steps do not interleave with the run's.
long run(PySimulator& s, std::optional<long> steps, long every, nb::object callback) {
  SimulatorLock lock(s);
  checkArgument(every >= 1, "every must be >= 1, got " + std::to_string(every));
  if (steps) checkSteps(*steps);
  const long total = steps ? *steps : std::max(0L, s.numSteps() - s.stepsTaken());
  long done = 0;
  InterruptCheck interrupted;
  while (done < total) {
    const long chunk = callback.is_none() ? total - done : std::min(every, total - done);
    {
      nb::gil_scoped_release release;
      for (long k = 0; k < chunk; ++k, ++done) {
        s.step();
        interrupted();
      }
    }
    if (!callback.is_none()) {  // after every `every` steps of this run, and after its last
      nb::object r = callback(nb::find(&s));
      // Python's truth, so that np.False_ or 0 stop too; None, a callback's usual return, goes on.
      const int go = r.is_none() ? 1 : PyObject_IsTrue(r.ptr());
      if (go < 0) throw nb::python_error();
      if (go == 0) break;
    }
  }
  return done;
}

nb::dict diagnostics(const PySimulator& s) {
  SimulatorLock lock(s);  // another thread's step may grow the table
  if (!s.recordsDiagnostics()) throw SimulationError("this simulator records no diagnostics (diagnostics=False)");
  const auto& columns = s.columns();
  const auto& table = s.table();
  const size_t rows = table.size() / columns.size(), cols = columns.size();
  nb::dict out;
  std::vector<double> column(rows);
  for (size_t c = 0; c < cols; ++c) {
    for (size_t r = 0; r < rows; ++r) column[r] = table[r * cols + c];
    out[columns[c].c_str()] = copyArray(column.data(), rows);
  }
  return out;
}

}  // namespace

void bindSimulator(nb::module_& m) {
  nb::class_<PySimulator>(m, "Simulator",
                          "Steps a copy of a scene from its initial state. Positions and velocities are read-only "
                          "NumPy views that follow the steps; assign arrays to change them.")
      .def(nb::init<const PyScene&, bool, int, bool, bool>(), nb::arg("scene"), nb::arg("compat") = false,
           nb::arg("threads") = 1, nb::arg("diagnostics") = true, nb::arg("sleep") = true,
           "compat: the course's formulas (as FOSSSim --compat); threads: for collision detection (same "
           "results for any count); diagnostics: record a row of diagnostics per step (and time the phases); "
           "sleep: resting particles sleep in the default mode (False: as FOSSSim --no-sleep).")
      .def("step", [](PySimulator& s, long count) {
             checkSteps(count, "count");
             SimulatorLock lock(s);
             InterruptCheck interrupted;
             nb::gil_scoped_release release;
             for (long k = 0; k < count; ++k) {
               s.step();
               interrupted();
             }
           }, nb::arg("count") = 1,
           "Takes `count` steps; raises SimulationError if a step fails (ValueError for a negative count).")
      .def("run", &run, nb::arg("steps") = nb::none(), nb::arg("every") = 1, nb::arg("callback") = nb::none(),
           "Takes `steps` steps (default: the rest of the scene's duration), calling callback(simulator) "
           "after every `every` steps of this run and after its last step; a callback returning a false value "
           "(False, 0, np.False_; not None) stops the run. Returns the steps taken.")
      .def_prop_ro("time", [](const PySimulator& s) {
             SimulatorLock lock(s);
             return s.time();
           })
      .def_prop_ro("steps_taken", [](const PySimulator& s) {
             SimulatorLock lock(s);
             return s.stepsTaken();
           })
      .def_prop_ro("num_steps", &PySimulator::numSteps, "Steps of the scene's full duration.")
      .def_prop_ro("num_particles", &PySimulator::numParticles)
      .def_prop_ro("compat", &PySimulator::compat)
      .def_prop_ro("scene", [](const PySimulator& s) { return s.scene().copy(); }, "A copy of the simulated scene.")
      .def_prop_rw("positions", [](const PySimulator& s) { return view(s, s.positions()); },
                   [](PySimulator& s, const Input& a) {
                     SimulatorLock lock(s);
                     s.setPositions(pairsOf(a, s.numParticles(), "positions"), 2L * s.numParticles());
                   })
      .def_prop_rw("velocities", [](const PySimulator& s) { return view(s, s.velocities()); },
                   [](PySimulator& s, const Input& a) {
                     SimulatorLock lock(s);
                     s.setVelocities(pairsOf(a, s.numParticles(), "velocities"), 2L * s.numParticles());
                   })
      .def_prop_ro("masses", [](const PySimulator& s) {
        // Every other entry of the scene's 2N mass vector: a strided view, as the scene copy never changes.
        const size_t shape[1] = {static_cast<size_t>(s.numParticles())};
        const int64_t strides[1] = {2};
        return toPython(View1(s.scene().file.scene.mass.data(), 1, shape, nb::find(&s), strides));
      })
      .def_prop_ro("columns", &PySimulator::columns, "The diagnostics' column names (README: --stats).")
      .def("diagnostics", &diagnostics, "The diagnostics so far as a dict of column name to array (row 0: the "
                                        "initial state).")
      .def("dataframe", [](const PySimulator& s) {
             nb::module_ pandas = nb::module_::import_("pandas");
             return pandas.attr("DataFrame")(diagnostics(s));
           }, "The diagnostics as a pandas DataFrame.")
      .def("__repr__", [](const PySimulator& s) {
        SimulatorLock lock(s);
        return "<fosssim.Simulator step " + std::to_string(s.stepsTaken()) + " of " + std::to_string(s.numSteps()) +
               ", t = " + std::to_string(s.time()) + (s.compat() ? ", compat" : "") + ">";
      });
}

}  // namespace fosssim::py
