// -g and --movie: frames drawn off-screen (OSMesa) once, then written as PNG files and/or piped
// into ffmpeg.
#pragma once

#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/image.h"
#include "fosssim/render/movie_writer.h"
#include "fosssim/render/offscreen_renderer.h"

namespace fosssim::render {

struct RasterSettings {
  int width = 512, height = 512;
  std::string pngDir;  ///< write dir/frame%05d.png (created if needed); empty: no PNG files
  std::string movie;   ///< pipe into ffmpeg writing this file; empty: no movie
  double fps = 30;
};

class RasterFrames final : public PictureSink {
 public:
  /// Sets up everything before the run starts, so that a missing ffmpeg or an unwritable folder
  /// is reported before any step is taken.
  static Status open(const RasterSettings& settings, std::unique_ptr<RasterFrames>& out);
  Status frame(const Picture& picture, long number) override;
  Status finish() override;

 private:
  RasterFrames() = default;
  RasterSettings settings_;
  std::unique_ptr<OffscreenRenderer> renderer_;
  std::unique_ptr<MovieWriter> movie_;
  Image image_;  // reused from frame to frame
};

}  // namespace fosssim::render
