// Runs the trajectory fuzz target's own checks (fuzz/trajectory_fuzz.cpp) on every input in
// tests/data/fuzz-regressions/trajectory. tests/io/CMakeLists.txt compiles the fuzzer's source into this test.
#include "fuzz_regressions.h"

namespace {

TEST(FuzzRegression, Trajectory) { replayFuzzRegressions("trajectory"); }

}  // namespace
