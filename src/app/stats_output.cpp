#include "stats_output.h"

#include "fosssim/io/scene_writer.h"  // formatNumber: every value as the shortest text that reads back exactly

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace fosssim::app {
namespace {

/// Rows are gathered up to this many bytes and written together: one system call per row would
/// slow runs of tiny scenes, and the file only ever receives whole rows.
constexpr std::size_t kFlushBytes = 64 * 1024;

}  // namespace

StatsOutput::StatsOutput(std::string path, Simulator& simulator) : path_(std::move(path)), simulator_(simulator) {
  simulator.setTiming(true);
}

// A run that ends without finish() (an exception) keeps its rows, as the ofstream's did.
StatsOutput::~StatsOutput() {
  (void)flush();
  if (fd_ >= 0) ::close(fd_);
}

Status StatsOutput::start(const SceneFile& file, const State& initial, const RecordLayout&) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd_ < 0) return Status::error(path_ + ": cannot create the --stats file (" + std::strerror(errno) + ")");
  created_ = true;
  pending_.clear();
  for (const std::string& name : diagnosticColumns(file.scene)) pending_ += (pending_.empty() ? "" : ",") + name;
  pending_ += '\n';
  pendingRows_ = 0;  // the header is no row
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
  for (size_t k = 0; k < row_.size(); ++k) {
    if (k) pending_ += ',';
    pending_ += formatNumber(row_[k]);
  }
  pending_ += '\n';
  ++pendingRows_;
  return pending_.size() >= kFlushBytes ? flush() : Status::ok();
}

/// Writes the rows gathered so far. A write that fails partway (a full disk) would leave a row
/// cut in the middle, read as a row of other numbers: the file is cut back to its last whole row.
Status StatsOutput::flush() {
  if (fd_ < 0 || pending_.empty()) return Status::ok();
  const char* data = pending_.data();
  std::size_t left = pending_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      keepWholeRows(static_cast<std::size_t>(data - pending_.data()));
      (void)!::ftruncate(fd_, wholeBytes_);
      ::close(fd_);
      fd_ = -1;
      pending_.clear();
      return Status::error(path_ + ": cannot write the --stats file (" + std::strerror(error) + ")");
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  wholeBytes_ += static_cast<off_t>(pending_.size());
  wholeRows_ += pendingRows_;
  headerWritten_ = true;
  pending_.clear();
  pendingRows_ = 0;
  return Status::ok();
}

/// After a failed write of which the first `written` bytes of pending_ reached the file: counts
/// the whole rows among them, the file to be cut after the last.
void StatsOutput::keepWholeRows(std::size_t written) {
  const std::size_t end = written == 0 ? std::string::npos : pending_.rfind('\n', written - 1);
  if (end == std::string::npos) return;
  long lines = static_cast<long>(std::count(pending_.begin(), pending_.begin() + static_cast<long>(end) + 1, '\n'));
  if (!headerWritten_) --lines;  // the first line is the header
  headerWritten_ = true;
  wholeRows_ += lines;
  wholeBytes_ += static_cast<off_t>(end + 1);
}

Status StatsOutput::finish() {
  if (fd_ < 0) return Status::ok();
  Status s = flush();
  if (!s || fd_ < 0) return s;
  const int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0) return Status::error(path_ + ": cannot write the --stats file (" + std::strerror(errno) + ")");
  return Status::ok();
}

std::string StatsOutput::written() const {
  if (!created_) return "";
  if (!headerWritten_) return "--stats: no row written; " + path_ + " is empty";
  if (wholeRows_ == 0) return "--stats: no row written; " + path_ + " holds the header only";
  return "--stats: the rows of steps 0 to " + std::to_string(wholeRows_ - 1) + " (" + std::to_string(wholeRows_) +
         " whole rows under the header) are in " + path_;
}

}  // namespace fosssim::app
