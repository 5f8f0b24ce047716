#include "outputs.h"

#include <cstdio>
#include <unistd.h>

namespace fosssim::app {

Status TrajectoryOutput::start(const SceneFile&, const State& initial, const RecordLayout& layout) {
  if (Status s = TrajectoryWriter::open(path_, layout, writer_); !s) return s;
  return writer_->write(initial, CollisionLog{});
}

void TrajectoryOutput::midStep(const CollisionLog& log, State& state) {
  if (midStatus_) midStatus_ = writer_->write(state, log);
}

Status TrajectoryOutput::afterStep(const SceneFile&, const State& state, const CollisionLog& log) {
  if (!midStatus_) return midStatus_;
  return writer_->write(state, log);
}

Status TrajectoryOutput::finish() { return writer_ ? writer_->close() : Status::ok(); }

Status ProgressOutput::start(const SceneFile& file, const State&, const RecordLayout&) {
  started_ = true;
  total_ = file.scene.numSteps();
  terminal_ = isatty(STDERR_FILENO);
  begin_ = lastPrint_ = Clock::now();
  return Status::ok();
}

Status ProgressOutput::afterStep(const SceneFile&, const State& state, const CollisionLog&) {
  ++steps_;
  const auto now = Clock::now();
  const long decile = total_ > 0 ? state.step * 10 / total_ : 10;
  const bool due = terminal_ ? now - lastPrint_ > std::chrono::milliseconds(200) : decile != lastDecile_;
  if (!due && state.step != total_) return Status::ok();
  lastPrint_ = now;
  lastDecile_ = decile;
  const double seconds = std::chrono::duration<double>(now - begin_).count();
  std::fprintf(stderr, "%sstep %ld/%ld (%3.0f%%)  t = %.4g s  %.0f steps/s%s", terminal_ ? "\r" : "", state.step,
               total_, total_ > 0 ? 100.0 * static_cast<double>(state.step) / static_cast<double>(total_) : 100.0,
               state.time, seconds > 0 ? static_cast<double>(steps_) / seconds : 0.0, terminal_ ? "   " : "\n");
  return Status::ok();
}

Status ProgressOutput::finish() {
  if (!started_) return Status::ok();  // an earlier observer failed to start: there was no run
  const double seconds = std::chrono::duration<double>(Clock::now() - begin_).count();
  std::fprintf(stderr, "%sdone: %ld steps in %.3f s\n", terminal_ ? "\n" : "", steps_, seconds);
  return Status::ok();
}

}  // namespace fosssim::app
