// A test fixture with its own temporary folder: TMPDIR's (std::filesystem::temp_directory_path)
// "fosssim-<suite>-<pid>", made before each test and removed with what it holds after it, so
// that tests clean up after themselves and parallel runs (ctest -j) do not meet.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace fosssim::testing {

class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string suite = ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name();
    dir_ = std::filesystem::temp_directory_path() / ("fosssim-" + suite + "-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  /// `name` inside the folder.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace fosssim::testing
