// --verify: after every step, a fresh continuous-time detection over the step must find no pair
// still colliding (pairs inside one rigid impact zone excepted). Violations are reported with
// step and pair; the run then ends with a failure status.
//
// That is the promise of continuous-time and hybrid handling in the default mode. The other
// methods do not make it (simple handling responds at a step's end only, penalty handling lets
// pairs overlap while it pushes them apart, none keeps nothing apart, and --compat reproduces the
// course's methods, flaws included), so the same check finds contacts there by design: the
// summary then says so, lest a finding the method allows be read as a defect of the run.
#pragma once

#include "run_observer.h"

#include "fosssim/core/scene.h"
#include "fosssim/core/simulator.h"

#include <string>

namespace fosssim::app {

/// Why --verify may find contacts with handling of this type although nothing is wrong, as one
/// sentence; empty when the handler keeps pairs apart (Simulator::keepsPairsApart: continuous-time
/// and hybrid without --compat), where every finding is a defect.
std::string verifyScope(CollisionType type, bool keepsPairsApart);

class VerifyOutput final : public RunObserver {
 public:
  explicit VerifyOutput(const Simulator& simulator)
      : simulator_(simulator), scope_(verifyScope(simulator.collisionType(), simulator.keepsPairsApart())) {}
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  Status finish() override;

  long violations() const { return violations_; }

 private:
  const Simulator& simulator_;
  std::string scope_;
  long violations_ = 0, stepsWithViolations_ = 0, steps_ = 0;
};

}  // namespace fosssim::app
