// Output files that never destroy an input and never leave a half-written file under their name.
//
// - Every output (-o, --movie, --stats, the frames of -m and -g) is compared with the inputs (-s,
//   -i) by device and inode before anything is opened: the same file under another name, through
//   a symbolic or a hard link, is refused.
// - No output is another's file either: -o, --movie (final and partial names) and --stats differ
//   from each other and from the frames of -m and -g, else one would write over the other.
// - -o and --movie are written under a partial name next to the final one ("out.bin" is written
//   as "out.partial.bin", "run.mp4" as "run.partial.mp4": ffmpeg picks the format by the ending)
//   and renamed to the final name when the run completes (all steps, or the window closed by the
//   user). After an error or a signal the partial file stays, holding whole records (a movie
//   closed properly), and the final name is untouched: an older file of that name is left as it
//   was. A process killed outright (SIGKILL, power loss) leaves only the partial file
//   (io::StagedFile, which the Python module's writers share).
// - Each frame of -m and -g is written under its partial name ("frame00001.partial.png") and
//   renamed once whole (io::writeStaged): a viewer that takes frames as they appear never reads
//   one half written. The partial names are checked against the inputs and the other outputs as
//   the frames' own names are (a stale partial file is removed before a frame is written).
// - Character devices (-o /dev/null) are written directly: there is nothing to rename. Named pipes,
//   sockets and block devices are refused (a pipe without a reader would block the open forever).
#pragma once

#include "options.h"

#include "fosssim/core/status.h"
#include "fosssim/io/staged_file.h"

#include <string>
#include <vector>

namespace fosssim::app {

/// Fails (naming both) when an output of `options` is the same file as one of its inputs, or two
/// outputs would write one file (a final or partial name of -o or --movie, --stats, a frame).
Status checkOutputsAgainstInputs(const Options& options);

/// Warnings about frames already in the folders of -m and -g that a run of `frames` frames does
/// not write over (a longer earlier run's): left as they are, they would pass for this run's. And
/// about the partial files of frames beyond this run's (frameN.partial.svg, left by a run killed
/// while writing frame N): a run removes only the partial files of the frames it writes.
std::vector<std::string> earlierFrameWarnings(const Options& options, long frames);

/// Fails when --frame-every K asks for frames after steps K, 2K, ... and the run of `steps` steps
/// never reaches K: -g 1, -m and --movie would write no frame at all, without a word.
Status checkFrameEvery(const Options& options, long steps);

/// Fails when -i names the scene file itself (under any name or link): its XML was read as
/// records and graded, a "Failed" full of numbers made of text.
Status checkGradedFile(const Options& options);

}  // namespace fosssim::app
