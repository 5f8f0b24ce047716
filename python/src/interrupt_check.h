// Ctrl-C in the loops that step without the GIL (step, run, record_movie, write_trajectory).
// Python's SIGINT handler only notes the signal; the KeyboardInterrupt is raised when code
// holding the GIL asks for it (PyErr_CheckSignals), which a loop in C++ never did: Ctrl-C waited
// for the whole run.
#pragma once

#include <nanobind/nanobind.h>

#include <chrono>

namespace fosssim::py {

class InterruptCheck {
 public:
  /// Between two steps, without the GIL. Every 20 ms (a step's cost is unknown: microseconds
  /// to seconds) it takes the GIL back to run the handlers of signals that came, and throws what
  /// they raise (KeyboardInterrupt) to Python. The steps taken before it stay taken.
  void operator()() {
    const auto now = Clock::now();
    if (now < next_) return;
    next_ = now + kEvery;
    nanobind::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw nanobind::python_error();
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kEvery{20};
  Clock::time_point next_ = Clock::now() + kEvery;
};

}  // namespace fosssim::py
