#include "outputs.h"

#include <unistd.h>

namespace fosssim::app {

Status TrajectoryOutput::start(const SceneFile& file, const State& initial, const RecordLayout& sceneLayout) {
  RecordLayout layout = sceneLayout;
  if (compact_) layout.polynomials = false;
  if (Status s = io::StagedFile::prepare(path_, "-o", file_); !s) return s;
  if (Status s = TrajectoryWriter::open(file_.writePath(), layout, writer_, path_); !s) return s;
  if (file_.staged()) {
    const std::string hint = layout.polynomials ? "--compact leaves out the polynomial log (positions, velocities "
                                                  "and impulses stay; grading with -i needs the full file)"
                                                : "";
    budget_.emplace(file_.writePath(), path_, file.scene.numSteps(), hint, freeSpace_);
  }
  pending_.clear();
  if (Status s = writer_->encode(initial, CollisionLog{}, pending_); !s)
    return Status::error(path_ + ": record 0 (the initial state): " + s.message());
  if (budget_)
    if (Status s = budget_->reserve(pending_.size(), 0); !s) return s;
  if (Status s = writer_->append(pending_); !s) return s;
  initialBytes_ = writer_->bytesWritten();
  records_ = 1;
  lastStep_ = 0;
  pending_.clear();
  return Status::ok();
}

const State* TrajectoryOutput::midStep(const CollisionLog& log, const State& state) {
  // Held until afterStep: the step may still fail its finite check.
  if (midStatus_ && writer_) {
    midStatus_ = writer_->encode(state, log, pending_);
    if (!midStatus_)
      midStatus_ = Status::error(path_ + ": step " + std::to_string(state.step + 1) + "'s mid-step record: " +
                                 midStatus_.message());
  }
  return nullptr;
}

Status TrajectoryOutput::afterStep(const SceneFile&, const State& state, const CollisionLog& log) {
  if (!midStatus_) return midStatus_;
  const bool withMid = !pending_.empty();
  if (Status s = writer_->encode(state, log, pending_); !s)
    return Status::error(path_ + ": step " + std::to_string(state.step) + "'s record: " + s.message());
  if (budget_)
    if (Status s = budget_->reserve(pending_.size(), state.step); !s) return s;
  if (Status s = writer_->append(pending_); !s) return s;
  pending_.clear();
  records_ += withMid ? 2 : 1;
  lastStep_ = state.step;
  if (budget_) {
    const std::string warning = budget_->estimate(state.step, writer_->bytesWritten(), initialBytes_);
    if (!warning.empty()) std::fprintf(stderr, "FOSSSim: warning: %s\n", warning.c_str());
  }
  return Status::ok();
}

Status TrajectoryOutput::finish() {
  if (!writer_) return Status::ok();
  Status closed = writer_->close();
  if (closed && end_ == RunEnd::Completed) return file_.commit();
  return closed;
}

std::string TrajectoryOutput::written() const {
  if (!writer_) return "";
  if (records_ == 0) return "-o: no record written; " + file_.whereIncomplete() + " is empty";
  return "-o: the trajectory up to step " + std::to_string(lastStep_) + " (" + std::to_string(records_) +
         " whole records, " + std::to_string(writer_->bytesWritten()) + " bytes) is in " + file_.whereIncomplete();
}

ProgressOutput::ProgressOutput() : ProgressOutput(stderr, isatty(STDERR_FILENO), [] { return Clock::now(); }) {}

Status ProgressOutput::start(const SceneFile& file, const State&, const RecordLayout&) {
  started_ = true;
  total_ = file.scene.numSteps();
  begin_ = lastPrint_ = now_();
  return Status::ok();
}

Status ProgressOutput::afterStep(const SceneFile&, const State& state, const CollisionLog&) {
  ++steps_;
  const auto now = now_();
  const long decile = total_ > 0 ? state.step * 10 / total_ : 10;
  const bool due = terminal_ ? now - lastPrint_ > std::chrono::milliseconds(200)
                             : decile != lastDecile_ || now - lastPrint_ >= kInterval;
  if (!due && state.step != total_) return Status::ok();
  lastPrint_ = now;
  lastDecile_ = decile;
  const double seconds = std::chrono::duration<double>(now - begin_).count();
  std::fprintf(out_, "%sstep %ld/%ld (%3.0f%%)  t = %.4g s  %.0f steps/s%s", terminal_ ? "\r" : "", state.step,
               total_, total_ > 0 ? 100.0 * static_cast<double>(state.step) / static_cast<double>(total_) : 100.0,
               state.time, seconds > 0 ? static_cast<double>(steps_) / seconds : 0.0, terminal_ ? "   " : "\n");
  std::fflush(out_);
  return Status::ok();
}

Status ProgressOutput::finish() {
  if (!started_) return Status::ok();  // an earlier observer failed to start: there was no run
  const double seconds = std::chrono::duration<double>(now_() - begin_).count();
  std::fprintf(out_, "%s%s: %ld steps in %.3f s\n", terminal_ ? "\n" : "",
               end_ == RunEnd::Completed ? "done" : "stopped", steps_, seconds);
  return Status::ok();
}

}  // namespace fosssim::app
