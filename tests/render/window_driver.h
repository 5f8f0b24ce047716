// Driving FOSSSim's interactive window in tests: a child process guard, spawning with the output
// in a file, XWD screenshots (x11-apps' xwd), one shared Xvfb display and a FOSSSim run in a window
// on it, driven with xdotool. Used by window_test.cpp.
#pragma once

#include "render_test_support.h"
#include "support/xvfb.h"

#include <chrono>
#include <csignal>
#include <cstdint>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <thread>
#include <vector>

extern char** environ;

namespace fosssim::testing {

using Clock = std::chrono::steady_clock;

struct Child {
  pid_t pid = -1;
  ~Child() { stop(); }
  void stop() {
    if (pid <= 0) return;
    kill(pid, SIGTERM);
    for (int k = 0; k < 50 && waitpid(pid, nullptr, WNOHANG) == 0; ++k)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (waitpid(pid, nullptr, WNOHANG) == 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
    pid = -1;
  }
  /// Waits up to `seconds` for the child to exit; its exit code, or -1 if it did not.
  int wait(double seconds) {
    const auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
      int status = 0;
      if (waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return -1;
  }
};

inline pid_t spawn(const std::vector<std::string>& args, int stdoutFd = -1, const std::string& cwd = "") {
  std::vector<char*> argv;
  std::vector<std::string> copy = args;
  for (auto& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdoutFd >= 0) {
    posix_spawn_file_actions_adddup2(&actions, stdoutFd, STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, stdoutFd, STDERR_FILENO);
  }
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  pid_t pid = -1;
  if (posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

/// An XWD screenshot (the format of x11-apps' xwd): 24/32-bit TrueColor, ZPixmap.
struct Screenshot {
  int width = 0, height = 0;
  std::vector<std::uint32_t> rgb;  // 0xRRGGBB, top row first
  bool load(const std::string& path, std::string& why) {
    const std::string data = readText(path);
    auto field = [&](int k) {
      const auto* b = reinterpret_cast<const unsigned char*>(data.data()) + 4 * k;
      return (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | b[3];
    };
    if (data.size() < 100) return (why = "XWD file too short", false);
    const std::uint32_t headerSize = field(0), format = field(2), w = field(4), h = field(5), byteOrder = field(7),
                        bitsPerPixel = field(11), bytesPerLine = field(12), redMask = field(14),
                        greenMask = field(15), blueMask = field(16), colors = field(19);
    if (format != 2 || bitsPerPixel != 32) return (why = "XWD file is not a 32-bit ZPixmap", false);
    const std::size_t offset = headerSize + 12 * std::size_t(colors);
    if (data.size() < offset + std::size_t(bytesPerLine) * h) return (why = "XWD file truncated", false);
    auto shift = [](std::uint32_t mask) {
      int s = 0;
      while (mask && !(mask & 1)) mask >>= 1, ++s;
      return s;
    };
    width = int(w);
    height = int(h);
    rgb.resize(std::size_t(w) * h);
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const auto* b = reinterpret_cast<const unsigned char*>(data.data()) + offset + y * bytesPerLine + 4 * x;
        const std::uint32_t v = byteOrder == 0 ? (b[0] | b[1] << 8 | b[2] << 16 | std::uint32_t(b[3]) << 24)
                                               : (std::uint32_t(b[0]) << 24 | b[1] << 16 | b[2] << 8 | b[3]);
        const std::uint32_t r = (v & redMask) >> shift(redMask), g = (v & greenMask) >> shift(greenMask),
                            bl = (v & blueMask) >> shift(blueMask);
        rgb[std::size_t(y) * w + x] = r << 16 | g << 8 | bl;
      }
    return true;
  }
  std::uint32_t at(int x, int y) const { return rgb[std::size_t(y) * width + x]; }
};

inline std::string hex(std::uint32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%06x", c);
  return buf;
}

/// One Xvfb for the tests below (started on first use, stopped at exit), with the tools they need.
struct Display {
  Child xvfb;
  std::string name, why;
  static Display& get() {
    static Display d;
    static bool started = false;
    if (!started) {
      started = true;
      for (const char* tool : {"Xvfb", "xdotool", "xwd"})
        if (onPath(tool).empty()) {
          d.why = std::string(tool) + " is not installed (scripts/setup installs xvfb, xdotool and x11-apps)";
          return d;
        }
      d.name = startXvfb(d.xvfb.pid, d.why);
    }
    return d;
  }
};

/// FOSSSim in a window on the shared display, its output in a log, run in `cwd`.
struct WindowRun {
  Child app;
  std::string display, log, window;

  WindowRun(const std::string& disp, const std::string& cwd, const std::vector<std::string>& args)
      : display(disp), log(cwd + "/fosssim.log") {
    setenv("DISPLAY", display.c_str(), 1);
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> argv = {FOSSSIM_EXECUTABLE};
    argv.insert(argv.end(), args.begin(), args.end());
    app.pid = spawn(argv, fd, cwd);
    close(fd);
    unsetenv("DISPLAY");
  }
  std::string x() const { return "DISPLAY=" + display + " "; }
  /// Waits for the window to appear; false if it did not within 20 s.
  bool find() {
    for (auto end = Clock::now() + std::chrono::seconds(20); Clock::now() < end && window.empty();) {
      const auto r = run(x() + "xdotool search --name '^FOSSSim: '");
      if (r.exitCode == 0) window = r.output.substr(0, r.output.find('\n'));
      else std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return !window.empty();
  }
  /// Waits until the title contains `text`; the last title seen.
  std::string waitTitle(const std::string& text, double seconds = 10) {
    std::string title;
    for (auto end = Clock::now() + std::chrono::duration<double>(seconds); Clock::now() < end;) {
      title = run(x() + "xdotool getwindowname " + window).output;
      if (title.find(text) != std::string::npos) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return title;
  }
  int key(const std::string& keys) { return run(x() + "xdotool key --window " + window + " " + keys).exitCode; }
  bool shot(const std::string& path, Screenshot& image, std::string& why) {
    const auto r = run(x() + "xwd -silent -id " + window + " -out " + path);
    if (r.exitCode != 0) return (why = r.output, false);
    return image.load(path, why);
  }
  std::string output() const { return readText(log); }
};

#define NEED_DISPLAY()                                                   \
  Display& shared = Display::get();                                      \
  if (shared.name.empty()) GTEST_SKIP() << "no window test here: " << shared.why

}  // namespace fosssim::testing
