// Replays a fuzz target on every input kept in tests/data/fuzz-regressions/<target>: inputs that
// once crashed it or broke one of its invariants. The including test defines the target
// (LLVMFuzzerTestOneInput, by including the fuzzer's source); a violated invariant aborts, which
// fails the test.
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

inline void replayFuzzRegressions(const std::string& target) {
  const std::filesystem::path dir = std::string(FOSSSIM_TEST_DATA) + "/fuzz-regressions/" + target;
  int inputs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    SCOPED_TRACE(entry.path().string());
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), 0);
    ++inputs;
  }
  EXPECT_GT(inputs, 0) << "no inputs in " << dir;
}
