// -g and --movie: frames drawn off-screen (OSMesa) once, then written as PNG files and/or piped
// into ffmpeg. The movie also shows the initial state (t = 0) first, and by default plays at the
// scene's own pace (real time).
#pragma once

#include "fosssim/render/frame_outputs.h"
#include "fosssim/render/image.h"
#include "fosssim/render/movie_writer.h"
#include "fosssim/render/offscreen_renderer.h"

namespace fosssim::render {

struct RasterSettings {
  int width = 512, height = 512;
  std::string pngDir;  ///< write dir/frame%05d.png (created if needed); empty: no PNG files
  double fps = 30;     ///< the movie's frame rate (the one its MovieWriter was opened with)
  long movieEvery = 1; ///< the movie keeps frames movieEvery, 2 movieEvery, ... of the sequence
  bool titleCard = false;  ///< the movie opens with titleCard() for kTitleSeconds
};

/// How long a movie's title card shows.
inline constexpr double kTitleSeconds = 2.0;
/// The highest frame rate a real-time movie gets: beyond it frames are left out.
inline constexpr double kMaxRealTimeFps = 60.0;
/// The lowest: a scene whose frames are further apart than a second plays faster than real time.
inline constexpr double kMinRealTimeFps = 1.0;

/// A movie's pace, decided from the command line and the scene.
struct MovieTiming {
  double fps = 30;      ///< frames per second of the movie
  long every = 1;       ///< the movie keeps every `every`-th frame of the sequence
  double speed = 1;     ///< scene seconds per movie second (1: real time)
  bool realTime = true; ///< the rate was chosen for real time (no --fps given)
};

/// `requestedFps` > 0 (--fps): that rate with every frame, at whatever speed that gives. 0: real
/// time, fps = 1 / (dt * frameEvery), except that above kMaxRealTimeFps only every k-th frame is
/// kept (the smallest k that brings the rate down to it), which stays real time, and below
/// kMinRealTimeFps the movie plays at that rate, faster than real time. Past 1e18 steps a frame
/// (dt = 1e-30) the movie is the first frame alone at kMaxRealTimeFps.
MovieTiming movieTiming(double requestedFps, double dt, int frameEvery);

class RasterFrames final : public PictureSink {
 public:
  /// Sets up the PNG folder and the off-screen renderer before the run starts, so that an
  /// unwritable folder or a missing OpenGL is reported before any step is taken.
  static Status open(const RasterSettings& settings, std::unique_ptr<RasterFrames>& out);
  /// The frames also go into `movie`, opened by the caller (MovieWriter::open, at the settings'
  /// size and fps), so that the caller can tell a failing movie from failing PNG frames.
  void setMovie(std::unique_ptr<MovieWriter> movie) { movie_ = std::move(movie); }
  /// The movie opens with the title card (when asked for) and the initial state.
  Status start(const SceneFile& file, const Picture& initial) override;
  bool wants(long number) const override;
  Status frame(const Picture& picture, long number) override;
  Status finish() override;

 private:
  RasterFrames() = default;
  bool inMovie(long number) const;
  RasterSettings settings_;
  std::unique_ptr<OffscreenRenderer> renderer_;
  std::unique_ptr<MovieWriter> movie_;
  Image image_;  // reused from frame to frame
};

}  // namespace fosssim::render
