#include "output_files.h"

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

/// Follows symbolic links: a link to an input is that input.
Status checkOne(const std::string& option, const std::string& output, const std::string& role,
                const std::vector<Input>& inputs) {
  struct stat st {};
  if (stat(output.c_str(), &st) != 0) return Status::ok();  // does not exist (yet): not an input
  for (const Input& in : inputs)
    if (st.st_dev == in.device && st.st_ino == in.inode)
      return Status::error(option + " \"" + output + "\"" + (role.empty() ? " " : ": " + role) + "is the same file as the " +
                           (in.option == "-s" ? "scene file" : "trajectory file") + " given to " + in.option + " (\"" +
                           in.path + "\"): FOSSSim never writes over its input; choose another output name");
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

/// The frames a run writes into `dir` may already exist there: none of them may be an input.
Status checkFrames(const std::string& option, const std::string& dir, const std::string& ending,
                   const std::vector<Input>& inputs) {
  DIR* d = opendir(dir.empty() ? "." : dir.c_str());
  if (!d) return Status::ok();  // created later, or the frame writer reports why it cannot
  Status result = Status::ok();
  while (const dirent* e = readdir(d)) {
    const std::string name = e->d_name;
    if (!isFrameName(name, ending)) continue;
    result = checkOne(option, (dir.empty() ? "" : dir + "/") + name, "the frame file ", inputs);
    if (!result) break;
  }
  closedir(d);
  return result;
}

}  // namespace

std::string partialName(const std::string& path) {
  const fs::path p(path);
  const std::string stem = p.stem().string(), ending = p.extension().string();
  return fs::path(p).replace_filename(stem + ".partial" + ending).string();
}

Status checkOutputsAgainstInputs(const Options& options) {
  const std::vector<Input> inputs = inputsOf(options);
  for (const auto& [option, path] : {std::pair<std::string, std::string>{"-o", options.output}, {"--movie", options.movie}}) {
    if (path.empty()) continue;
    if (Status s = checkOne(option, path, "", inputs); !s) return s;
    if (Status s = checkOne(option, partialName(path), "its partial file \"" + partialName(path) + "\" ", inputs); !s)
      return s;
  }
  if (!options.svgDir.empty())
    if (Status s = checkFrames("-m", options.svgDir, ".svg", inputs); !s) return s;
  if (options.pngs)
    if (Status s = checkFrames("--png-dir", options.pngDir, ".png", inputs); !s) return s;
  if (!options.output.empty() && !options.movie.empty()) {
    std::error_code e1, e2;
    const fs::path a = fs::weakly_canonical(options.output, e1), b = fs::weakly_canonical(options.movie, e2);
    if (!e1 && !e2 && a == b)
      return Status::error("-o and --movie name the same file (\"" + options.output + "\"): give each its own");
  }
  return Status::ok();
}

Status StagedFile::prepare(const std::string& finalPath, const std::string& what, StagedFile& out) {
  out.finalPath_ = out.renameTo_ = out.writePath_ = finalPath;
  struct stat st {};
  if (stat(finalPath.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    // A device or a named pipe is written directly; a folder is refused by whoever opens it.
    return Status::ok();
  }
  struct stat link {};
  if (lstat(finalPath.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    std::error_code ec;
    const fs::path target = fs::canonical(finalPath, ec);  // fails for a dangling link: then the link is replaced
    if (!ec) out.renameTo_ = target.string();
  }
  out.writePath_ = partialName(out.renameTo_);
  // The partial name is ours: an old partial file (or a link there) goes, so that nothing is
  // written through it. checkOutputsAgainstInputs made sure it is no input.
  if (lstat(out.writePath_.c_str(), &link) == 0 && !S_ISDIR(link.st_mode) && std::remove(out.writePath_.c_str()) != 0)
    return Status::error(what + " \"" + finalPath + "\": cannot remove the old partial file \"" + out.writePath_ +
                         "\" (" + std::strerror(errno) + ")");
  return Status::ok();
}

Status StagedFile::commit() {
  if (!staged()) return Status::ok();
  struct stat old {};
  if (stat(renameTo_.c_str(), &old) == 0 && S_ISREG(old.st_mode)) (void)chmod(writePath_.c_str(), old.st_mode & 07777);
  if (std::rename(writePath_.c_str(), renameTo_.c_str()) != 0)
    return Status::error("\"" + finalPath_ + "\": cannot rename \"" + writePath_ + "\" to it (" + std::strerror(errno) +
                         "); the complete data is in \"" + writePath_ + "\"");
  return Status::ok();
}

std::string StagedFile::whereIncomplete() const {
  if (!staged()) return "\"" + finalPath_ + "\"";
  struct stat st {};
  const bool older = stat(renameTo_.c_str(), &st) == 0;
  return "\"" + writePath_ + "\" (\"" + finalPath_ + "\" was not written" +
         (older ? "; the older file of that name is as it was)" : ")");
}

}  // namespace fosssim::app
