// Keeps a growing output file from filling its disk. A continuous-time or hybrid trajectory
// record holds the polynomials of every candidate pair: thousands of particles write gigabytes
// per step. From the first step on, the final size is estimated (bytes per step so far times the
// steps of the scene) and reported when it is large or more than the free space; before each
// write the free space is checked, and a write that would leave less than a margin free is
// refused, so that the run stops with a message (and whole records) instead of a full disk.
#pragma once

#include "fosssim/core/status.h"

#include <cstdint>
#include <functional>
#include <string>

namespace fosssim::app {

/// The bytes an unprivileged user may still write on the file system holding `path` (statvfs's
/// f_bavail); false when unknown. Replaceable, so that tests need not fill a disk.
using FreeSpaceQuery = std::function<bool(const std::string& path, std::uint64_t& bytes)>;
bool statvfsFreeSpace(const std::string& path, std::uint64_t& bytes);

/// "1.5 GiB", "12 MiB", "800 bytes".
std::string bytesText(std::uint64_t bytes);

class DiskBudget {
 public:
  static constexpr std::uint64_t kLargeOutput = 1ull << 30;  ///< a larger estimate is reported
  static constexpr std::uint64_t kFreeMargin = 16ull << 20;  ///< never leave less than this free

  /// `path`: the file being written; `name`: how messages call it; `hint`: what to add to the
  /// warnings (e.g. how to make the file smaller), may be empty.
  DiskBudget(std::string path, std::string name, long totalSteps, std::string hint,
             FreeSpaceQuery query = statvfsFreeSpace);

  /// Before writing `bytes` more (the records of step `step`): fails when the free space after
  /// them would be less than kFreeMargin. The free space is asked again whenever the writes since
  /// the last answer could have used half of what was left above the margin.
  Status reserve(std::uint64_t bytes, long step);

  /// After step `step`'s records, the file holding `written` bytes of which `initial` are record
  /// 0: a warning (once each: the estimate is large; it exceeds the free space), or empty.
  std::string estimate(long step, std::uint64_t written, std::uint64_t initial);

 private:
  void query();
  std::string path_, name_, hint_;
  long totalSteps_;
  FreeSpaceQuery query_;
  bool known_ = false;                ///< the last query answered
  std::uint64_t free_ = 0;            ///< its answer
  std::uint64_t sinceQuery_ = 0;      ///< bytes reserved since
  bool warnedLarge_ = false, warnedFull_ = false;
};

}  // namespace fosssim::app
