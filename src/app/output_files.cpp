#include "output_files.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <filesystem>
#include <sys/stat.h>
#include <vector>

namespace fosssim::app {
namespace {

namespace fs = std::filesystem;

struct Input {
  std::string option, path;
  dev_t device;
  ino_t inode;
};

/// The inputs that exist (the loader reports the others).
std::vector<Input> inputsOf(const Options& options) {
  std::vector<Input> inputs;
  for (const auto& [option, path] : {std::pair<std::string, std::string>{"-s", options.scene}, {"-i", options.input}}) {
    struct stat st {};
    if (!path.empty() && stat(path.c_str(), &st) == 0) inputs.push_back({option, path, st.st_dev, st.st_ino});
  }
  return inputs;
}

/// Follows symbolic links: a link to an input is that input. What io::unwritableOutput refuses
/// is refused (a named pipe that nothing reads, a socket, a block device); a pipe that a process
/// reads (-o /dev/stdout piped into gzip, -o >(gzip > t.gz)) and character devices (/dev/null)
/// are written.
Status checkOne(const std::string& option, const std::string& output, const std::string& role,
                const std::vector<Input>& inputs) {
  struct stat st {};
  if (stat(output.c_str(), &st) != 0) return Status::ok();  // does not exist (yet): not an input
  static std::vector<int> probes;  // the pipes' probes, kept open until the process ends (see there)
  int probe = -1;
  const char* kind = io::unwritableOutput(output, probe);
  if (probe >= 0) probes.push_back(probe);
  if (kind)
    return Status::error(option + " \"" + output + "\": cannot write " + (role.empty() ? "the output " : role) +
                         "(it is " + kind + ", not a file): choose a file name");
  for (const Input& in : inputs)
    if (st.st_dev == in.device && st.st_ino == in.inode)
      return Status::error(option + " \"" + output + "\"" + (role.empty() ? " " : ": " + role) +
                           "is the same file as the " + (in.option == "-s" ? "scene file" : "trajectory file") +
                           " given to " + in.option + " (\"" + in.path +
                           "\"): FOSSSim never writes over its input; choose another output name");
  return Status::ok();
}

/// "frame" + digits + ending: the names -m and -g write.
bool isFrameName(const std::string& name, const std::string& ending) {
  if (name.size() <= 5 + ending.size() || name.compare(0, 5, "frame") != 0 ||
      name.compare(name.size() - ending.size(), ending.size(), ending) != 0)
    return false;
  for (std::size_t k = 5; k < name.size() - ending.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(name[k]))) return false;
  return true;
}

/// The frame whose partial name `name` is ("frame12.partial.png" -> "frame12.png"), or "" if it is
/// none: each frame is written to "frame" + digits + ".partial" + ending and renamed once whole
/// (io::writeStaged), and a file left there (by a run killed mid-frame) is removed first.
std::string frameOfPartial(const std::string& name, const std::string& ending) {
  const std::string partial = ".partial" + ending;
  if (name.size() <= partial.size() || name.compare(name.size() - partial.size(), partial.size(), partial) != 0)
    return std::string();
  std::string frame = name.substr(0, name.size() - partial.size()) + ending;
  return isFrameName(frame, ending) ? frame : std::string();
}

bool isFramePartialName(const std::string& name, const std::string& ending) {
  return !frameOfPartial(name, ending).empty();
}

/// The frames a run writes into `dir`, and their partial names, may already exist there: none of
/// them may be an input.
Status checkFrames(const std::string& option, const std::string& dir, const std::string& ending,
                   const std::vector<Input>& inputs) {
  DIR* d = opendir(dir.empty() ? "." : dir.c_str());
  if (!d) return Status::ok();  // created later, or the frame writer reports why it cannot
  Status result = Status::ok();
  while (const dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    const bool frame = isFrameName(name, ending);
    if (!frame && !isFramePartialName(name, ending)) continue;
    result = checkOne(option, (dir.empty() ? "" : dir + "/") + name,
                      frame ? "the frame file " : "the partial file of a frame (written there, then renamed) ", inputs);
    if (!result) break;
  }
  closedir(d);
  return result;
}

/// A file the run writes: -o and --movie under their final and partial names, --stats.
struct Written {
  std::string option, path;
  bool partial;  ///< the partial name of option's output (where it is written until the run completes)
};

std::vector<Written> writtenFiles(const Options& options) {
  std::vector<Written> files;
  for (const auto& [option, path] :
       {std::pair<std::string, std::string>{"-o", options.output}, {"--movie", options.movie}}) {
    if (path.empty()) continue;
    files.push_back({option, path, false});
    std::string renameTo;
    if (const std::string writePath = io::stagedPaths(path, renameTo); writePath != renameTo)
      files.push_back({option, writePath, true});
  }
  if (!options.stats.empty()) files.push_back({"--stats", options.stats, false});
  return files;
}

std::string describe(const Written& w, const Options& options) {
  if (!w.partial) return w.option + " \"" + w.path + "\"";
  return "the partial file \"" + w.path + "\" of " + w.option +
         " (written there until the run completes, then renamed to \"" +
         (w.option == "-o" ? options.output : options.movie) + "\")";
}

/// Two names of one file that both outputs would write: an existing regular file under any
/// name or link (device and inode), or a file still to be made under the same canonical path.
/// Devices and named pipes are written directly and destroy nothing (-o /dev/null --stats
/// /dev/null is a run that keeps nothing, as asked).
bool sameWrittenFile(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  const bool hasA = stat(a.c_str(), &sa) == 0, hasB = stat(b.c_str(), &sb) == 0;
  if (hasA && hasB) return S_ISREG(sa.st_mode) && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  if (hasA || hasB) return false;
  std::error_code e1, e2;
  const fs::path ca = fs::weakly_canonical(a, e1), cb = fs::weakly_canonical(b, e2);
  return !e1 && !e2 && ca == cb;
}

/// One place, whether it exists or not: the same canonical path (symbolic links followed).
bool samePlace(const std::string& a, const std::string& b) {
  std::error_code e1, e2;
  fs::path ca = fs::weakly_canonical(a, e1), cb = fs::weakly_canonical(b, e2);
  if (!ca.has_filename()) ca = ca.parent_path();  // "svg/" is the folder "svg"
  if (!cb.has_filename()) cb = cb.parent_path();
  return !e1 && !e2 && ca == cb;
}

/// True when `path` is one of the frames -m or -g writes into `dir` (ending ".svg" or ".png"), or
/// a frame's partial name there.
bool isFrameOf(const std::string& path, const std::string& dir, const std::string& ending) {
  const fs::path p(path);
  const std::string name = p.filename().string();
  if (!isFrameName(name, ending) && !isFramePartialName(name, ending)) return false;
  std::error_code e1, e2;
  const fs::path parent = fs::weakly_canonical(p.parent_path().empty() ? fs::path(".") : p.parent_path(), e1);
  const fs::path frames = fs::weakly_canonical(dir.empty() ? fs::path(".") : fs::path(dir), e2);
  return !e1 && !e2 && parent == frames;
}

/// No output may be written over by another: the stats written into the trajectory, or a
/// trajectory renamed over the stats, would lose one of them without a word.
Status checkOutputsAgainstEachOther(const Options& options) {
  const std::vector<Written> files = writtenFiles(options);
  for (size_t a = 0; a < files.size(); ++a)
    for (size_t b = a + 1; b < files.size(); ++b)
      if (files[a].option != files[b].option && sameWrittenFile(files[a].path, files[b].path))
        return Status::error(describe(files[b], options) + " and " + describe(files[a], options) +
                             " are the same file: give each output its own name");
  for (const Written& w : files) {
    // A file where -m or -g makes its folder: the folder was made first and the file's open then
    // failed ("Is a directory"), leaving an empty folder under the output's name.
    for (const auto& [folderOption, folder] : {std::pair<std::string, std::string>{"-m", options.svgDir},
                                               {"--png-dir", options.pngs ? options.pngDir : std::string()}})
      if (!folder.empty() && samePlace(w.path, folder))
        return Status::error(describe(w, options) + " is the folder that " + folderOption +
                             " writes its frames into (\"" + folder + "\"): give each output its own name");
    const bool svg = !options.svgDir.empty() && isFrameOf(w.path, options.svgDir, ".svg");
    const bool png = options.pngs && isFrameOf(w.path, options.pngDir, ".png");
    if (svg || png) {
      const bool partial = isFramePartialName(fs::path(w.path).filename().string(), svg ? ".svg" : ".png");
      return Status::error(describe(w, options) +
                           (partial ? " is the partial file of a frame, which " : " is a frame file that ") +
                           (svg ? "-m" : "-g") + (partial ? " writes before renaming it" : " writes") +
                           ": give each output its own name");
    }
  }
  return Status::ok();
}

}  // namespace

