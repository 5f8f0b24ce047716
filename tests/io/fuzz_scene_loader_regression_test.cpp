// Runs fuzz_scene_loader's own checks (fuzz/scene_loader_fuzz.cpp) on every input in
// tests/data/fuzz-regressions/scene_loader: inputs that once crashed or broke an invariant.
// A violated invariant aborts, which fails this test.
#include "../../fuzz/scene_loader_fuzz.cpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

TEST(FuzzRegression, SceneLoader) {
  const std::filesystem::path dir = std::string(FOSSSIM_TEST_DATA) + "/fuzz-regressions/scene_loader";
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().string());
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
    ++inputs;
  }
  EXPECT_GT(inputs, 0);
}

}  // namespace
