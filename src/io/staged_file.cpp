// StagedFile: an output under a partial name, renamed when complete (include/fosssim/io/staged_file.h).
#include "fosssim/io/staged_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>

namespace fosssim::io {

namespace fs = std::filesystem;

std::string partialName(const std::string& path) {
  const fs::path p(path);
  const std::string stem = p.stem().string(), ending = p.extension().string();
  return fs::path(p).replace_filename(stem + ".partial" + ending).string();
}

std::string stagedPaths(const std::string& finalPath, std::string& renameTo) {
  renameTo = finalPath;
  struct stat st {};
  // A folder is refused by whoever opens it.
  if (stat(finalPath.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) return finalPath;
  struct stat link {};
  if (lstat(finalPath.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    std::error_code ec;
    const fs::path target = fs::canonical(finalPath, ec);  // fails for a dangling link: then the link is replaced
    if (!ec) renameTo = target.string();
  }
  return partialName(renameTo);
}

const char* unwritableOutput(const std::string& path, int& probe) {
  probe = -1;
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return nullptr;  // made by the writer
  if (S_ISFIFO(st.st_mode)) {
    // Without blocking, opening for writing fails (ENXIO) when no process has the pipe open for
    // reading.
    probe = open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    return probe >= 0 ? nullptr : "a named pipe that nothing reads";
  }
  return S_ISSOCK(st.st_mode) ? "a socket" : S_ISBLK(st.st_mode) ? "a block device" : nullptr;
}

Status StagedFile::prepare(const std::string& finalPath, const std::string& what, StagedFile& out) {
  out.finalPath_ = finalPath;
  out.writePath_ = stagedPaths(finalPath, out.renameTo_);
  if (!out.staged()) return Status::ok();
  struct stat link {};
  // The partial name is ours: an old partial file (or a link there) goes, so that nothing is
  // written through it. checkOutputsAgainstInputs made sure it is no input.
  if (lstat(out.writePath_.c_str(), &link) == 0 && !S_ISDIR(link.st_mode) && std::remove(out.writePath_.c_str()) != 0)
    return Status::error(what + " \"" + finalPath + "\": cannot remove the old partial file \"" + out.writePath_ +
                         "\" (" + std::strerror(errno) + ")");
  return Status::ok();
}

Status StagedFile::commit() {
  if (!staged()) return Status::ok();
  struct stat old {};
  if (stat(renameTo_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) (void)chmod(writePath_.c_str(), old.st_mode & 07777);
  if (std::rename(writePath_.c_str(), renameTo_.c_str()) != 0)
    return Status::error("\"" + finalPath_ + "\": cannot rename \"" + writePath_ + "\" to it (" + std::strerror(errno) +
                         "); the complete data is in \"" + writePath_ + "\"");
  return Status::ok();
}

bool StagedFile::made() const {
  struct stat st {};
  return stat(writePath_.c_str(), &st) == 0;
}

std::string StagedFile::whereIncomplete() const {
  if (!staged()) return "\"" + finalPath_ + "\"";
  struct stat st {};
  const bool older = stat(renameTo_.c_str(), &st) == 0;
  return "\"" + writePath_ + "\" (\"" + finalPath_ + "\" was not written" +
         (older ? "; the older file of that name is as it was)" : ")");
}

void StagedFile::discard() {
  if (staged()) (void)std::remove(writePath_.c_str());
}

Status writeWholeFile(const std::string& path, std::string_view bytes, const char* kind) {
  const auto failed = [&](int error) {
    return Status::error(std::string("cannot write ") + kind + " file \"" + path + "\": " + std::strerror(error));
  };
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return failed(errno);
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const bool flushed = std::fflush(f) == 0;
  const int error = errno;
  const bool closed = std::fclose(f) == 0;
  if (written && flushed && closed) return Status::ok();
  const int why = written && flushed ? errno : error;
  struct stat st {};
  if (stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode)) (void)std::remove(path.c_str());
  return failed(why);
}

Status writeStaged(const std::string& path, const std::string& what,
                   const std::function<Status(const std::string&)>& write) {
  StagedFile out;
  if (Status s = StagedFile::prepare(path, what, out); !s) return s;
  if (Status s = write(out.writePath()); !s) {
    out.discard();  // a file cut short is of no use (writeWholeFile removed it already)
    return out.staged() ? Status::error(s.message() + " (\"" + path + "\" was not written)") : s;
  }
  return out.commit();
}

}  // namespace fosssim::io
