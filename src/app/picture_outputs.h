// The run observer that forwards run events to the picture outputs (SVG, PNG, movie), shared by
// both frontends. The movie is written under its partial name and renamed when the run completes
// (output_files.h); frames are whole files each and keep their names.
#pragma once

#include "output_files.h"
#include "run_observer.h"

#include "fosssim/render/frame_outputs.h"

#include <optional>
#include <vector>

namespace fosssim::app {

class PictureOutputs final : public RunObserver {
 public:
  /// `places`: where each kind of frame goes, for the summary ("SVG frames in \"dir\"");
  /// `movie`: the --movie file, when there is one.
  explicit PictureOutputs(render::FrameOutputs outputs, std::vector<std::string> places = {},
                          std::optional<StagedFile> movie = std::nullopt)
      : outputs_(std::move(outputs)), places_(std::move(places)), movie_(std::move(movie)) {}
  Status start(const SceneFile& file, const State& initial, const RecordLayout&) override {
    return outputs_.start(file, initial);
  }
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog&) override {
    return outputs_.afterStep(file, state);
  }
  void ending(RunEnd end) override { end_ = end; }
  Status finish() override {
    Status finished = outputs_.finish();  // ffmpeg has written the whole movie when this returns
    if (finished && movie_ && end_ == RunEnd::Completed) return movie_->commit();
    return finished;
  }
  std::string written() const override {
    if (outputs_.frames() == 0 && !movie_) return "";
    std::string line = "frames 1 to " + std::to_string(outputs_.frames()) + ":";
    for (const std::string& place : places_) line += " " + place + ";";
    if (movie_) line += " the movie is in " + movie_->whereIncomplete();
    else line.pop_back();
    return line;
  }

 private:
  render::FrameOutputs outputs_;
  std::vector<std::string> places_;
  std::optional<StagedFile> movie_;
  RunEnd end_ = RunEnd::Failed;
};

}  // namespace fosssim::app
