// --movie: frames piped straight into an ffmpeg process as raw RGB, encoded on the fly, so a run
// leaves a single video file and no frames on disk.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/render/image.h"

#include <cctype>
#include <iterator>
#include <memory>
#include <string>
#include <sys/types.h>

namespace fosssim::render {

/// The endings of the movies MovieWriter writes (lower case).
inline constexpr const char* kMovieEndingList[] = {".mp4", ".mov", ".mkv", ".webm", ".avi", ".gif"};

/// The frame rates a movie may have (--fps, record_movie's fps): slower than one frame in 100 s or
/// faster than 1000 a second is a typo, not a movie.
inline constexpr double kMinMovieFps = 0.01, kMaxMovieFps = 1000;

/// kMovieEndingList for messages: ".mp4, .mov, ... or .gif".
inline std::string movieEndings() {
  std::string text;
  const std::size_t n = std::size(kMovieEndingList);
  for (std::size_t k = 0; k < n; ++k)
    text += (k == 0 ? "" : k + 1 == n ? " or " : ", ") + std::string(kMovieEndingList[k]);
  return text;
}

/// Whether `path` ends (in any case) in one of kMovieEndingList. ffmpeg would write an image name
/// (out.png) as one picture and fail at the second frame, a pattern (out%03d.png) as numbered
/// pictures, and finds no format for other endings. Inline: the command line checks names in
/// builds without the renderer too.
inline bool isMovieName(const std::string& path) {
  const std::size_t dot = path.find_last_of("./");
  if (dot == std::string::npos || path[dot] != '.') return false;
  std::string ending = path.substr(dot);
  for (char& c : ending) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* movie : kMovieEndingList)
    if (ending == movie) return true;
  return false;
}

class MovieWriter {
 public:
  /// Starts `ffmpeg` (found on PATH) writing `path` from width x height frames at `fps`.
  /// .mp4/.mov/.mkv get H.264 in yuv420p (plays everywhere; odd sizes are padded by one pixel);
  /// .webm, .avi and .gif let ffmpeg choose; other names (isMovieName) are refused. Fails with a
  /// clear message when ffmpeg is missing.
  static Status open(const std::string& path, int width, int height, double fps, std::unique_ptr<MovieWriter>& out);
  ~MovieWriter();  ///< closes (and waits for ffmpeg) if close() was not called
  MovieWriter(const MovieWriter&) = delete;
  MovieWriter& operator=(const MovieWriter&) = delete;

  Status write(const Image& frame);
  /// Ends the stream and waits for ffmpeg; fails if it did not exit cleanly.
  Status close();
  long frames() const { return frames_; }

 private:
  MovieWriter(std::string path, int fd, pid_t pid, int width, int height);
  std::string path_;
  int fd_ = -1;
  pid_t pid_ = -1;
  int width_, height_;
  long frames_ = 0;
};

/// The full path of `program` found on PATH, or empty.
std::string findOnPath(const std::string& program);

}  // namespace fosssim::render
