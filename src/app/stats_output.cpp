#include "stats_output.h"

#include "fosssim/io/scene_writer.h"  // formatNumber: every value as the shortest text that reads back exactly

#include <cerrno>
#include <cstring>

namespace fosssim::app {

StatsOutput::StatsOutput(std::string path, Simulator& simulator) : path_(std::move(path)), simulator_(simulator) {
  simulator.setTiming(true);
}

Status StatsOutput::start(const SceneFile& file, const State& initial, const RecordLayout&) {
  out_.open(path_, std::ios::binary | std::ios::trunc);
  if (!out_) return Status::error(path_ + ": cannot create the --stats file (" + std::strerror(errno) + ")");
  line_.clear();
  for (const std::string& name : diagnosticColumns(file.scene)) line_ += (line_.empty() ? "" : ",") + name;
  out_ << line_ << '\n';
  diagnostics_ = StepDiagnostics{};
  measureState(file.scene, initial, diagnostics_);
  return writeRow();
}

Status StatsOutput::afterStep(const SceneFile& file, const State& state, const CollisionLog& log) {
  measureStep(file.scene, state, log, simulator_.stats(), diagnostics_);
  return writeRow();
}

Status StatsOutput::writeRow() {
  diagnosticRow(diagnostics_, row_);
  line_.clear();
  for (size_t k = 0; k < row_.size(); ++k) {
    if (k) line_ += ',';
    line_ += formatNumber(row_[k]);
  }
  out_ << line_ << '\n';
  if (!out_) return Status::error(path_ + ": cannot write the --stats file (" + std::strerror(errno) + ")");
  return Status::ok();
}

Status StatsOutput::finish() {
  if (!out_.is_open()) return Status::ok();
  out_.close();
  if (!out_) return Status::error(path_ + ": cannot write the --stats file (" + std::strerror(errno) + ")");
  return Status::ok();
}

}  // namespace fosssim::app
