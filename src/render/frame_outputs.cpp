#include "fosssim/render/frame_outputs.h"

#include "fosssim/io/staged_file.h"
#include "fosssim/render/svg_writer.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace fosssim::render {

FrameSequence::FrameSequence(int width, int height, int every) : every_(std::max(every, 1)) {
  view_.width = width;
  view_.height = height;
}

void FrameSequence::start(const SceneFile& file, const State& initial) {
  camera_.start(file, initial, view_.width, view_.height);
  view_.camera = camera_.camera();
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

Picture FrameSequence::picture(const SceneFile& file, const State& state) {
  view_.camera = camera_.update(file.scene, state, view_.width, view_.height);
  return makePicture(file, state, trails_, view_);
}

Picture FrameSequence::initialPicture(const SceneFile& file, const State& initial) const {
  return makePicture(file, initial, trails_, view_);
}

Status createDirectory(const std::string& dir, const std::string& what) {
  if (dir.empty()) return Status::ok();  // the current directory
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Status::error("cannot create the folder \"" + dir + "\" for " + what + ": " + ec.message());
  if (!std::filesystem::is_directory(dir, ec))
    return Status::error("\"" + dir + "\" exists and is not a folder: it cannot hold " + what);
  return Status::ok();
}

Status SvgFrames::open(const std::string& dir, std::unique_ptr<SvgFrames>& out) {
  if (Status s = createDirectory(dir, "the SVG frames"); !s) return s;
  out.reset(new SvgFrames(dir));
  return Status::ok();
}

// Under the frame's partial name, then renamed: a viewer or script that takes each frame as it
// appears never reads one half written, and a frame that fails (a full disk) leaves an earlier
// run's frame of that number as it was.
Status SvgFrames::frame(const Picture& picture, long number) {
  return io::writeStaged(svgFrameName(dir_, number), "SVG frame",
                         [&](const std::string& to) { return writeSvg(to, picture); });
}

Status FrameOutputs::start(const SceneFile& file, const State& initial) {
  sequence_.start(file, initial);
  written_ = 0;
  if (sinks_.empty()) return Status::ok();
  const Picture picture = sequence_.initialPicture(file, initial);
  for (auto& sink : sinks_)
    if (Status s = sink->start(file, picture); !s) return s;
  return Status::ok();
}

Status FrameOutputs::afterStep(const SceneFile& file, const State& state) {
  if (!sequence_.advance(state) || sinks_.empty()) return Status::ok();
  const long number = sequence_.frameNumber();
  if (std::none_of(sinks_.begin(), sinks_.end(), [&](const auto& sink) { return sink->wants(number); })) {
    written_ = number;
    return Status::ok();
  }
  const Picture picture = sequence_.picture(file, state);
  for (auto& sink : sinks_)
    if (sink->wants(number))
      if (Status s = sink->frame(picture, number); !s) return s;
  written_ = number;
  return Status::ok();
}

Status FrameOutputs::finish() {
  Status first = Status::ok();
  for (auto& sink : sinks_) {
    Status s = sink->finish();
    if (first && !s) first = s;
  }
  return first;
}

}  // namespace fosssim::render
