// Trajectory files in the reference's binary layout (raw little-endian records, no header):
//   x: 2N float64, v: 2N float64,
//   if layout.impulses:    int32 count, count x (int32 kind, int32 i, int32 j, float64 nx, ny, time)
//   if layout.polynomials: int32 count, count x (int32 length, length x float64, highest power first)
// Record 0 is the initial state; a step writes one record, or two when layout.midStep (one from
// inside collision handling, then the end of the step).
#pragma once

#include "fosssim/core/collision_log.h"
#include "fosssim/core/state.h"
#include "fosssim/core/status.h"

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>

namespace fosssim {

/// One record as read from a file.
struct TrajectoryRecord {
  VecX x, v;  ///< 2N each
  CollisionLog log;  ///< the record's impulses and polynomials (those its layout holds; empty otherwise)
};

/// Writes records straight to the file (one write() per append, no buffer in this process): what
/// append() accepted is in the file even if the process dies next. Implemented in
/// trajectory_writer.cpp.
class TrajectoryWriter {
 public:
  /// Creates (truncates) the file. Messages name it `shownAs` when given (the name the user
  /// knows, e.g. the final name of a file written under a temporary one), followed by the path.
  static Status open(const std::string& path, RecordLayout layout, std::unique_ptr<TrajectoryWriter>& out,
                     const std::string& shownAs = "");
  ~TrajectoryWriter();
  TrajectoryWriter(const TrajectoryWriter&) = delete;
  TrajectoryWriter& operator=(const TrajectoryWriter&) = delete;

  /// Appends the bytes of one record to `record`. A record never holds a non-finite number: then
  /// it fails naming the first one, and `record` is left as it was.
  Status encode(const State& state, const CollisionLog& log, std::string& record) const;
  /// Writes whole records (from encode). On failure the file is cut back to the records written
  /// before, so it never ends inside a record.
  Status append(const std::string& records);
  /// encode, then append.
  Status write(const State& state, const CollisionLog& log);
  Status close();
  /// Bytes of the complete records in the file.
  std::uint64_t bytesWritten() const { return size_; }
  const std::string& path() const { return path_; }

 private:
  TrajectoryWriter() = default;
  /// "<name>: cannot <what> the trajectory file[ \"<path>\"]"
  std::string cannot(const std::string& what) const;
  std::string path_;             ///< the file written (path())
  std::string name_, realName_;  ///< for messages: shownAs (or the path), and the path when they differ
  RecordLayout layout_;          ///< what each record holds
  int fd_ = -1;                  ///< the open file's descriptor; -1 once closed
  std::uint64_t size_ = 0;       ///< bytes of the complete records in the file (bytesWritten())
  std::string buffer_;           ///< write()'s scratch: the encoded record
};

class TrajectoryReader {
 public:
  /// Opens a file for a scene of `numParticles` particles whose records have `layout`.
  static Status open(const std::string& path, int numParticles, RecordLayout layout,
                     std::unique_ptr<TrajectoryReader>& out);
  /// Reads the next record. At a clean end of the file returns ok with `atEnd` true; a record
  /// that does not fit is an error naming record and byte: "the file ends early at record N (byte
  /// B of S)" when what the record announces runs past the end, "record N (byte B of S):
  /// impossible ..." for negative counts and unknown kinds. An error after the positions and
  /// velocities leaves them in `record` (x and v are empty otherwise), so that a caller can tell
  /// another scene's file by its values.
  Status next(TrajectoryRecord& record, bool& atEnd);
  long recordsRead() const { return records_; }
  std::uint64_t fileSize() const { return size_; }
  /// Bytes read so far (the end of the last whole record after a successful next()).
  std::uint64_t offset() const { return offset_; }

 private:
  TrajectoryReader() = default;
  Status fail(const std::string& what) const;
  Status endsEarly(const std::string& what) const;
  bool readBytes(void* into, std::uint64_t bytes);
  std::string path_;                     ///< the file read (for messages)
  int n_ = 0;                            ///< particles per record: each holds 2n_ positions and 2n_ velocities
  RecordLayout layout_;                  ///< what each record holds
  std::ifstream in_;                     ///< the open file
  std::uint64_t size_ = 0, offset_ = 0;  ///< the file's size and the bytes read so far (fileSize(), offset())
  long records_ = 0;                     ///< whole records read so far (recordsRead())
  std::vector<double> scratch_;          ///< next()'s scratch: one polynomial's coefficients as read
};

}  // namespace fosssim