Status checkOutputsAgainstInputs(const Options& options) {
  const std::vector<Input> inputs = inputsOf(options);
  for (const auto& [option, path] :
       {std::pair<std::string, std::string>{"-o", options.output}, {"--movie", options.movie}}) {
    if (path.empty()) continue;
    if (Status s = checkOne(option, path, "", inputs); !s) return s;
    std::string renameTo;
    const std::string writePath = io::stagedPaths(path, renameTo);
    if (writePath != renameTo)
      if (Status s = checkOne(option, writePath, "its partial file \"" + writePath + "\" ", inputs); !s) return s;
  }
  if (!options.svgDir.empty())
    if (Status s = checkFrames("-m", options.svgDir, ".svg", inputs); !s) return s;
  if (options.pngs)
    if (Status s = checkFrames("--png-dir", options.pngDir, ".png", inputs); !s) return s;
  if (!options.stats.empty())
    if (Status s = checkOne("--stats", options.stats, "", inputs); !s) return s;
  return checkOutputsAgainstEachOther(options);
}

std::vector<std::string> earlierFrameWarnings(const Options& options, long frames) {
  std::vector<std::string> warnings;
  const std::vector<std::pair<std::string, std::string>> folders = {
      {"-m", options.svgDir}, {"-g 1", options.pngs ? options.pngDir : std::string()}};
  for (const auto& folder : folders) {
    // Named, not structured bindings: C++17 lambdas cannot capture those (clang refuses).
    const std::string &option = folder.first, &dir = folder.second;
    if (dir.empty()) continue;
    DIR* d = opendir(dir.c_str());
    if (!d) continue;  // made by the run
    const std::string ending = option == "-m" ? ".svg" : ".png";
    auto number = [&](const std::string& frame) {  // the digits without leading zeros, compared as numbers
      const std::string digits = frame.substr(5, frame.size() - 5 - ending.size());
      const size_t from = digits.find_first_not_of('0');
      return from == std::string::npos ? std::string() : digits.substr(from);
    };
    auto less = [&](const std::string& a, const std::string& b) {
      const std::string x = number(a), y = number(b);
      return x.size() != y.size() ? x.size() < y.size() : x < y;
    };
    // Files beyond this run's frames: frames, and the partial files of frames that a run stopped
    // mid-frame (SIGKILL, power loss) left. A run removes the partial file of each frame it writes,
    // so one beyond its frames would stay, unseen among the frames, for ever.
    struct Beyond {
      long count = 0;
      std::string first, last;  // by frame number, as the file names read
    } beyondFrames, beyondPartials;
    auto frameOf = [&](const std::string& file) {  // a partial file's frame name; a frame's own
      std::string frame = frameOfPartial(file, ending);
      return frame.empty() ? file : frame;
    };
    const std::string limit = std::to_string(frames);
    while (const dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      const bool partial = isFramePartialName(name, ending);
      if (!partial && !isFrameName(name, ending)) continue;
      const std::string n = number(frameOf(name));
      if (n.size() < limit.size() || (n.size() == limit.size() && n <= limit)) continue;  // this run writes it
      Beyond& b = partial ? beyondPartials : beyondFrames;
      ++b.count;
      if (b.first.empty() || less(frameOf(name), frameOf(b.first))) b.first = name;
      if (b.last.empty() || less(frameOf(b.last), frameOf(name))) b.last = name;
    }
    closedir(d);
    auto found = [&](const Beyond& b, const std::string& what, const std::string& frameWord) {
      return option + ": \"" + dir + "\" holds " + std::to_string(b.count) + " " + what + (b.count == 1 ? "" : "s") +
             " of an earlier run beyond this run's " + std::to_string(frames) + frameWord + " (" + b.first +
             (b.count == 1 ? "" : " to " + b.last) + ")";
    };
    if (beyondFrames.count > 0)
      warnings.push_back(found(beyondFrames, "frame", "") +
                         "; they are left as they are, and the folder mixes the runs");
    if (beyondPartials.count > 0)
      warnings.push_back(found(beyondPartials, "partial file", " frames") +
                         (beyondPartials.count == 1
                              ? ": a run stopped while writing that frame left it; it is not a frame, and no run of "
                                "fewer frames removes it"
                              : ": runs stopped while writing those frames left them; they are not frames, and no run "
                                "of fewer frames removes them"));
  }
  return warnings;
}

Status checkFrameEvery(const Options& options, long steps) {
  const bool frames = options.pngs || !options.svgDir.empty() || !options.movie.empty();
  if (!frames || options.frameEvery <= steps) return Status::ok();
  const std::string k = std::to_string(options.frameEvery);
  return Status::error("--frame-every " + k + " writes a frame after steps " + k + ", " +
                       std::to_string(2L * options.frameEvery) + ", ..., and the scene runs " + std::to_string(steps) +
                       " step" + (steps == 1 ? "" : "s") +
                       ": -g 1, -m and --movie would write no frame (give at most " + "--frame-every " +
                       std::to_string(std::max(steps, 1L)) + ")");
}

Status checkGradedFile(const Options& options) {
  struct stat scene {}, graded {};
  if (options.input.empty() || stat(options.scene.c_str(), &scene) != 0 || stat(options.input.c_str(), &graded) != 0)
    return Status::ok();  // the loader and the reader report a missing file
  if (scene.st_dev == graded.st_dev && scene.st_ino == graded.st_ino)
    return Status::error("-i \"" + options.input + "\" is the scene file given to -s (\"" + options.scene +
                         "\"): -i grades a trajectory file written with -o, not the scene");
  return Status::ok();
}

}  // namespace fosssim::app
