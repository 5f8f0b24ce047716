// --movie: frames piped straight into an ffmpeg process as raw RGB, encoded on the fly, so a run
// leaves a single video file and no frames on disk.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/render/image.h"

#include <memory>
#include <string>
#include <sys/types.h>

namespace fosssim::render {

class MovieWriter {
 public:
  /// Starts `ffmpeg` (found on PATH) writing `path` from width x height frames at `fps`.
  /// .mp4/.mov/.mkv get H.264 in yuv420p (plays everywhere; odd sizes are padded by one pixel);
  /// other extensions let ffmpeg choose. Fails with a clear message when ffmpeg is missing.
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
