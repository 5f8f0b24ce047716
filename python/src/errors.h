// The exceptions the module raises: a failed Status becomes one of these, carrying the same
// located message the command line prints ("scene.xml:12: <integrator> attribute 'dt': ...").
#pragma once

#include "fosssim/core/status.h"

#include <stdexcept>

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

}  // namespace fosssim::py
