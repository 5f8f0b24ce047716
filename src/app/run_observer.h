// Things that watch a run step by step: trajectory writer, progress line, pictures, verification.
#pragma once

#include "fosssim/core/collision_handler.h"
#include "fosssim/io/scene_file.h"

#include <memory>
#include <vector>

namespace fosssim::app {

class RunObserver : public StepObserver {
 public:
  /// Before the first step, with the initial state.
  virtual Status start(const SceneFile&, const State&, const RecordLayout&) { return Status::ok(); }
  /// Inside collision handling (layouts with a mid-step record only).
  void midStep(const CollisionLog&, State&) override {}
  /// After every step.
  virtual Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) = 0;
  /// After the last step (or after a failure, to release resources).
  virtual Status finish() { return Status::ok(); }
};

/// Forwards mid-step calls to several observers.
class ObserverList final : public StepObserver {
 public:
  std::vector<std::unique_ptr<RunObserver>> items;
  void midStep(const CollisionLog& log, State& state) override {
    for (auto& o : items) o->midStep(log, state);
  }
};

}  // namespace fosssim::app
