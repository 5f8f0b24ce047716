// Runs the scene_steps fuzz target's own checks (fuzz/scene_steps_fuzz.cpp: a few steps under every
// collision handler in both modes) on every input in tests/data/fuzz-regressions/scene_steps.
// tests/io/CMakeLists.txt compiles the fuzzer's source into this test.
#include "fuzz_regressions.h"

namespace {

TEST(FuzzRegression, SceneSteps) { replayFuzzRegressions("scene_steps"); }

}  // namespace
