// Internal header: what a path given as input must be before FOSSSim opens it.
//
// Opening a named pipe for reading blocks until some other process opens it for writing, which
// may never happen: a mistyped path must not hang the program, so pipes and sockets are refused
// before the open, as are directories (which open "successfully" on some systems and then fail
// to read). Devices such as /dev/zero are left to the readers' size limits.
#pragma once

#include "fosssim/core/status.h"

#include <filesystem>
#include <string>

namespace fosssim::io_detail {

/// ok() when `path` may be opened as the input file `what` ("scene file", "trajectory file");
/// an error naming the path otherwise. A missing path is left to the open, whose errno says why.
inline Status checkInputPath(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_type type = fs::status(path, ec).type();
  const char* kind = type == fs::file_type::directory ? "a directory"
                     : type == fs::file_type::fifo    ? "a named pipe"
                     : type == fs::file_type::socket  ? "a socket"
                                                      : nullptr;
  if (kind) return Status::error(path + ": cannot read the " + what + " (it is " + kind + ", not a file)");
  return Status::ok();
}

}  // namespace fosssim::io_detail
