// The bookkeeping that every per-step picture output shares (-g PNG frames, --movie, -m SVG):
// which steps get a frame, how frames are numbered, the camera, and the path trails.
#pragma once

#include "fosssim/render/picture.h"

namespace fosssim::render {

class FrameSequence {
 public:
  /// Pictures of width x height pixels, one after every `every`-th step (steps every, 2*every,
  /// ...), numbered 1, 2, 3, ... in that order.
  FrameSequence(int width, int height, int every);

  /// Resets for a run starting at `initial`: the camera is the scene's viewport or fits the
  /// initial particles (and then stays put, so the picture does not jitter), trails start empty
  /// but for the initial positions.
  void start(const SceneFile& file, const State& initial);

  /// Call after every step: records the trails; true when this step gets a frame.
  bool advance(const State& state);

  /// The number of the frame that the last advance() returning true asked for (from 1).
  long frameNumber() const { return frames_; }

  Picture picture(const SceneFile& file, const State& state) const;
  const View& view() const { return view_; }

 private:
  View view_;
  int every_;
  long steps_ = 0;
  long frames_ = 0;
  PathTrails trails_;
};

}  // namespace fosssim::render
