// The end of a run, the same for the headless loop and the window: outputs learn how the run
// ended before they close (only a completed run renames -o and --movie to their final names), and
// a run that did not complete says what it wrote and where.
#include "run_observer.h"
#include "signals.h"

#include <cstdio>

namespace fosssim::app {

int endRun(ObserverList& observers, Status status, const State& state, long totalSteps) {
  const int signal = stopSignal();
  // A signal after the last step interrupted nothing.
  const bool interrupted = status && signal != 0 && state.step < totalSteps;
  const RunEnd end = !status ? RunEnd::Failed : interrupted ? RunEnd::Interrupted : RunEnd::Completed;
  for (auto& o : observers.items) o->ending(end);
  for (auto& o : observers.items) {
    Status finished = o->finish();
    if (status && !finished) status = finished;
  }
  if (!status) std::fprintf(stderr, "FOSSSim: error: %s\n", status.message().c_str());
  if (end == RunEnd::Completed && status) return 0;
  if (interrupted)
    std::fprintf(stderr, "FOSSSim: interrupted by %s after step %ld of %ld\n", signalName(signal), state.step,
                 totalSteps);
  for (auto& o : observers.items) {
    const std::string line = o->written();
    if (!line.empty()) std::fprintf(stderr, "FOSSSim: %s\n", line.c_str());
  }
  if (!status) return 1;
  return 128 + signal;
}

}  // namespace fosssim::app
