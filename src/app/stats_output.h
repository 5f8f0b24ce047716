// --stats FILE: per-step diagnostics (fosssim/core/diagnostics.h) as CSV, one row for the initial
// state (step 0) and one per step, under a header row of the column names (README: --stats).
// The file only ever ends after a whole row: a write that fails (a full disk) is cut back to the
// last whole row, and a run that does not complete says how many rows the file holds.
#pragma once

#include "run_observer.h"

#include "fosssim/core/diagnostics.h"
#include "fosssim/core/simulator.h"

#include <sys/types.h>
#include <string>
#include <vector>

namespace fosssim::app {

class StatsOutput final : public RunObserver {
 public:
  /// Turns on the simulator's phase timing (the cost columns need it).
  StatsOutput(std::string path, Simulator& simulator);
  ~StatsOutput() override;
  StatsOutput(const StatsOutput&) = delete;
  StatsOutput& operator=(const StatsOutput&) = delete;
  Status start(const SceneFile& file, const State& initial, const RecordLayout& layout) override;
  Status afterStep(const SceneFile& file, const State& state, const CollisionLog& log) override;
  Status finish() override;
  std::string written() const override;

 private:
  Status writeRow();
  Status flush();
  void keepWholeRows(std::size_t written);
  std::string path_;
  const Simulator& simulator_;
  int fd_ = -1;
  bool created_ = false;         ///< the file was created (and may be closed after a failure)
  bool headerWritten_ = false;
  off_t wholeBytes_ = 0;         ///< the header and the whole rows on disk
  long wholeRows_ = 0;           ///< rows on disk (steps 0 to wholeRows_ - 1)
  std::string pending_;          ///< whole rows not yet written
  long pendingRows_ = 0;
  StepDiagnostics diagnostics_;
  std::vector<double> row_;
};

}  // namespace fosssim::app
