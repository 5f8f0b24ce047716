// The exceptions the module raises: a failed Status becomes one of these, carrying the same
// located message the command line prints ("scene.xml:12: <integrator> attribute 'dt': ...").
#pragma once

#include "fosssim/core/status.h"

#include <stdexcept>
#include <string>

namespace fosssim::py {

/// A scene that does not load or cannot be built or written (Python: fosssim.SceneError, a ValueError).
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// A run that fails: non-finite state, solver failure, energy blow-up (fosssim.SimulationError).
struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// A file that cannot be read or written (fosssim.FileError, an OSError).
struct FileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class Error>
void check(const Status& status) {
  if (!status) throw Error(status.message());
}

/// An argument out of its range (a negative number of steps, every < 1) raises ValueError, which
/// nanobind makes of std::invalid_argument: nothing was simulated, so it is no SimulationError.
inline void checkArgument(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

/// A number of steps to take: 0 or more.
inline void checkSteps(long steps, const char* name = "steps") {
  checkArgument(steps >= 0, std::string(name) + " must be >= 0, got " + std::to_string(steps));
}

}  // namespace fosssim::py
