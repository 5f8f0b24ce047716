// Every experiment runs end to end on its quick matrix and writes a CSV file with rows.
#include "experiments.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace fosssim::study {
namespace {

long lines(const std::string& path) {
  std::ifstream in(path);
  long n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

TEST(StudyExperiments, QuickMatrixWritesEveryCsvFile) {
  // A folder of this process's own: the Release and sanitizer suites may run side by side.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fosssim-study-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  StudyOptions options;
  options.outDir = dir.string();
  options.quick = true;
  options.timingBudget = 0.0;
  options.timingRepeats = 1;
  ASSERT_TRUE(runAccuracy(options).isOk());
  ASSERT_TRUE(runStability(options).isOk());
  ASSERT_TRUE(runRobustness(options).isOk());
  ASSERT_TRUE(runHybridCost(options).isOk());
  ASSERT_TRUE(runProfile(options).isOk());
  ASSERT_TRUE(runContacts(options).isOk());
  for (const char* name : {"accuracy", "problems", "audit_series", "stability", "damped_stability",
                           "newton_failure", "newton_iterations", "robustness", "robustness_shots", "hybrid",
                           "profile", "contacts_series", "contacts_summary"})
    EXPECT_GT(lines((dir / (std::string(name) + ".csv")).string()), 2) << name;
  std::filesystem::remove_all(dir);
}

TEST(StudyExperiments, UnwritableDirectoryIsAnErrorNotACrash) {
  StudyOptions options;
  options.outDir = "/nonexistent/fosssim-study";
  options.quick = true;
  const Status s = runStability(options);
  EXPECT_FALSE(s.isOk());
  EXPECT_NE(s.message().find("cannot write"), std::string::npos);
}

}  // namespace
}  // namespace fosssim::study
