// The module's output files, written as the command line writes -o and --movie
// (io::StagedFile, include/fosssim/io/staged_file.h): under a partial name next to the final one ("out.bin" as
// "out.partial.bin", "run.mp4" as "run.partial.mp4": ffmpeg picks the format by the ending) and
// renamed over the final name only when complete. A write that fails leaves the final name as it
// was (an older file of that name is not cut or removed) and the exception says where the data so
// far is. Devices and named pipes are written directly: there is nothing to rename, and a device
// node must never be replaced or removed (libpng's simplified writer removes its file on error).
// What the command line refuses to write is refused here too (io::unwritableOutput): a named
// pipe that nothing reads (the write would block for ever), a socket, a block device.
#pragma once

#include "errors.h"

#include "fosssim/io/staged_file.h"

#include <string>
#include <utility>

namespace fosssim::py {

/// Raises ValueError("<what>: embedded null byte", as Python's open()) when `path` holds a NUL: the C
/// library would stop at it and read or write a file of another name.
void checkPath(const std::string& path, const char* what);

class StagedOutput {
 public:
  /// Checks the path (NUL, a folder, the scene file `input` the Scene was loaded from, under any
  /// name or link) and removes a stale partial file (the partial name is FOSSSim's own). `what`
  /// names the function in messages. Throws ValueError or FileError; nothing is written then.
  StagedOutput(const std::string& finalPath, const char* what, const std::string& input = "");
  /// Closes the named pipe's probe (io::unwritableOutput), the writer being done with the pipe.
  ~StagedOutput();
  StagedOutput(const StagedOutput&) = delete;
  StagedOutput& operator=(const StagedOutput&) = delete;

  /// Where to write now: the partial name, or the final one for a device or a named pipe.
  const std::string& writePath() const { return file_.writePath(); }
  const std::string& finalPath() const { return file_.finalPath(); }
  bool staged() const { return file_.staged(); }

  /// The output is complete: the partial file takes the final name (and the old file's
  /// permissions). Throws FileError naming both when the rename fails.
  void commit();
  /// For the message of a write that did not complete: where its data is, and that the final name
  /// was left as it was.
  std::string whereIncomplete() const { return file_.whereIncomplete(); }
  /// "; <data> is in <the partial file> (...)", or, when that file does not exist, that nothing
  /// was written and the final name was left as it was.
  std::string whereData(const char* data) const;
  /// Removes the partial file (for outputs whose partial file holds nothing useful, a PNG).
  void discard() { file_.discard(); }

  /// Runs `body` (the writing); a FileError or SimulationError it throws is raised again, same
  /// type, saying where `data` ("the trajectory so far") is: the partial file, kept. When no
  /// partial file was made (ffmpeg failed before writing one), says so instead of naming it.
  /// `finish` runs first on failure: it ends a writer that makes its file late (the movie's
  /// ffmpeg, which may not have created it yet), so that whether the file exists is known.
  template <class F, class Finish>
  auto keepingPartial(const char* data, F&& body, Finish&& finish) {
    try {
      return body();
    } catch (const FileError& e) {
      finish();
      throw FileError(std::string(e.what()) + whereData(data));
    } catch (const SimulationError& e) {
      finish();
      throw SimulationError(std::string(e.what()) + whereData(data));
    }
  }
  template <class F>
  auto keepingPartial(const char* data, F&& body) {
    return keepingPartial(data, std::forward<F>(body), [] {});
  }

 private:
  io::StagedFile file_;
  int pipeProbe_ = -1;  ///< a named pipe's probe, open until the writing is done (io::unwritableOutput)
};

}  // namespace fosssim::py
