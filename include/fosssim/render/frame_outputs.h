// Per-step picture outputs (-m SVG, -g PNG, --movie) behind one interface, so that the command
// line's front ends only forward run events: which steps get a frame and what each frame shows
// is decided here once, for every output alike.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/render/picture.h"

#include <memory>
#include <string>
#include <vector>

namespace fosssim::render {

/// Which steps get a frame, how frames are numbered, the camera and the path trails: the
/// bookkeeping every per-step picture output shares.
class FrameSequence {
 public:
  /// Pictures of width x height pixels, one after every `every`-th step (steps every, 2*every,
  /// ...), numbered 1, 2, 3, ... in that order.
  FrameSequence(int width, int height, int every);

  /// Resets for a run starting at `initial`: the camera is the scene's viewport, or fits the
  /// initial particles and then follows them (FollowCamera: it only grows, smoothly, and keeps
  /// every particle in view); trails start empty but for the initial positions.
  void start(const SceneFile& file, const State& initial);

  /// Call after every step: records the trails; true when this step gets a frame.
  bool advance(const State& state);

  /// The number of the frame that the last advance() returning true asked for (from 1).
  long frameNumber() const { return frames_; }

  /// The picture of `state` (call in time order: the camera follows the states it is shown).
  Picture picture(const SceneFile& file, const State& state);
  /// The picture of the initial state given to start() (t = 0), with the starting camera.
  Picture initialPicture(const SceneFile& file, const State& initial) const;
  const View& view() const { return view_; }

 private:
  View view_;
  FollowCamera camera_;
  int every_;
  long steps_ = 0;
  long frames_ = 0;
  PathTrails trails_;
};

/// Receives the pictures of the frames that are due.
class PictureSink {
 public:
  virtual ~PictureSink() = default;
  /// Before the first step, with the picture of the initial state (t = 0). The reference's
  /// per-step outputs (-g, -m) number their frames from the first step and leave it out; a
  /// movie opens with it.
  virtual Status start(const SceneFile&, const Picture&) { return Status::ok(); }
  /// Whether frame `number` is wanted: a sink that keeps only some frames (a movie at a lower
  /// rate than the frames) spares the drawing of the others.
  virtual bool wants(long) const { return true; }
  /// Frame `number` (1, 2, ...) shows `picture`.
  virtual Status frame(const Picture& picture, long number) = 0;
  /// After the last frame (also after a failure, to release resources).
  virtual Status finish() { return Status::ok(); }
};

/// -m: one SVG file per frame, dir/frame%020d.svg.
class SvgFrames final : public PictureSink {
 public:
  /// Creates `dir` (and its parents) when it does not exist.
  static Status open(const std::string& dir, std::unique_ptr<SvgFrames>& out);
  Status frame(const Picture& picture, long number) override;

 private:
  explicit SvgFrames(std::string dir) : dir_(std::move(dir)) {}
  std::string dir_;
};

/// A FrameSequence feeding any number of sinks.
class FrameOutputs {
 public:
  /// Frames of width x height pixels after every `every`-th step.
  FrameOutputs(int width, int height, int every) : sequence_(width, height, every) {}
  void add(std::unique_ptr<PictureSink> sink) { sinks_.push_back(std::move(sink)); }
  bool empty() const { return sinks_.empty(); }

  /// Starts the sequence and hands every sink the picture of the initial state.
  Status start(const SceneFile& file, const State& initial);
  /// Call after every step; builds the picture once and hands it to every sink when due.
  Status afterStep(const SceneFile& file, const State& state);
  /// Finishes every sink; the first failure is returned.
  Status finish();
  /// The frames every sink has written, or left out by choice, so far: 1 to frames(). A frame a
  /// sink failed to write is not counted, nor are those after it.
  long frames() const { return written_; }

 private:
  FrameSequence sequence_;
  std::vector<std::unique_ptr<PictureSink>> sinks_;
  long written_ = 0;
};

/// Creates `dir` and its parents if needed; `what` names what the folder is for in the message
/// (e.g. "the PNG frames").
Status createDirectory(const std::string& dir, const std::string& what);

}  // namespace fosssim::render
