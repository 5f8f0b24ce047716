// Helpers for the render tests: inline scenes, temporary folders, running programs.
#pragma once

#include "fosssim/io/scene_file.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fosssim::testing {

/// A scene with a particle, an edge between two more, a half-plane and a path, on a coloured
/// background, shown through a fixed viewport: every kind of shape the pictures have.
/// With a 100 x 80 picture the scale is 40 pixels per unit and the origin at pixel (50, 40).
inline const char* kShapesScene = R"(<scene>
  <duration time="0.1"/>
  <integrator type="explicit-euler" dt="0.01"/>
  <viewport cx="0" cy="0" size="1"/>
  <backgroundcolor r="0.2" g="0.4" b="0.6"/>
  <particle m="1" px="0.5" py="0.25" vx="0" vy="0" fixed="1" radius="0.2"/>
  <particle m="1" px="-0.5" py="0.5" vx="0" vy="0" fixed="1" radius="0.05"/>
  <particle m="1" px="-0.5" py="-0.3" vx="0" vy="0" fixed="1" radius="0.05"/>
  <particle m="1" px="0" py="-0.5" vx="0" vy="0" fixed="1" radius="0.1"/>
  <edge i="1" j="2" radius="0.05"/>
  <halfplane px="0" py="-0.5" nx="0" ny="2"/>
  <particlecolor i="0" r="1" g="0" b="0"/>
  <halfplanecolor i="0" r="0" g="0.5" b="0"/>
  <particlepath i="0" duration="0.05" r="1" g="1" b="0"/>
</scene>)";

inline SceneFile parsed(const char* text) {
  SceneFile file;
  const Status s = parseScene(text, "inline.xml", file);
  EXPECT_TRUE(s.isOk()) << s.message();
  return file;
}

/// A fresh, empty temporary folder (removed by the caller's TempDir guard).
struct TempDir {
  std::string path;
  TempDir() {
    // Under TMPDIR when set (temp_directory_path reads it), as every test's scratch files.
    std::string pattern = (std::filesystem::temp_directory_path() / "fosssim_render_XXXXXX").string();
    const char* made = mkdtemp(pattern.data());
    path = made ? made : "";
  }
  ~TempDir() {
    std::error_code ec;
    if (!path.empty()) std::filesystem::remove_all(path, ec);
  }
  std::string operator/(const std::string& name) const { return path + "/" + name; }
};

inline void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct CommandResult {
  int exitCode = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs a shell command line, capturing its output.
inline CommandResult run(const std::string& command) {
  CommandResult r;
  std::FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
  const int status = pclose(p);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// The full path of `program` on PATH, or empty.
inline std::string onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

}  // namespace fosssim::testing
