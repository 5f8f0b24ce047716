#pragma once
// An output file that never leaves a half-written file under its name: written under a partial
// name next to the final one ("out.bin" as "out.partial.bin", "run.mp4" as "run.partial.mp4":
// ffmpeg picks the format by the ending) and renamed to the final name when complete. A write
// that does not complete leaves the partial file, and the final name as it was (an older file of
// that name is not cut or removed). A symbolic link keeps pointing at the new file. Devices and
// named pipes are written directly: there is nothing to rename. The command line's -o and
// --movie and the Python module's writers use it.

#include "fosssim/core/status.h"

#include <functional>
#include <string>
#include <string_view>

namespace fosssim::io {

/// "dir/out.bin" -> "dir/out.partial.bin"; "traj" -> "traj.partial".
std::string partialName(const std::string& path);

/// Where a staged output goes: `renameTo` the final name, a symbolic link resolved, and the
/// returned name to write while the output lasts, the partial name next to it, or the final name
/// itself for a device or a named pipe (nothing to rename).
std::string stagedPaths(const std::string& finalPath, std::string& renameTo);

/// Why no output can be written at `path`, or nullptr when one can (nothing there yet, a regular
/// file, a character device such as /dev/null, or a named pipe that a process reads). A named
/// pipe that nothing reads is refused: opening it for writing blocks until a reader comes, which
/// may never happen (a run hung in open(), deaf to SIGTERM). A socket cannot be opened at all,
/// and a block device is a disk, never a wanted output. For a pipe that a process reads, `probe`
/// receives a descriptor open for writing on it, -1 otherwise. The caller closes it only after its
/// own writer has opened the pipe: closed before, it would be the pipe's last writer, a reader
/// such as `cat` would take that for the end of its input and leave, and the writer's open would
/// then block for ever.
const char* unwritableOutput(const std::string& path, int& probe);

/// One output written under its partial name and renamed at the end.
class StagedFile {
 public:
  /// Chooses where the data goes while the output lasts and removes a stale partial file (the
  /// partial name is FOSSSim's own). `what` names the option or function in messages ("-o",
  /// "--movie", "write_trajectory").
  static Status prepare(const std::string& finalPath, const std::string& what, StagedFile& out);

  /// Where to write now: the partial name, or the final one for devices and pipes.
  const std::string& writePath() const { return writePath_; }
  const std::string& finalPath() const { return finalPath_; }
  bool staged() const { return writePath_ != renameTo_; }

  /// The output is complete: the partial file takes the final name (and the old file's
  /// permissions).
  Status commit();
  /// For the message of an output that did not complete: where its data is, and that the final
  /// name was left as it was.
  std::string whereIncomplete() const;
  /// Whether the file written to exists (a writer that could not create it made none).
  bool made() const;
  /// Removes the partial file (for an output whose partial file holds nothing of use).
  void discard();

 private:
  std::string finalPath_;  ///< as given
  std::string renameTo_;   ///< the final path, a symbolic link resolved (the link keeps pointing at it)
  std::string writePath_;
};

/// Writes `bytes` to `path` (created or truncated), as "cannot write KIND file \"PATH\": why" when
/// that fails. A regular file cut short (a full disk) is removed: it would pass for a whole one.
/// Anything else (/dev/null, /dev/full, a named pipe) is only written to, never removed: libpng's
/// own file writer removes its file whatever it is, which as root deletes a device node.
Status writeWholeFile(const std::string& path, std::string_view bytes, const char* kind);

/// Writes one whole file at once through `write` (given the path to write to) under the partial
/// name, then gives it the final name: a reader never finds the file half written under its name
/// (the window's saves, which a script may pick up as soon as they appear), and a failed write
/// leaves an older file of that name as it was and no partial file. `what` names the output in
/// messages. Devices and named pipes are written directly (StagedFile).
Status writeStaged(const std::string& path, const std::string& what,
                   const std::function<Status(const std::string&)>& write);

}  // namespace fosssim::io
