// ffmpeg as a child process fed through a pipe. posix_spawn with an argument vector, not popen:
// no shell; and the output is named with "file:" and its absolute path, so any name is a file to
// ffmpeg (one beginning with '-' or holding ':' included).
#include "fosssim/render/movie_writer.h"

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace fosssim::render {
namespace {

bool endsWith(const std::string& s, const std::string& tail) {
  if (s.size() < tail.size()) return false;
  for (std::size_t k = 0; k < tail.size(); ++k)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - tail.size() + k])) != tail[k]) return false;
  return true;
}

/// Writes all of `data` to a pipe without letting SIGPIPE kill the process when the reader has
/// died: SIGPIPE is blocked for this thread only during the write and a pending one is consumed,
/// so the process-wide disposition stays untouched and EPIPE becomes an error message.
bool writeAll(int fd, const std::uint8_t* data, std::size_t size, int& error) {
  sigset_t pipeSet, oldSet;
  sigemptyset(&pipeSet);
  sigaddset(&pipeSet, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipeSet, &oldSet);
  bool ok = true;
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      error = errno;
      ok = false;
      break;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  if (!ok && error == EPIPE) {
    const timespec zero{0, 0};
    sigtimedwait(&pipeSet, nullptr, &zero);
  }
  pthread_sigmask(SIG_SETMASK, &oldSet, nullptr);
  return ok;
}

/// How ffmpeg must be given the output: it reads a name beginning with '-' as an option and
/// "name:rest" as a protocol, whatever follows. "file:" and an absolute path is always the file
/// itself (the format is still chosen by the name's ending).
std::string ffmpegFileName(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  return "file:" + (ec ? path : absolute.string());
}

}  // namespace

std::string findOnPath(const std::string& program) {
  if (program.find('/') != std::string::npos) return access(program.c_str(), X_OK) == 0 ? program : "";
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    std::size_t end = dirs.find(':', begin);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > begin ? dirs.substr(begin, end - begin) : ".";
    const std::string candidate = dir + "/" + program;
    struct stat st {};
    if (stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(candidate.c_str(), X_OK) == 0)
      return candidate;
    begin = end + 1;
  }
  return "";
}

MovieWriter::MovieWriter(std::string path, int fd, pid_t pid, int width, int height)
    : path_(std::move(path)), fd_(fd), pid_(pid), width_(width), height_(height) {}

MovieWriter::~MovieWriter() {
  if (fd_ >= 0 || pid_ > 0) (void)close();
}

Status MovieWriter::open(const std::string& path, int width, int height, double fps,
                         std::unique_ptr<MovieWriter>& out) {
  if (!isMovieName(path))
    return Status::error("the movie \"" + path + "\": a movie's name ends in " + movieEndings() +
                         " (ffmpeg writes others as pictures or not at all)");
  const std::string ffmpeg = findOnPath("ffmpeg");
  if (ffmpeg.empty())
    return Status::error("writing the movie \"" + path + "\" needs ffmpeg, which is not on PATH: install it "
                         "(scripts/setup does, or apt-get install ffmpeg)");
  if (!(fps > 0)) return Status::error("the movie \"" + path + "\": the frame rate must be positive");
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  char rate[32];
  std::snprintf(rate, sizeof rate, "%g", fps);
  // -xerror: without it ffmpeg exits 0 after "Error writing trailer" (a full disk as the movie
  // ends), leaving an unplayable file that the run would have renamed to the final name.
  std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-nostdin", "-xerror", "-y",
                                   "-f", "rawvideo", "-pixel_format", "rgb24", "-video_size", size,
                                   "-framerate", rate, "-i", "pipe:0", "-an"};
  if (endsWith(path, ".mp4") || endsWith(path, ".mov") || endsWith(path, ".mkv")) {
    // H.264 in yuv420p plays in browsers and phones; it needs even sizes, hence the pad.
    for (const char* a : {"-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-pix_fmt", "yuv420p", "-vf",
                          "pad=ceil(iw/2)*2:ceil(ih/2)*2"})
      args.emplace_back(a);
    if (!endsWith(path, ".mkv")) args.insert(args.end(), {"-movflags", "+faststart"});
  }
  args.push_back(ffmpegFileName(path));
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  int pipeFds[2];
  if (pipe(pipeFds) != 0)
    return Status::error("the movie \"" + path + "\": cannot create a pipe to ffmpeg: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipeFds[0], STDIN_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipeFds[0]);
  posix_spawn_file_actions_addclose(&actions, pipeFds[1]);
  // A process group of its own: Ctrl-C in a terminal reaches FOSSSim only, which then finishes
  // its step and closes the pipe, so ffmpeg ends the movie properly instead of dying with it.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, ffmpeg.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipeFds[0]);
  if (rc != 0) {
    ::close(pipeFds[1]);
    return Status::error("the movie \"" + path + "\": cannot start " + ffmpeg + ": " + std::strerror(rc));
  }
  out.reset(new MovieWriter(path, pipeFds[1], pid, width, height));
  return Status::ok();
}

Status MovieWriter::write(const Image& frame) {
  if (fd_ < 0) return Status::error("the movie \"" + path_ + "\" is already closed");
  if (frame.width != width_ || frame.height != height_)
    return Status::error("the movie \"" + path_ + "\": a " + std::to_string(frame.width) + "x" +
                         std::to_string(frame.height) + " frame in a " + std::to_string(width_) + "x" +
                         std::to_string(height_) + " movie");
  int error = 0;
  if (!writeAll(fd_, frame.rgb.data(), frame.rgb.size(), error)) {
    Status closed = close();
    std::string why = error == EPIPE ? "ffmpeg stopped reading" : std::strerror(error);
    if (!closed) why += " (" + closed.message() + ")";
    return Status::error("cannot write frame " + std::to_string(frames_ + 1) + " of the movie \"" + path_ + "\": " +
                         why);
  }
  ++frames_;
  return Status::ok();
}

Status MovieWriter::close() {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (pid_ <= 0) return Status::ok();
  int status = 0;
  pid_t r;
  do r = waitpid(pid_, &status, 0);
  while (r < 0 && errno == EINTR);
  pid_ = -1;
  if (r < 0)
    return Status::error("the movie \"" + path_ + "\": lost the ffmpeg process: " + std::string(std::strerror(errno)));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return Status::ok();
  if (WIFEXITED(status))
    return Status::error("ffmpeg failed writing the movie \"" + path_ + "\" (exit status " +
                         std::to_string(WEXITSTATUS(status)) + "; its message is above)");
  return Status::error("ffmpeg was killed by signal " + std::to_string(WTERMSIG(status)) +
                       " while writing the movie \"" + path_ + "\"");
}

}  // namespace fosssim::render
