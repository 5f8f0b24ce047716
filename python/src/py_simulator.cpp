#include "py_simulator.h"

#include "errors.h"
#include "fosssim/io/scene_writer.h"

#include <cmath>

namespace fosssim::py {

PySimulator::PySimulator(const PyScene& scene, bool compat, int threads, bool diagnostics, bool sleep)
    : scene_(scene.copy("Simulator")), compat_(compat), diagnostics_(diagnostics) {
  checkArgument(threads >= 1, "threads must be >= 1, got " + std::to_string(threads));
  // The command line's --threads limit: far beyond any machine's cores, more would only exhaust the process.
  checkArgument(threads <= 1024, "threads must be an integer from 1 to 1024, got " + std::to_string(threads));
  SimulatorOptions options;
  options.handler.compat = compat;
  options.handler.threads = threads;
  options.handler.sleep = sleep;
  check<SimulationError>(Simulator::create(scene_->file.scene, options, simulator_));
  simulator_->setTiming(diagnostics);
  state_ = scene_->file.initial;
  x_ = state_.x;
  v_ = state_.v;
  trails_ = render::PathTrails(scene_->file.look.paths, scene_->file.scene.dt);
  trails_.record(state_);
  if (diagnostics_) {
    columns_ = diagnosticColumns(scene_->file.scene);
    measureState(scene_->file.scene, state_, measured_);
    diagnosticRow(measured_, row_);
    table_.insert(table_.end(), row_.begin(), row_.end());
  }
}

void PySimulator::step() {
  if (!failure_.empty())
    throw SimulationError("this simulator cannot go on after its failed " + failure_ +
                          "; make a new Simulator (its positions and velocities are the last good state's)");
  const double time = state_.time;
  const long steps = state_.step;
  if (const Status s = simulator_->step(scene_->file.scene, state_); !s) {
    // Back to the step's start, which x_ and v_ still hold, so that everything Python sees is one
    // state; the command line stops at a failure too.
    state_.x = x_;
    state_.v = v_;
    state_.time = time;
    state_.step = steps;
    failure_ = s.message();
    throw SimulationError(s.message());
  }
  // Copies into the pinned buffers (sizes never change, so no reallocation): 2 x 16 N bytes,
  // nothing next to a step's cost.
  x_ = state_.x;
  v_ = state_.v;
  trails_.record(state_);
  if (diagnostics_) record();
}

void PySimulator::record() {
  measureStep(scene_->file.scene, state_, simulator_->log(), simulator_->stats(), measured_);
  diagnosticRow(measured_, row_);
  table_.insert(table_.end(), row_.begin(), row_.end());
}

// A bad value is a ValueError (SceneError), as the same assignment to a Scene and a wrong shape
// here: nothing was simulated.
void PySimulator::setVector(VecX& into, const double* data, long count, const char* what) {
  if (count != into.size())
    throw SceneError(std::string(what) + ": expected " + std::to_string(into.size() / 2) + " x 2 values, got " +
                          std::to_string(count) + " values");
  for (long k = 0; k < count; ++k)
    if (!std::isfinite(data[k]))
      throw SceneError(std::string(what) + ": particle " + std::to_string(k / 2) + " has a non-finite value (" +
                            formatNumber(data[k]) + ")");
  for (long k = 0; k < count; ++k) into[k] = data[k];
}

void PySimulator::setPositions(const double* data, long count) {
  setVector(state_.x, data, count, "positions");
  x_ = state_.x;
}

void PySimulator::setVelocities(const double* data, long count) {
  setVector(state_.v, data, count, "velocities");
  v_ = state_.v;
}

}  // namespace fosssim::py
