// The reading half of trajectory files (the writer is in trajectory_writer.cpp).
#include "fosssim/io/trajectory.h"

#include "input_path.h"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace fosssim {
namespace {

static_assert(sizeof(double) == 8 && sizeof(std::int32_t) == 4, "the file format needs 8-byte doubles");

}  // namespace

Status TrajectoryReader::open(const std::string& path, int numParticles, RecordLayout layout,
                              std::unique_ptr<TrajectoryReader>& out) {
  // Every record must hold some bytes, or the end of the file could never be reached.
  if (numParticles < 1) return Status::error(path + ": a trajectory needs a scene with at least one particle");
  std::unique_ptr<TrajectoryReader> r(new TrajectoryReader());
  r->path_ = path;
  r->n_ = numParticles;
  r->layout_ = layout;
  if (Status st = io_detail::checkInputPath(path, "trajectory file"); !st) return st;
  // Records are checked against the file's size, which a device does not have (/dev/zero reads
  // as endless zeros and reports size 0: it would be graded as an empty file).
  {
    std::error_code ec;
    const auto type = std::filesystem::status(path, ec).type();
    if (type == std::filesystem::file_type::character || type == std::filesystem::file_type::block)
      return Status::error(path + ": cannot read the trajectory file (it is a device, not a file: a trajectory is "
                                  "read against its file's size)");
  }
  r->in_.open(path, std::ios::binary);
  if (!r->in_) return Status::error(path + ": cannot open the trajectory file (" + std::strerror(errno) + ")");
  r->in_.seekg(0, std::ios::end);
  const std::streamoff size = r->in_.tellg();
  r->in_.seekg(0);
  // Records are checked against the size, so it must be known: no pipes or terminals.
  if (size < 0 || !r->in_)
    return Status::error(path + ": cannot determine the size of the trajectory file (is it a regular file?)");
  r->size_ = static_cast<std::uint64_t>(size);
  out = std::move(r);
  return Status::ok();
}

Status TrajectoryReader::fail(const std::string& what) const {
  return Status::error(path_ + ": record " + std::to_string(records_) + " (byte " + std::to_string(offset_) +
                       " of " + std::to_string(size_) + "): " + what +
                       "; is this the trajectory of this scene?");
}

// A file cut short (a copy that did not finish, a run that was killed) and a count misread from
// another scene's bytes look the same here; the message says where the bytes ran out and what
// they were announced to hold, and the grader's check of record 0 tells the other scene apart.
Status TrajectoryReader::endsEarly(const std::string& what) const {
  return Status::error(path_ + ": the file ends early at record " + std::to_string(records_) + " (byte " +
                       std::to_string(offset_) + " of " + std::to_string(size_) + "): " + what);
}

bool TrajectoryReader::readBytes(void* into, std::uint64_t bytes) {
  if (bytes > size_ - offset_) return false;
  in_.read(static_cast<char*>(into), static_cast<std::streamsize>(bytes));
  if (!in_) return false;
  offset_ += bytes;
  return true;
}

Status TrajectoryReader::next(TrajectoryRecord& record, bool& atEnd) {
  atEnd = offset_ == size_;
  if (atEnd) return Status::ok();
  const std::uint64_t stateBytes = 16ull * static_cast<std::uint64_t>(n_);
  const auto remaining = [this] { return std::to_string(size_ - offset_) + " remain"; };
  record.x.resize(0);
  record.v.resize(0);
  if (2 * stateBytes > size_ - offset_)
    return endsEarly("the positions and velocities of " + std::to_string(n_) + " particles need " +
                     std::to_string(2 * stateBytes) + " bytes, " + remaining());
  record.x.resize(2 * n_);
  record.v.resize(2 * n_);
  if (!readBytes(record.x.data(), stateBytes) || !readBytes(record.v.data(), stateBytes)) {
    record.x.resize(0);
    record.v.resize(0);
    return fail("cannot read the positions and velocities");
  }
  record.log.clear();
  std::int32_t count = 0;
  if (layout_.impulses) {
    if (!readBytes(&count, 4)) return endsEarly("the impulse count needs 4 bytes, " + remaining());
    constexpr std::uint64_t kImpulseBytes = 3 * 4 + 3 * 8;
    if (count < 0) return fail("impossible impulse count " + std::to_string(count));
    if (static_cast<std::uint64_t>(count) * kImpulseBytes > size_ - offset_)
      return endsEarly("impulse count " + std::to_string(count) + " needs " +
                       std::to_string(static_cast<std::uint64_t>(count) * kImpulseBytes) + " bytes, " + remaining());
    for (std::int32_t k = 0; k < count; ++k) {
      std::int32_t head[3];
      double tail[3];
      if (!readBytes(head, sizeof head) || !readBytes(tail, sizeof tail))
        return fail("cannot read impulse " + std::to_string(k));
      if (head[0] < 0 || head[0] > 2) return fail("impulse of unknown kind " + std::to_string(head[0]));
      record.log.impulses.push_back(
          Impulse{static_cast<PairKind>(head[0]), head[1], head[2], Vec2(tail[0], tail[1]), tail[2]});
    }
  }
  if (layout_.polynomials) {
    if (!readBytes(&count, 4)) return endsEarly("the polynomial count needs 4 bytes, " + remaining());
    if (count < 0) return fail("impossible polynomial count " + std::to_string(count));
    if (static_cast<std::uint64_t>(count) * 4 > size_ - offset_)
      return endsEarly("polynomial count " + std::to_string(count) + " needs at least " +
                       std::to_string(static_cast<std::uint64_t>(count) * 4) + " bytes, " + remaining());
    record.log.polynomials.setEnabled(true);
    for (std::int32_t k = 0; k < count; ++k) {
      std::int32_t length = 0;
      if (!readBytes(&length, 4))
        return endsEarly("polynomial " + std::to_string(k) + " of " + std::to_string(count) +
                         ": its length needs 4 bytes, " + remaining());
      if (length < 0)
        return fail("impossible length " + std::to_string(length) + " of polynomial " + std::to_string(k));
      const std::uint64_t bytes = 8ull * static_cast<std::uint64_t>(length);
      if (bytes > size_ - offset_)
        return endsEarly("polynomial " + std::to_string(k) + " of " + std::to_string(count) + " (length " +
                         std::to_string(length) + ") needs " + std::to_string(bytes) + " bytes, " + remaining());
      scratch_.resize(static_cast<size_t>(length));
      if (!readBytes(scratch_.data(), bytes)) return fail("cannot read polynomial " + std::to_string(k));
      record.log.polynomials.add(scratch_.data(), length);
    }
  }
  ++records_;
  return Status::ok();
}

}  // namespace fosssim
