// Things that watch a run step by step: trajectory writer, progress line, pictures, verification.
#pragma once

#include "fosssim/core/collision_handler.h"
#include "fosssim/io/scene_file.h"

#include <memory>
#include <string>
#include <vector>

namespace fosssim::app {

/// How a run ended. Only a completed run (every step, or the window closed by the user) gives
/// -o and --movie their final names (output_files.h).
enum class RunEnd { Completed, Failed, Interrupted };

class RunObserver : public StepObserver {
 public:
  /// Before the first step, with the initial state.
  virtual Status start(const SceneFile&, const State&, const RecordLayout&) { return Status::ok(); }
  /// Inside collision handling (layouts with a mid-step record only).
  const State* midStep(const CollisionLog&, const State&) override { return nullptr; }
  /// After every step.
  virtual Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) = 0;
  /// Before finish(): how the run ended.
  virtual void ending(RunEnd) {}
  /// After the last step (or after a failure, to release resources).
  virtual Status finish() { return Status::ok(); }
  /// After finish(), for a run that did not complete: what this output wrote and where it is
  /// (one line), or empty.
  virtual std::string written() const { return {}; }
};

/// Forwards mid-step calls to several observers.
class ObserverList final : public StepObserver {
 public:
  std::vector<std::unique_ptr<RunObserver>> items;
  /// Outputs only record: none replaces the state.
  const State* midStep(const CollisionLog& log, const State& state) override {
    for (auto& o : items) o->midStep(log, state);
    return nullptr;
  }
};

/// Ends a run (both frontends): tells every observer how it ended (`status` failed: Failed; a
/// stop signal: Interrupted; otherwise Completed), finishes them, prints the error and, unless
/// the run completed, what was written. Returns the exit status: 0, 1, or 128 + the signal.
/// Implemented in run_end.cpp.
int endRun(ObserverList& observers, Status status, const State& state, long totalSteps);

}  // namespace fosssim::app
