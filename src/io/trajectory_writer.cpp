// The writing half of trajectory files (the layout is in fosssim/io/trajectory.h). Records go to
// the file through a plain descriptor, one write() per append: no bytes wait in a stream buffer
// (a window run's file grows step by step, and a killed process loses nothing it appended), and
// a write that fails half-way is cut back, so the file always ends after a whole record.
#include "fosssim/io/trajectory.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <sstream>
#include <unistd.h>

namespace fosssim {
namespace {

static_assert(sizeof(double) == 8 && sizeof(std::int32_t) == 4, "the file format needs 8-byte doubles");

// The format is little-endian; so are the machines we build for. A big-endian port would swap here.
template <class T>
void put(std::string& buffer, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  buffer.append(bytes, sizeof(T));
}

bool allFinite(const double* values, std::size_t count) {
  for (std::size_t k = 0; k < count; ++k)
    if (!std::isfinite(values[k])) return false;
  return true;
}

/// Names the first non-finite number of a record, for the message.
std::string firstNonFinite(const State& state, const CollisionLog& log, const RecordLayout& layout) {
  std::ostringstream what;
  for (int i = 0; i < state.numParticles(); ++i) {
    const double* x = state.x.data() + 2 * i;
    const double* v = state.v.data() + 2 * i;
    if (!allFinite(x, 2)) what << "particle " << i << "'s position (" << x[0] << ", " << x[1] << ")";
    else if (!allFinite(v, 2)) what << "particle " << i << "'s velocity (" << v[0] << ", " << v[1] << ")";
    else continue;
    return what.str();
  }
  if (layout.impulses)
    for (std::size_t k = 0; k < log.impulses.size(); ++k) {
      const Impulse& im = log.impulses[k];
      if (std::isfinite(im.n.x()) && std::isfinite(im.n.y()) && std::isfinite(im.tau)) continue;
      what << "impulse " << k << " (" << pairKindName(im.kind) << ", " << im.i << " and " << im.j << ": n = ("
           << im.n.x() << ", " << im.n.y() << "), tau " << im.tau << ")";
      return what.str();
    }
  if (layout.polynomials)
    for (int k = 0; k < log.polynomials.size(); ++k)
      if (!allFinite(log.polynomials.coefficients(k), static_cast<std::size_t>(log.polynomials.length(k)))) {
        what << "polynomial " << k << " of the collision log";
        return what.str();
      }
  return "";
}

}  // namespace

Status TrajectoryWriter::open(const std::string& path, RecordLayout layout, std::unique_ptr<TrajectoryWriter>& out,
                              const std::string& shownAs) {
  std::unique_ptr<TrajectoryWriter> w(new TrajectoryWriter());
  w->path_ = path;
  const bool renamed = !shownAs.empty() && shownAs != path;
  w->name_ = renamed ? shownAs : path;
  w->realName_ = renamed ? " \"" + path + "\"" : "";
  w->layout_ = layout;
  w->fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (w->fd_ < 0) return Status::error(w->cannot("create") + " (" + std::strerror(errno) + ")");
  out = std::move(w);
  return Status::ok();
}

TrajectoryWriter::~TrajectoryWriter() {
  if (fd_ >= 0) ::close(fd_);
}

Status TrajectoryWriter::encode(const State& state, const CollisionLog& log, std::string& record) const {
  // Checked before anything is appended: the caller's buffer may already hold an earlier record.
  bool finite = state.x.allFinite() && state.v.allFinite();
  if (finite && layout_.impulses)
    for (const Impulse& im : log.impulses)
      finite = finite && std::isfinite(im.n.x()) && std::isfinite(im.n.y()) && std::isfinite(im.tau);
  if (finite && layout_.polynomials)
    for (int k = 0; k < log.polynomials.size() && finite; ++k)
      finite = allFinite(log.polynomials.coefficients(k), static_cast<std::size_t>(log.polynomials.length(k)));
  if (!finite)
    return Status::error("a trajectory record cannot hold a non-finite number: " + firstNonFinite(state, log, layout_));

  record.append(reinterpret_cast<const char*>(state.x.data()), state.x.size() * sizeof(double));
  record.append(reinterpret_cast<const char*>(state.v.data()), state.v.size() * sizeof(double));
  if (layout_.impulses) {
    put<std::int32_t>(record, static_cast<std::int32_t>(log.impulses.size()));
    for (const Impulse& im : log.impulses) {
      put<std::int32_t>(record, static_cast<std::int32_t>(im.kind));
      put<std::int32_t>(record, im.i);
      put<std::int32_t>(record, im.j);
      put(record, im.n.x());
      put(record, im.n.y());
      put(record, im.tau);
    }
  }
  if (layout_.polynomials) {
    const PolynomialLog& polys = log.polynomials;
    put<std::int32_t>(record, polys.size());
    for (int k = 0; k < polys.size(); ++k) {
      put<std::int32_t>(record, polys.length(k));
      record.append(reinterpret_cast<const char*>(polys.coefficients(k)), polys.length(k) * sizeof(double));
    }
  }
  return Status::ok();
}

Status TrajectoryWriter::append(const std::string& records) {
  if (fd_ < 0) return Status::error(cannot("write") + ": it is already closed");
  const char* data = records.data();
  std::size_t left = records.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, data, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      // Cut the file back to its last whole record (not possible on devices: nothing to cut there).
      if (ftruncate(fd_, static_cast<off_t>(size_)) == 0) (void)lseek(fd_, static_cast<off_t>(size_), SEEK_SET);
      return Status::error(cannot("write") + " (" + std::strerror(error) + ")");
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  size_ += records.size();
  return Status::ok();
}

Status TrajectoryWriter::write(const State& state, const CollisionLog& log) {
  buffer_.clear();
  if (Status s = encode(state, log, buffer_); !s) return Status::error(cannot("write") + ": " + s.message());
  return append(buffer_);
}

std::string TrajectoryWriter::cannot(const std::string& what) const {
  return name_ + ": cannot " + what + " the trajectory file" + realName_;
}

Status TrajectoryWriter::close() {
  if (fd_ < 0) return Status::ok();
  const int rc = ::close(fd_);
  fd_ = -1;
  if (rc != 0) return Status::error(cannot("finish writing") + " (" + std::strerror(errno) + ")");
  return Status::ok();
}

}  // namespace fosssim
