#include "staged_output.h"

#include "errors.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <sys/stat.h>

namespace fosssim::py {
namespace {

namespace fs = std::filesystem;

std::string quote(const std::string& path) { return "\"" + path + "\""; }

/// Fails when `output` exists and is the file `input` (device and inode: a hard or symbolic link
/// to the scene file is the scene file).
void checkNotInput(const std::string& output, const std::string& input, const char* what, const std::string& role) {
  struct stat out {}, in {};
  if (input.empty() || stat(output.c_str(), &out) != 0 || stat(input.c_str(), &in) != 0) return;
  if (out.st_dev == in.st_dev && out.st_ino == in.st_ino)
    throw FileError(std::string(what) + ": " + quote(output) + (role.empty() ? " " : ": " + role) +
                    "is the same file as the scene file the Scene was loaded from (" + quote(input) +
                    "): FOSSSim never writes over its input; choose another output name");
}

}  // namespace

void checkPath(const std::string& path, const char* what) {
  if (path.find('\0') != std::string::npos) throw std::invalid_argument(std::string(what) + ": embedded null byte");
}

std::string partialName(const std::string& path) {
  const fs::path p(path);
  const std::string stem = p.stem().string(), ending = p.extension().string();
  return fs::path(p).replace_filename(stem + ".partial" + ending).string();
}

StagedOutput::StagedOutput(const std::string& finalPath, const char* what, const std::string& input)
    : finalPath_(finalPath), renameTo_(finalPath), writePath_(finalPath) {
  checkPath(finalPath, what);
  if (finalPath.empty()) throw std::invalid_argument(std::string(what) + ": the path is empty");
  checkNotInput(finalPath, input, what, "");
  struct stat st {};
  if (stat(finalPath.c_str(), &st) == 0) {
    // Refused here, before a writer that removes its file on error (libpng) could rmdir an empty folder.
    if (S_ISDIR(st.st_mode)) throw FileError(std::string(what) + ": " + quote(finalPath) + " is a directory");
    if (!S_ISREG(st.st_mode)) return;  // a device or a named pipe: written directly
  }
  struct stat link {};
  if (lstat(finalPath.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    std::error_code ec;
    const fs::path target = fs::canonical(finalPath, ec);  // fails for a dangling link: then the link is replaced
    if (!ec) renameTo_ = target.string();
  }
  writePath_ = partialName(renameTo_);
  checkNotInput(writePath_, input, what, "its partial file " + quote(writePath_) + " ");
  // An old partial file (or a link there) goes, so that nothing is written through it.
  if (lstat(writePath_.c_str(), &link) == 0 && !S_ISDIR(link.st_mode) && std::remove(writePath_.c_str()) != 0)
    throw FileError(std::string(what) + ": " + quote(finalPath) + ": cannot remove the old partial file " +
                    quote(writePath_) + " (" + std::strerror(errno) + ")");
}

void StagedOutput::commit() {
  if (!staged()) return;
  struct stat old {};
  if (stat(renameTo_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) (void)chmod(writePath_.c_str(), old.st_mode & 07777);
  if (std::rename(writePath_.c_str(), renameTo_.c_str()) != 0)
    throw FileError(quote(finalPath_) + ": cannot rename " + quote(writePath_) + " to it (" + std::strerror(errno) +
                    "); the complete data is in " + quote(writePath_));
}

std::string StagedOutput::whereIncomplete() const {
  if (!staged()) return quote(finalPath_);
  struct stat st {};
  const bool older = stat(renameTo_.c_str(), &st) == 0;
  return quote(writePath_) + " (" + quote(finalPath_) + " was not written" +
         (older ? "; the older file of that name is as it was)" : ")");
}

void StagedOutput::discard() {
  if (staged()) (void)std::remove(writePath_.c_str());
}

}  // namespace fosssim::py
