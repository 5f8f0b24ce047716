#include "fosssim/render/frame_sequence.h"

#include <algorithm>

namespace fosssim::render {

FrameSequence::FrameSequence(int width, int height, int every) : every_(std::max(every, 1)) {
  view_.width = width;
  view_.height = height;
}

void FrameSequence::start(const SceneFile& file, const State& initial) {
  view_.camera = initialCamera(file.look, initial, view_.width, view_.height);
  trails_ = PathTrails(file.look.paths, file.scene.dt);
  trails_.record(initial);
  steps_ = 0;
  frames_ = 0;
}

bool FrameSequence::advance(const State& state) {
  trails_.record(state);
  if (++steps_ % every_ != 0) return false;
  ++frames_;
  return true;
}

Picture FrameSequence::picture(const SceneFile& file, const State& state) const {
  return makePicture(file, state, trails_, view_);
}

}  // namespace fosssim::render
