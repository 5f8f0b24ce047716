// Runs the trajectory fuzz target's own checks (fuzz/trajectory_fuzz.cpp) on every input in
// tests/data/fuzz-regressions/trajectory.
#include "../../fuzz/trajectory_fuzz.cpp"

#include "fuzz_regressions.h"

namespace {

TEST(FuzzRegression, Trajectory) { replayFuzzRegressions("trajectory"); }

}  // namespace
