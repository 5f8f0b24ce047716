// FOSSSim started in the background, for the tests that act on a running process (signals, the
// size warning of a long run): its stderr goes to a file that the test can watch, and the
// process is killed and reaped when the guard goes, whatever the test did.
#pragma once

#include "run_fosssim.h"

#include "fosssim/io/trajectory.h"

#include <cmath>

namespace fosssim::testing {

class BackgroundRun {
 public:
  /// Starts FOSSSim with `args` in `dir` (stdin /dev/null, stdout and stderr to files there).
  BackgroundRun(const std::vector<std::string>& args, const std::string& dir,
                const std::vector<std::pair<std::string, std::string>>& env = {})
      : out_(dir + "/fosssim.out"), err_(dir + "/fosssim.err") {
    std::vector<std::string> strings = {FOSSSIM_EXECUTABLE};
    strings.insert(strings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : strings) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_ = fork();
    if (pid_ == 0) {
      const int in = open("/dev/null", O_RDONLY);
      const int out = open(out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
      const int err = open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
      if (in < 0 || out < 0 || err < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0) _exit(126);
      for (const auto& [name, value] : env) setenv(name.c_str(), value.c_str(), 1);
      execv(argv[0], argv.data());
      _exit(127);
    }
  }
  ~BackgroundRun() {
    if (pid_ > 0) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  BackgroundRun(const BackgroundRun&) = delete;
  BackgroundRun& operator=(const BackgroundRun&) = delete;

  bool started() const { return pid_ > 0; }
  void signal(int sig) const { kill(pid_, sig); }
  std::string err() const { return slurp(err_); }
  std::string out() const { return slurp(out_); }

  /// Polls `done` every 10 ms for up to `seconds`; false if it never held or the process ended.
  template <class Condition>
  bool waitFor(Condition&& done, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
      if (done()) return true;
      if (pid_ > 0 && waitpid(pid_, &status_, WNOHANG) == pid_) {
        pid_ = -1;
        ended_ = true;
        return done();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

  /// Waits up to `seconds` for the end; how it ended (timedOut if it did not, and then it is killed).
  Outcome finish(double seconds) {
    Outcome o;
    waitFor([] { return false; }, seconds);
    if (!ended_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status_, 0);
      pid_ = -1;
      o.timedOut = true;
    }
    o.exited = !o.timedOut && WIFEXITED(status_);
    o.code = o.exited ? WEXITSTATUS(status_) : -1;
    o.signal = !o.timedOut && WIFSIGNALED(status_) ? WTERMSIG(status_) : 0;
    o.out = out();
    o.err = err();
    return o;
  }

 private:
  std::string out_, err_;
  pid_t pid_ = -1;
  int status_ = 0;
  bool ended_ = false;
};

/// True when `program` is an executable file in a folder of PATH.
inline bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t begin = 0; begin <= dirs.size();) {
    std::size_t end = dirs.find(':', begin);
    if (end == std::string::npos) end = dirs.size();
    const std::string candidate = (end > begin ? dirs.substr(begin, end - begin) : ".") + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0) return true;
    begin = end + 1;
  }
  return false;
}

inline std::uintmax_t sizeOf(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  return ec ? 0 : size;
}

/// Reads a whole trajectory file as records of `n` particles with `layout`; fails the test at a
/// record that does not parse or holds a non-finite number. The number of records read.
inline long wholeFiniteRecords(const std::string& path, int n, RecordLayout layout) {
  std::unique_ptr<TrajectoryReader> reader;
  const Status opened = TrajectoryReader::open(path, n, layout, reader);
  EXPECT_TRUE(opened.isOk()) << opened.message();
  if (!opened) return -1;
  TrajectoryRecord record;
  for (long records = 0;; ++records) {
    bool atEnd = false;
    const Status s = reader->next(record, atEnd);
    EXPECT_TRUE(s.isOk()) << s.message();
    if (!s || atEnd) return s ? records : -1;
    bool finite = record.x.allFinite() && record.v.allFinite();
    for (const Impulse& im : record.log.impulses)
      finite = finite && std::isfinite(im.n.x()) && std::isfinite(im.n.y()) && std::isfinite(im.tau);
    for (int k = 0; k < record.log.polynomials.size(); ++k)
      for (int c = 0; c < record.log.polynomials.length(k); ++c)
        finite = finite && std::isfinite(record.log.polynomials.coefficients(k)[c]);
    EXPECT_TRUE(finite) << path << ": record " << records << " holds a non-finite number";
    if (!finite) return -1;
  }
}

/// The step after "after step " or "up to step " in `text`, or -1.
inline long stepAfter(const std::string& text, const std::string& prefix) {
  const std::size_t at = text.find(prefix);
  return at == std::string::npos ? -1 : std::atol(text.c_str() + at + prefix.size());
}

}  // namespace fosssim::testing
