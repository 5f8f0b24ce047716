// The lock that serialises Python threads' calls into one simulator (py_simulator.h).
#pragma once

#include "py_simulator.h"

#include <nanobind/nanobind.h>

#include <mutex>

namespace fosssim::py {

/// Holds a simulator's lock for a binding's call. It waits for the lock without the GIL: the
/// thread that holds the lock may be stepping without the GIL and need it back (to end its call
/// or to run a callback), so waiting with the GIL would deadlock both threads.
class SimulatorLock {
 public:
  explicit SimulatorLock(const PySimulator& s) : lock_(s.mutex(), std::try_to_lock) {
    if (!lock_.owns_lock()) {
      nanobind::gil_scoped_release release;
      lock_.lock();
    }
  }

 private:
  std::unique_lock<std::recursive_mutex> lock_;
};

}  // namespace fosssim::py
