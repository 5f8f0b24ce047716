// --stats FILE: per-step diagnostics (fosssim/core/diagnostics.h) as CSV, one row for the initial
// state (step 0) and one per step, under a header row of the column names (README: --stats).
#pragma once

#include "run_observer.h"

#include "fosssim/core/diagnostics.h"
#include "fosssim/core/simulator.h"

#include <fstream>
#include <string>
#include <vector>

namespace fosssim::app {

class StatsOutput final : public RunObserver {
 public:
  /// Turns on the simulator's phase timing (the cost columns need it).
  StatsOutput(std::string path, Simulator& simulator);
  Status start(const SceneFile& file, const State& initial, const RecordLayout& layout) override;
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  Status finish() override;

 private:
  Status writeRow();
  std::string path_;
  const Simulator& simulator_;
  std::ofstream out_;
  StepDiagnostics diagnostics_;
  std::vector<double> row_;
  std::string line_;
};

}  // namespace fosssim::app
