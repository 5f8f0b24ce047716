#include "verify_output.h"

#include "fosssim/core/verify.h"

#include <cstdio>
#include <string>

namespace fosssim::app {
namespace {

/// Violations printed per step; the rest are counted.
constexpr size_t kReportedPerStep = 5;

/// "1 step", "2 steps".
std::string counted(long n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

std::string verifyScope(CollisionType type, bool keepsPairsApart) {
  if (keepsPairsApart) return "";
  const char* promise = "continuous-time and hybrid handling (without --compat) promise that no pair is left colliding";
  switch (type) {
    case CollisionType::None:
      return "the scene has no collision handling: nothing keeps pairs apart, so every contact is found";
    case CollisionType::Simple:
      return std::string("simple handling responds only to pairs that overlap at the end of a step, so contacts "
                         "within a step are to be expected; ") + promise;
    case CollisionType::Penalty:
      return std::string("penalty handling lets pairs overlap while its force pushes them apart, so contacts are to "
                         "be expected; ") + promise;
    case CollisionType::ContinuousTime:
    case CollisionType::Hybrid:  // the course's handlers: the default mode's keep pairs apart
      return std::string("--compat reproduces the course's handling, flaws included, and it can leave pairs "
                         "colliding; without --compat ") + collisionKeyword(type) + " handling promises that none is";
  }
  return "";
}

Status VerifyOutput::afterStep(const SceneFile& file, const State& state, const CollisionLog&) {
  ++steps_;
  if (Status s = checkFinite(state); !s) {
    ++violations_, ++stepsWithViolations_;
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
  const std::string found = counted(violations_, "violation") + " in " + counted(stepsWithViolations_, "step");
  std::fprintf(stderr, "verify: %s checked, %s\n", counted(steps_, "step").c_str(), found.c_str());
  if (violations_ == 0) return Status::ok();
  if (!scope_.empty()) std::fprintf(stderr, "verify: %s\n", scope_.c_str());
  return Status::error("--verify found " + found);
}

}  // namespace fosssim::app
