// A simulator as the Python module holds it: its own copy of the scene (later changes to the
// Python Scene do not reach a running simulation), the state, pinned position and velocity
// buffers that NumPy views read (they stay valid and current whatever the step does with its
// own vectors), the diagnostics table, and the trails for pictures.
//
// Stepping releases the GIL, so Python threads can call into one simulator at once: every
// binding that reads or changes the state, the diagnostics or the trails holds the simulator's
// lock (SimulatorLock, simulator_lock.h). What never changes after construction (the scene copy,
// the particle count, the columns, compat) is read without it.
#pragma once

#include "py_scene.h"

#include "fosssim/core/diagnostics.h"
#include "fosssim/core/simulator.h"
#include "fosssim/render/path_trails.h"

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace fosssim::py {

class PySimulator {
 public:
  PySimulator(const PyScene& scene, bool compat, int threads, bool diagnostics, bool sleep = true);

  /// One step; throws SimulationError with the step's message. A failed step leaves the state
  /// the step started from (positions, velocities, time, steps, diagnostics, trails), and every
  /// later step throws: the failed step's state is half made and the C++ simulator's own state
  /// (sleepers, zones, the energy watch) is mid-step, so there is nothing to go on from.
  void step();
  /// The failed step's message, empty while every step succeeded.
  const std::string& failure() const { return failure_; }
  long stepsTaken() const { return state_.step; }
  double time() const { return state_.time; }
  /// Steps of a full run of the scene (ceil(duration / dt)).
  long numSteps() const { return scene_->file.scene.numSteps(); }
  int numParticles() const { return scene_->file.scene.numParticles(); }

  const VecX& positions() const { return x_; }
  const VecX& velocities() const { return v_; }
  /// Sets positions or velocities (2N finite values), between steps.
  void setPositions(const double* data, long count);
  void setVelocities(const double* data, long count);

  const PyScene& scene() const { return *scene_; }
  const State& state() const { return state_; }
  const render::PathTrails& trails() const { return trails_; }
  const Simulator& simulator() const { return *simulator_; }
  bool compat() const { return compat_; }

  bool recordsDiagnostics() const { return diagnostics_; }
  const std::vector<std::string>& columns() const { return columns_; }
  /// Row-major, one row per recorded state (the initial state first).
  const std::vector<double>& table() const { return table_; }

  /// Taken through SimulatorLock only. Recursive: a run's callback may use its own simulator.
  std::recursive_mutex& mutex() const { return mutex_; }

 private:
  void record();
  void setVector(VecX& into, const double* data, long count, const char* what);
  std::shared_ptr<PyScene> scene_;
  std::unique_ptr<Simulator> simulator_;
  State state_;
  VecX x_, v_;  ///< pinned: what Python's views read, refreshed after every step
  bool compat_;
  bool diagnostics_;
  std::vector<std::string> columns_;
  std::vector<double> table_, row_;
  StepDiagnostics measured_;
  render::PathTrails trails_;
  std::string failure_;
  mutable std::recursive_mutex mutex_;
};

}  // namespace fosssim::py
