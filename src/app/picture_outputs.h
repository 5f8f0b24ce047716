// The run observer that forwards run events to the picture outputs (SVG, PNG, movie), shared by
// both frontends.
#pragma once

#include "run_observer.h"

#include "fosssim/render/frame_outputs.h"

namespace fosssim::app {

class PictureOutputs final : public RunObserver {
 public:
  explicit PictureOutputs(render::FrameOutputs outputs) : outputs_(std::move(outputs)) {}
  Status start(const SceneFile& file, const State& initial, const RecordLayout&) override {
    outputs_.start(file, initial);
    return Status::ok();
  }
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog&) override {
    return outputs_.afterStep(file, state);
  }
  Status finish() override { return outputs_.finish(); }

 private:
  render::FrameOutputs outputs_;
};

}  // namespace fosssim::app
