#include "fosssim/render/raster_frames.h"

#include "fosssim/render/png_writer.h"

#include <filesystem>

namespace fosssim::render {

Status RasterFrames::open(const RasterSettings& settings, std::unique_ptr<RasterFrames>& out) {
  std::unique_ptr<RasterFrames> r(new RasterFrames());
  r->settings_ = settings;
  if (!settings.pngDir.empty())
    if (Status s = createDirectory(settings.pngDir, "-g"); !s) return s;
  if (Status s = OffscreenRenderer::create(settings.width, settings.height, r->renderer_); !s) return s;
  if (!settings.movie.empty()) {
    const std::string parent = std::filesystem::path(settings.movie).parent_path().string();
    if (Status s = createDirectory(parent, "--movie"); !s) return s;
  }
  if (!settings.movie.empty())
    if (Status s = MovieWriter::open(settings.movie, settings.width, settings.height, settings.fps, r->movie_); !s)
      return s;
  out = std::move(r);
  return Status::ok();
}

Status RasterFrames::frame(const Picture& picture, long number) {
  if (Status s = renderer_->render(picture, image_); !s) return s;
  if (!settings_.pngDir.empty())
    if (Status s = writePng(pngFrameName(settings_.pngDir, number), image_); !s) return s;
  if (movie_)
    if (Status s = movie_->write(image_); !s) return s;
  return Status::ok();
}

Status RasterFrames::finish() { return movie_ ? movie_->close() : Status::ok(); }

}  // namespace fosssim::render
