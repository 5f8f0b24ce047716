// --verify: after every step, a fresh continuous-time detection over the step must find no pair
// still colliding (pairs inside one rigid impact zone excepted). Violations are reported with
// step and pair; the run then ends with a failure status.
#pragma once

#include "run_observer.h"

#include "fosssim/core/simulator.h"

namespace fosssim::app {

class VerifyOutput final : public RunObserver {
 public:
  explicit VerifyOutput(const Simulator& simulator) : simulator_(simulator) {}
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  Status finish() override;

  long violations() const { return violations_; }

 private:
  const Simulator& simulator_;
  long violations_ = 0, stepsWithViolations_ = 0, steps_ = 0;
};

}  // namespace fosssim::app
