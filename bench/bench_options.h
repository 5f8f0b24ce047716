// fosssim-bench's options (fosssim_bench.cpp): what a run measures, and their command line.
#pragma once

#include "bench_scenes.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fosssim::bench {

struct Options {
  std::vector<int> sizes = {1000, 10000, 100000};
  std::vector<std::string> scenes = sceneKinds();
  std::string collision = "hybrid";
  std::string integrator;  ///< empty: each scene's own (symplectic Euler)
  long steps = 0;  ///< 0: each scene's own length
  int repeats = 0;  ///< 0: 3 below 10^5 particles, 1 from there on
  bool allPairs = false;
  bool compat = false;  ///< the course's formulation (--compat) instead of the default mode
  bool noSleep = false; ///< --no-sleep: the default mode's resting particles do not sleep
  bool noHold = false;  ///< --no-hold: the default mode's budget-ended solves hold nobody (HandlerOptions::hold)
  int threads = 1;
  std::string csv;
  bool queries = true;
  bool stepTable = true;
  bool alternatives = false;
  unsigned seed = 1;        ///< fixes the scenes' jitter and random velocities
  bool blocks = false;      ///< the block table for runs shorter than 1,000 steps too
  std::string blocksCsv;    ///< the block rows appended to this CSV file
  double timeLimit = 0;     ///< seconds: a timed run stops after the block that passes it (0: none)
};

/// Defines fosssim-bench's command line on `app`, filling `o`.
void defineOptions(CLI::App& app, Options& o);

}  // namespace fosssim::bench
