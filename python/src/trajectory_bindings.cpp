// Trajectory files in the course's binary format: write a run's, grade a file against a scene.
#include "bindings.h"
#include "errors.h"
#include "interrupt_check.h"
#include "py_scene.h"
#include "staged_output.h"

#include "fosssim/core/simulator.h"
#include "fosssim/io/grader.h"
#include "fosssim/io/trajectory.h"

#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>

#include <sstream>

namespace fosssim::py {

namespace nb = nanobind;

namespace {

SimulatorOptions optionsFor(bool compat) {
  SimulatorOptions options;
  options.handler.compat = compat;
  options.logPolynomials = true;  // the records hold every pair's polynomials (reference layout)
  return options;
}

std::unique_ptr<Simulator> simulatorFor(const PyScene& scene, const SimulatorOptions& options) {
  std::unique_ptr<Simulator> sim;
  check<SimulationError>(Simulator::create(scene.file.scene, options, sim));
  return sim;
}

/// Writes the records of a run of `steps` steps (default: the whole scene), as FOSSSim -o does:
/// under the partial name, renamed to `path` when every record is written (staged_output.h).
long writeTrajectory(const PyScene& given, const std::string& path, bool compat, std::optional<long> steps) {
  if (steps) checkSteps(*steps);  // before the file is made
  StagedOutput out(path, "write_trajectory", given.file.path);
  // The run goes without the GIL, while another Python thread may change the Scene (add a
  // particle, and its vectors move): it runs a copy, taken here with the GIL.
  const auto copy = given.copy();
  const PyScene& scene = *copy;
  auto sim = simulatorFor(scene, optionsFor(compat));
  std::unique_ptr<TrajectoryWriter> writer;
  check<FileError>(TrajectoryWriter::open(out.writePath(), sim->layout(), writer, path));
  // A mid-step record (continuous-time, hybrid) comes from inside collision handling.
  struct MidStep final : StepObserver {
    TrajectoryWriter* writer;
    Status status = Status::ok();
    const State* midStep(const CollisionLog& log, const State& state) override {
      if (status) status = writer->write(state, log);
      return nullptr;  // records only: the step goes on from `state`
    }
  } observer;
  observer.writer = writer.get();
  State state = scene.file.initial;
  InterruptCheck interrupted;
  const long total = steps ? *steps : scene.file.scene.numSteps();
  {
    nb::gil_scoped_release release;
    out.keepingPartial("the trajectory so far", [&] {
      check<FileError>(writer->write(state, CollisionLog{}));
      for (long k = 0; k < total; ++k) {
        check<SimulationError>(sim->step(scene.file.scene, state, sim->layout().midStep ? &observer : nullptr));
        check<FileError>(observer.status);
        check<FileError>(writer->write(state, sim->log()));
        interrupted();  // KeyboardInterrupt: the records so far stay in the partial file
      }
      check<FileError>(writer->close());
    });
  }
  out.commit();
  return total;
}

/// Grades `path` against the scene: (passed, the grader's report text). gradeFile, as -i: a
/// failing file that passes in the other mode gets -i's hint to grade it with (or without)
/// --compat.
std::tuple<bool, std::string> gradeTrajectoryFile(const PyScene& given, const std::string& path, bool compat) {
  checkPath(path, "grade_trajectory");
  const auto copy = given.copy();  // as in writeTrajectory: graded without the GIL
  const PyScene& scene = *copy;
  const SimulatorOptions options = optionsFor(compat);
  auto sim = simulatorFor(scene, options);
  std::ostringstream report;
  GradeReport result;
  {
    nb::gil_scoped_release release;
    result = gradeFile(scene.file.scene, scene.file.initial, *sim, options, path, report);
  }
  // Nothing was read, so there is no grade (and no report text): -i's error, as an exception.
  if (result.unreadable) throw FileError(result.structuralError);
  return {result.passed(GradeTolerances{}), report.str()};
}

}  // namespace

void bindTrajectories(nb::module_& m) {
  m.def("write_trajectory", &writeTrajectory, nb::arg("scene"), nb::arg("path"), nb::arg("compat") = false,
        nb::arg("steps") = nb::none(),
        "Runs the scene from its initial state and writes the trajectory file FOSSSim -o writes "
        "(compat: as --compat). Returns the steps written.");
  m.def("grade_trajectory", &gradeTrajectoryFile, nb::arg("scene"), nb::arg("path"), nb::arg("compat") = false,
        "Grades a trajectory file against the scene as FOSSSim -i does: (passed, report text), the report "
        "saying when the file passes in the other mode (compat). A file that cannot be read raises FileError.");
}

}  // namespace fosssim::py
