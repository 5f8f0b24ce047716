// The run observers that need no rendering: trajectory file and progress line.
#pragma once

#include "run_observer.h"

#include "fosssim/io/trajectory.h"

#include <chrono>
#include <string>

namespace fosssim::app {

/// -o: writes record 0, then one record per step (two with a mid-step record).
class TrajectoryOutput final : public RunObserver {
 public:
  explicit TrajectoryOutput(std::string path) : path_(std::move(path)) {}
  Status start(const SceneFile& file, const State& initial, const RecordLayout& layout) override;
  void midStep(const CollisionLog& log, State& state) override;
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  Status finish() override;

 private:
  std::string path_;
  std::unique_ptr<TrajectoryWriter> writer_;
  Status midStatus_ = Status::ok();
};

/// A progress line on stderr (rewritten in place on a terminal, every 10% otherwise).
class ProgressOutput final : public RunObserver {
 public:
  Status start(const SceneFile& file, const State& initial, const RecordLayout& layout) override;
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  Status finish() override;

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point begin_, lastPrint_;
  long total_ = 0, lastDecile_ = -1, steps_ = 0;
  bool terminal_ = false, started_ = false;
};

}  // namespace fosssim::app
