// Runs the scene_loader fuzz target's own checks (fuzz/scene_loader_fuzz.cpp) on every input in
// tests/data/fuzz-regressions/scene_loader.
#include "../../fuzz/scene_loader_fuzz.cpp"

#include "fuzz_regressions.h"

namespace {

TEST(FuzzRegression, SceneLoader) { replayFuzzRegressions("scene_loader"); }

}  // namespace
