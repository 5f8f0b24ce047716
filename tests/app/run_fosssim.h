// Runs the FOSSSim executable (FOSSSIM_EXECUTABLE) as a child process with a time limit, so that
// a hang fails the test instead of blocking ctest, and reports how it ended and what it printed.
#pragma once

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <grp.h>
#include <map>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fosssim::testing {

struct Outcome {
  bool exited = false;   ///< ended by exit() (not by a signal, not killed for the time limit)
  int code = -1;         ///< the exit status when exited
  int signal = 0;        ///< the signal that ended it, if any (e.g. SIGSEGV, SIGABRT, SIGFPE)
  bool timedOut = false;
  std::string out, err;  ///< stdout and stderr
};

inline std::ostream& operator<<(std::ostream& os, const Outcome& o) {
  os << (o.timedOut ? "timed out" : o.exited ? "exit " + std::to_string(o.code) : "signal " + std::to_string(o.signal))
     << "\n--- stdout ---\n" << o.out.substr(0, 4000) << "\n--- stderr ---\n" << o.err.substr(0, 4000);
  return os;
}

struct RunOptions {
  int timeoutSeconds = 120;
  bool asNobody = false;  ///< drop root privileges to uid/gid 65534 before running
  rlim_t addressSpace = 0;  ///< > 0: limit the child's address space to this many bytes (RLIMIT_AS)
  /// > 0: files the child writes end at this many bytes (RLIMIT_FSIZE, SIGXFSZ ignored): a write
  /// past it fails with EFBIG, as one fails with ENOSPC on a full disk, without mounting one.
  rlim_t fileSize = 0;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// A catalogue's EXPECTED file (tests/data/bad, tests/data/warnings): per line a file name, then
/// fragments its message must contain, tab-separated; '#' starts a comment line.
inline std::map<std::string, std::vector<std::string>> readExpectations(const std::string& dir) {
  std::map<std::string, std::vector<std::string>> table;
  std::ifstream in(dir + "/EXPECTED");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, '\t');) fields.push_back(f);
    table[fields.front()] = std::vector<std::string>(fields.begin() + 1, fields.end());
  }
  return table;
}

/// Runs FOSSSim with `args` (stdin from /dev/null).
inline Outcome runFosssim(const std::vector<std::string>& args, const RunOptions& options = {}) {
  const std::string base = std::filesystem::temp_directory_path() / ("fosssim-cli-" + std::to_string(getpid()));
  const std::string outPath = base + ".out", errPath = base + ".err";
  std::vector<std::string> argvStrings = {FOSSSIM_EXECUTABLE};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argvStrings) argv.push_back(a.data());
  argv.push_back(nullptr);

  const pid_t pid = fork();
  if (pid == 0) {
    const int in = open("/dev/null", O_RDONLY);
    const int out = open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    const int err = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (in < 0 || out < 0 || err < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0) _exit(126);
    const rlimit limit{options.addressSpace, options.addressSpace};
    if (options.addressSpace > 0 && setrlimit(RLIMIT_AS, &limit) != 0) _exit(126);
    const rlimit fileLimit{options.fileSize, options.fileSize};
    if (options.fileSize > 0 && (signal(SIGXFSZ, SIG_IGN) == SIG_ERR || setrlimit(RLIMIT_FSIZE, &fileLimit) != 0))
      _exit(126);
    if (options.asNobody && (setgroups(0, nullptr) != 0 || setgid(65534) != 0 || setuid(65534) != 0)) _exit(125);
    // The build may live where nobody cannot reach it (a checkout under /root): that is a
    // limit of the test machine: the test skips, saying so.
    if (options.asNobody && access(argv[0], X_OK) != 0) _exit(125);
    execv(argv[0], argv.data());
    _exit(127);
  }
  Outcome o;
  if (pid < 0) {
    ADD_FAILURE() << "fork: " << std::strerror(errno);
    return o;
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(options.timeoutSeconds);
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      o.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!o.timedOut) {
    o.exited = WIFEXITED(status);
    o.code = o.exited ? WEXITSTATUS(status) : -1;
    o.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  o.out = slurp(outPath);
  o.err = slurp(errPath);
  std::remove(outPath.c_str());
  std::remove(errPath.c_str());
  return o;
}

inline bool contains(const std::string& text, const std::string& fragment) {
  return text.find(fragment) != std::string::npos;
}

/// True when `o` ended by exit with `code`: false for crashes, time-outs and sanitizer reports
/// (AddressSanitizer and UBSan may exit with status 1 themselves, so stderr is checked too).
inline bool exitedWith(const Outcome& o, int code) {
  return o.exited && !o.timedOut && o.code == code && !contains(o.err, "Sanitizer") &&
         !contains(o.err, "runtime error:");
}

}  // namespace fosssim::testing
