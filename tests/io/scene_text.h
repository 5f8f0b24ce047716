// Scene texts for the loader tests, built line by line so that tests know every element's line.
#pragma once

#include "fosssim/io/scene_file.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fosssim::testing {

/// The name the tests give parseScene() for messages.
inline const std::string kFile = "bad.xml";

/// A small valid scene, one element per line (line numbers in the comments):
inline std::vector<std::string> baseLines() {
  return {
      "<scene>",                                                          // 1
      "  <duration time=\"1\"/>",                                         // 2
      "  <integrator type=\"explicit-euler\" dt=\"0.01\"/>",              // 3
      "  <particle m=\"1\" px=\"0\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",  // 4
      "  <particle m=\"2\" px=\"1\" py=\"0\" vx=\"0\" vy=\"0\" fixed=\"0\"/>",  // 5
      "  <edge i=\"0\" j=\"1\"/>",                                        // 6
      "  <halfplane px=\"0\" py=\"-1\" nx=\"0\" ny=\"1\"/>",              // 7
      "</scene>",                                                         // 8
  };
}
/// The line at which extra() puts its element.
inline constexpr int kExtraLine = 8;

inline std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  return text;
}

/// The base scene with `element` inserted at line kExtraLine (before </scene>).
inline std::string extra(const std::string& element) {
  std::vector<std::string> lines = baseLines();
  lines.insert(lines.begin() + (kExtraLine - 1), element);
  return join(lines);
}

/// The base scene with line `line` (1-based) replaced by `element`.
inline std::string replaced(int line, const std::string& element) {
  std::vector<std::string> lines = baseLines();
  lines.at(line - 1) = element;
  return join(lines);
}

/// Parses `text`; the Status message (empty on success).
inline std::string loadError(const std::string& text) {
  SceneFile file;
  const Status s = parseScene(text, kFile, file);
  return s ? std::string() : s.message();
}

/// "bad.xml:12: <integrator> attribute 'dt'": where the loader must point for a bad attribute.
inline std::string located(int line, const std::string& element, const std::string& attribute) {
  return kFile + ":" + std::to_string(line) + ": <" + element + "> attribute '" + attribute + "'";
}

/// `text` loaded (it must load: a failure is the test's).
inline SceneFile loaded(const std::string& text) {
  SceneFile file;
  const Status s = parseScene(text, kFile, file);
  EXPECT_TRUE(s.isOk()) << s.message();
  return file;
}

/// Expects `text` (a message) to contain every fragment.
inline void expectContains(const std::string& text, const std::vector<std::string>& fragments) {
  for (const auto& f : fragments) EXPECT_NE(text.find(f), std::string::npos) << "missing \"" << f << "\" in: " << text;
}

/// Asserts that `text` fails to load with a message that contains every fragment.
inline void expectError(const std::string& text, const std::vector<std::string>& fragments) {
  const std::string message = loadError(text);
  ASSERT_FALSE(message.empty()) << "loaded, but should have failed:\n" << text;
  for (const auto& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "missing \"" << f << "\" in: " << message;
}

}  // namespace fosssim::testing
