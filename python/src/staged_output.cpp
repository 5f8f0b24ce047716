#include "staged_output.h"

#include "errors.h"

#include <stdexcept>
#include <unistd.h>
#include <sys/stat.h>

namespace fosssim::py {
namespace {

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

StagedOutput::StagedOutput(const std::string& finalPath, const char* what, const std::string& input) {
  checkPath(finalPath, what);
  if (finalPath.empty()) throw std::invalid_argument(std::string(what) + ": the path is empty");
  checkNotInput(finalPath, input, what, "");
  struct stat st {};
  // Refused here, before a writer that removes its file on error (libpng) could rmdir an empty folder.
  if (stat(finalPath.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw FileError(std::string(what) + ": " + quote(finalPath) + " is a directory");
  // The partial name may not be the scene file either: preparing removes an old partial file.
  std::string renameTo;
  if (const std::string writePath = io::stagedPaths(finalPath, renameTo); writePath != renameTo)
    checkNotInput(writePath, input, what, "its partial file " + quote(writePath) + " ");
  if (const Status s = io::StagedFile::prepare(finalPath, what, file_); !s) throw FileError(s.message());
  // Last: nothing may throw after a pipe's probe is open (a throwing constructor runs no destructor).
  if (const char* kind = io::unwritableOutput(finalPath, pipeProbe_))
    throw FileError(std::string(what) + ": " + quote(finalPath) + ": cannot write there (it is " + kind +
                    ", not a file): choose a file name");
}

StagedOutput::~StagedOutput() {
  if (pipeProbe_ >= 0) close(pipeProbe_);
}

std::string StagedOutput::whereData(const char* data) const {
  struct stat st {};
  if (!staged() || stat(writePath().c_str(), &st) == 0) return std::string("; ") + data + " is in " + whereIncomplete();
  // ffmpeg that fails at once (fps=inf) makes no file: naming one would send the reader looking.
  return "; nothing was written (no partial file was made; " + quote(finalPath()) + " was left as it was)";
}

void StagedOutput::commit() {
  if (const Status s = file_.commit(); !s) throw FileError(s.message());
}

}  // namespace fosssim::py
