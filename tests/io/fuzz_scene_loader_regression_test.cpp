// Runs the scene_loader fuzz target's own checks (fuzz/scene_loader_fuzz.cpp) on every input in
// tests/data/fuzz-regressions/scene_loader. tests/io/CMakeLists.txt compiles the fuzzer's source into this test.
#include "fuzz_regressions.h"

namespace {

TEST(FuzzRegression, SceneLoader) { replayFuzzRegressions("scene_loader"); }

}  // namespace
