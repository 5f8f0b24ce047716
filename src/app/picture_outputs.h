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
                          std::optional<io::StagedFile> movie = std::nullopt)
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
  /// Only what was written: the frames every output wrote (a frame that failed is not), and the
  /// movie only when its file exists (ffmpeg may have failed to create it).
  std::string written() const override {
    const long frames = outputs_.frames();
    std::vector<std::string> parts;
    if (frames > 0) parts = places_;
    const bool movieMade = movie_ && movie_->made();
    if (movieMade) parts.push_back("the movie is in " + movie_->whereIncomplete());
    std::string line = parts.empty() || frames == 0 ? "" : "frames 1 to " + std::to_string(frames) + ": ";
    for (size_t k = 0; k < parts.size(); ++k) line += (k ? "; " : "") + parts[k];
    if (movie_ && !movieMade)
      line += (line.empty() ? "" : "; ") + std::string("no movie was made (\"") + movie_->writePath() +
              "\" does not exist)";
    if (line.empty() && !places_.empty()) {
      line = "no frame was written (";
      for (size_t k = 0; k < places_.size(); ++k) line += (k ? "; " : "") + places_[k];
      line += ")";
    }
    return line;
  }

 private:
  render::FrameOutputs outputs_;
  std::vector<std::string> places_;
  std::optional<io::StagedFile> movie_;
  RunEnd end_ = RunEnd::Failed;
};

}  // namespace fosssim::app
