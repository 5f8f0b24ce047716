// Starting a private X server for the tests that need a display (the window, signals sent to a
// window run): Xvfb picks a free display number itself (-displayfd) and writes it to a pipe,
// so parallel tests never race for one.
#pragma once

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fosssim::testing {

/// Starts Xvfb with one screen of `screen` (WxHxDepth). Returns ":N" and sets `pid`, or returns
/// an empty string and says why in `why` (Xvfb missing, or no display number within 20 s).
/// The caller stops the server (SIGTERM to `pid`).
inline std::string startXvfb(pid_t& pid, std::string& why, const std::string& screen = "800x600x24") {
  int fds[2];
  if (pipe(fds) != 0) {
    why = "cannot create a pipe";
    return "";
  }
  pid = fork();
  if (pid == 0) {
    const int devnull = open("/dev/null", O_RDWR);
    dup2(devnull, 0);
    dup2(devnull, 1);
    dup2(devnull, 2);
    close(fds[0]);
    const std::string fd = std::to_string(fds[1]);
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", screen.c_str(), "-nolisten", "tcp", "-noreset",
           static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (pid > 0 && std::chrono::steady_clock::now() < end && number.find('\n') == std::string::npos) {
    if (poll(&p, 1, 100) > 0) {
      char buf[32];
      const ssize_t n = read(fds[0], buf, sizeof buf);
      if (n <= 0) break;
      number.append(buf, static_cast<std::size_t>(n));
    }
  }
  close(fds[0]);
  if (pid <= 0 || number.find('\n') == std::string::npos) {
    why = "Xvfb did not start (no display number reported within 20 s)";
    return "";
  }
  return ":" + number.substr(0, number.find('\n'));
}

}  // namespace fosssim::testing
