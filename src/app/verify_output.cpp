#include "verify_output.h"

#include "fosssim/core/verify.h"

#include <cstdio>

namespace fosssim::app {
namespace {

/// Violations printed per step; the rest are counted.
constexpr size_t kReportedPerStep = 5;

}  // namespace

Status VerifyOutput::afterStep(const SceneFile& file, const State& state, const CollisionLog&) {
  ++steps_;
  if (Status s = checkFinite(state); !s) {
    ++violations_;
    std::fprintf(stderr, "verify: step %ld: %s\n", state.step, s.message().c_str());
    return Status::ok();
  }
  const std::vector<Violation> found = simulator_.unresolved(file.scene, state);
  if (found.empty()) return Status::ok();
  violations_ += static_cast<long>(found.size());
  ++stepsWithViolations_;
  for (size_t k = 0; k < found.size() && k < kReportedPerStep; ++k)
    std::fprintf(stderr, "verify: step %ld: %s pair (%d, %d) still collides at %.6g of the step\n", state.step,
                 pairKindName(found[k].kind), found[k].i, found[k].j, found[k].tau);
  if (found.size() > kReportedPerStep)
    std::fprintf(stderr, "verify: step %ld: ... and %zu more\n", state.step, found.size() - kReportedPerStep);
  return Status::ok();
}

Status VerifyOutput::finish() {
  std::fprintf(stderr, "verify: %ld steps checked, %ld violations in %ld steps\n", steps_, violations_,
               stepsWithViolations_);
  if (violations_ > 0)
    return Status::error("--verify found " + std::to_string(violations_) + " violations in " +
                         std::to_string(stepsWithViolations_) + " steps");
  return Status::ok();
}

}  // namespace fosssim::app
