#include "disk_budget.h"

#include <cstdio>
#include <filesystem>
#include <sys/statvfs.h>

namespace fosssim::app {

bool statvfsFreeSpace(const std::string& path, std::uint64_t& bytes) {
  // The file system of the folder: the file itself may not exist yet.
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  struct statvfs st {};
  if (statvfs(dir.c_str(), &st) != 0) return false;
  bytes = static_cast<std::uint64_t>(st.f_bavail) * static_cast<std::uint64_t>(st.f_frsize);
  return true;
}

std::string bytesText(std::uint64_t bytes) {
  static const char* const units[] = {"KiB", "MiB", "GiB", "TiB", "PiB"};
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  double value = static_cast<double>(bytes) / 1024;
  int unit = 0;
  while (value >= 1024 && unit < 4) value /= 1024, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, "%.*f %s", value < 10 ? 1 : 0, value, units[unit]);
  return text;
}

DiskBudget::DiskBudget(std::string path, std::string name, long totalSteps, std::string hint, FreeSpaceQuery query)
    : path_(std::move(path)), name_(std::move(name)), hint_(std::move(hint)), totalSteps_(totalSteps),
      query_(std::move(query)) {}

void DiskBudget::query() {
  std::uint64_t bytes = 0;
  known_ = query_ && query_(path_, bytes);
  free_ = known_ ? bytes : 0;
  sinceQuery_ = 0;
}

Status DiskBudget::reserve(std::uint64_t bytes, long step) {
  const std::uint64_t headroom = free_ > kFreeMargin ? free_ - kFreeMargin : 0;
  if (!known_ || sinceQuery_ + bytes >= headroom / 2) query();
  if (!known_) return Status::ok();  // nothing to go by; a failing write is still reported
  if (sinceQuery_ + bytes + kFreeMargin > free_) {
    const std::uint64_t left = free_ > sinceQuery_ ? free_ - sinceQuery_ : 0;
    return Status::error(name_ + ": stopped before writing the records of step " + std::to_string(step) + " (" +
                         bytesText(bytes) + "): they would leave less than " + bytesText(kFreeMargin) +
                         " free on its disk (" + bytesText(left) + " free)" + (hint_.empty() ? "" : "; " + hint_));
  }
  sinceQuery_ += bytes;
  return Status::ok();
}

std::string DiskBudget::estimate(long step, std::uint64_t written, std::uint64_t initial) {
  if (step <= 0 || totalSteps_ <= 0 || written < initial) return "";
  const double perStep = static_cast<double>(written - initial) / static_cast<double>(step);
  const double total = static_cast<double>(initial) + perStep * static_cast<double>(totalSteps_);
  const double more = total - static_cast<double>(written);
  const auto text = [](double bytes) { return bytesText(static_cast<std::uint64_t>(bytes)); };
  std::string warning;
  const std::uint64_t available = free_ > sinceQuery_ ? free_ - sinceQuery_ : 0;
  if (!warnedFull_ && known_ && more > 0 && more + static_cast<double>(kFreeMargin) > static_cast<double>(available)) {
    warnedFull_ = warnedLarge_ = true;
    const double room = static_cast<double>(available > kFreeMargin ? available - kFreeMargin : 0);
    const long lastStep = step + static_cast<long>(perStep > 0 ? room / perStep : 0);
    warning = name_ + ": at this rate the trajectory will take about " + text(total) + " (" + text(perStep) +
              " per step, " + std::to_string(totalSteps_) + " steps), but only " + bytesText(available) +
              " are free on its disk: the run will stop before the disk is full, after about step " +
              std::to_string(lastStep);
  } else if (!warnedLarge_ && total > static_cast<double>(kLargeOutput)) {
    warnedLarge_ = true;
    warning = name_ + ": at this rate the trajectory will take about " + text(total) + " (" + text(perStep) +
              " per step, " + std::to_string(totalSteps_) + " steps)";
  }
  if (!warning.empty() && !hint_.empty()) warning += "; " + hint_;
  return warning;
}

}  // namespace fosssim::app
