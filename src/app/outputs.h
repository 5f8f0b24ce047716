// The run observers that need no rendering: trajectory file and progress line.
#pragma once

#include "disk_budget.h"
#include "output_files.h"
#include "run_observer.h"

#include "fosssim/io/trajectory.h"

#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>

namespace fosssim::app {

/// -o: writes record 0, then one record per step (two with a mid-step record), under the file's
/// partial name until the run completes (output_files.h). A step's records are written together
/// once the step has succeeded: the mid-step record waits for the step's finite check, so a
/// step that fails writes nothing, and the file never ends inside a step. The free space is
/// watched (disk_budget.h).
class TrajectoryOutput final : public RunObserver {
 public:
  /// `compact`: records without the polynomial log (--compact): positions, velocities and
  /// impulses, for reading positions; grading (-i) needs the full records.
  TrajectoryOutput(std::string path, bool compact, FreeSpaceQuery freeSpace = statvfsFreeSpace)
      : path_(std::move(path)), compact_(compact), freeSpace_(std::move(freeSpace)) {}
  Status start(const SceneFile& file, const State& initial, const RecordLayout& layout) override;
  const State* midStep(const CollisionLog& log, const State& state) override;
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  void ending(RunEnd end) override { end_ = end; }
  Status finish() override;
  std::string written() const override;

 private:
  std::string path_;
  bool compact_;
  FreeSpaceQuery freeSpace_;
  io::StagedFile file_;
  std::unique_ptr<TrajectoryWriter> writer_;
  std::optional<DiskBudget> budget_;  ///< regular files only
  std::string pending_;               ///< the step's records, written when it has succeeded
  Status midStatus_ = Status::ok();
  RunEnd end_ = RunEnd::Failed;
  std::uint64_t initialBytes_ = 0;
  long records_ = 0, lastStep_ = -1;
};

/// A progress line: rewritten in place on a terminal (at most 5 times a second); otherwise one
/// line every 10% of the steps and at least every kInterval of wall time, so that a log shows
/// that a long run is alive.
class ProgressOutput final : public RunObserver {
 public:
  using Clock = std::chrono::steady_clock;
  using Now = std::function<Clock::time_point()>;
  static constexpr std::chrono::seconds kInterval{10};

  /// On stderr, rewritten in place when stderr is a terminal.
  ProgressOutput();
  /// For tests: any stream, either kind of output, any clock.
  ProgressOutput(std::FILE* out, bool terminal, Now now) : out_(out), terminal_(terminal), now_(std::move(now)) {}

  Status start(const SceneFile& file, const State& initial, const RecordLayout& layout) override;
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  void ending(RunEnd end) override { end_ = end; }
  Status finish() override;

 private:
  std::FILE* out_;
  RunEnd end_ = RunEnd::Completed;
  bool terminal_;
  Now now_;
  Clock::time_point begin_, lastPrint_;
  long total_ = 0, lastDecile_ = -1, steps_ = 0;
  bool started_ = false;
};

}  // namespace fosssim::app
