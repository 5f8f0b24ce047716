#include "fosssim/render/raster_frames.h"

#include "fosssim/io/staged_file.h"
#include "fosssim/render/png_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fosssim::render {

Status RasterFrames::open(const RasterSettings& settings, std::unique_ptr<RasterFrames>& out) {
  std::unique_ptr<RasterFrames> r(new RasterFrames());
  r->settings_ = settings;
  if (!settings.pngDir.empty())
    if (Status s = createDirectory(settings.pngDir, "the PNG frames"); !s) return s;
  if (Status s = OffscreenRenderer::create(settings.width, settings.height, r->renderer_); !s) return s;
  out = std::move(r);
  return Status::ok();
}

Status RasterFrames::start(const SceneFile& file, const Picture& initial) {
  if (!movie_) return Status::ok();
  if (settings_.titleCard) {
    if (Status s = renderer_->render(titleCard(file, initial.view), image_); !s) return s;
    const long frames = std::max(1L, std::lround(kTitleSeconds * settings_.fps));
    for (long k = 0; k < frames; ++k)
      if (Status s = movie_->write(image_); !s) return s;
  }
  if (Status s = renderer_->render(initial, image_); !s) return s;
  return movie_->write(image_);
}

bool RasterFrames::inMovie(long number) const {
  return movie_ && number % std::max(1L, settings_.movieEvery) == 0;
}

bool RasterFrames::wants(long number) const { return !settings_.pngDir.empty() || inMovie(number); }

Status RasterFrames::frame(const Picture& picture, long number) {
  if (!wants(number)) return Status::ok();
  if (Status s = renderer_->render(picture, image_); !s) return s;
  if (!settings_.pngDir.empty()) {
    // Staged as -m's SVG frames are (SvgFrames::frame).
    const auto write = [&](const std::string& to) { return writePng(to, image_); };
    if (Status s = io::writeStaged(pngFrameName(settings_.pngDir, number), "PNG frame", write); !s) return s;
  }
  if (inMovie(number))
    if (Status s = movie_->write(image_); !s) return s;
  return Status::ok();
}

MovieTiming movieTiming(double requestedFps, double dt, int frameEvery) {
  MovieTiming t;
  const double frameTime = dt * std::max(frameEvery, 1);  // scene seconds between frames
  if (requestedFps > 0 || !(frameTime > 0) || !std::isfinite(frameTime)) {
    t.realTime = false;
    t.fps = requestedFps > 0 ? requestedFps : 30;
    t.speed = frameTime > 0 && std::isfinite(frameTime) ? frameTime * t.fps : 1;
    return t;
  }
  const double rate = 1.0 / frameTime;
  if (rate < kMinRealTimeFps) {  // e.g. dt = 10 s: a frame per 10 s would be a slide show
    t.realTime = false;
    t.fps = kMinRealTimeFps;
    t.speed = frameTime * t.fps;
    return t;
  }
  // The smallest k with rate / k <= the cap (a hair of slack: 1 / (0.01 * 1) is not exactly 100).
  const double every = std::ceil(rate / kMaxRealTimeFps * (1 - 1e-12));
  t.speed = 1;
  // Beyond 1e18 steps a frame (dt = 1e-30: 1.7e28), converting to long was undefined: it came out
  // as 1, and ffmpeg was asked for 1e+30 fps and refused. No run takes that many steps, so the
  // movie is its first frame alone, at the cap's rate; `every` times frameEvery still fits a long.
  const long sequenceEvery = std::max(frameEvery, 1);
  if (!(every * static_cast<double>(sequenceEvery) < 1e18)) {
    t.every = std::numeric_limits<long>::max() / sequenceEvery;
    t.fps = kMaxRealTimeFps;
    return t;
  }
  t.every = std::max(1L, static_cast<long>(every));
  t.fps = rate / static_cast<double>(t.every);
  return t;
}

Status RasterFrames::finish() { return movie_ ? movie_->close() : Status::ok(); }

}  // namespace fosssim::render
