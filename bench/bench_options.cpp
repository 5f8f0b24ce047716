#include "bench_options.h"

#include "cli_values.h"
#include "fosssim/core/integrator.h"

namespace fosssim::bench {

void defineOptions(CLI::App& app, Options& o) {
  app.description(
      "Milliseconds per step by phase on the scalable scenes, and narrow-phase queries per second, on one core.\n"
      "Every scene and size runs in a child process of its own; figures are those of the fastest repeat.");
  app.add_option("--sizes", o.sizes, "particle counts, comma-separated, each 1 to 10^7 (default 1000,10000,100000)")
      ->option_text("N,N,...")
      ->delimiter(',')
      ->check(cli::integerIn(1, 10000000));
  app.add_option(
         "--scenes", o.scenes,
         "scenes, comma-separated, of " + cli::listed(allKinds()) + " (default " + cli::listed(sceneKinds()) + ")")
      ->option_text("NAME,...")
      ->delimiter(',')
      ->check(cli::oneOf("scene", allKinds()));
  app.add_option("--collision", o.collision,
                 "collision handling of every scene, one of " + cli::listed(collisionTypes()) + " (default hybrid)")
      ->option_text("TYPE")
      ->check(cli::oneOf("collision type", collisionTypes()));
  std::vector<std::string> integrators;
  for (const IntegratorEntry& entry : integratorTable()) integrators.push_back(entry.keyword);
  app.add_option(
         "--integrator", o.integrator,
         "integrator of every scene, one of " + cli::listed(integrators) + " (default: the scenes' symplectic-euler)")
      ->option_text("NAME")
      ->check(cli::oneOf("integrator", integrators));
  app.add_option("--steps", o.steps, "steps per run, 1 to 10^9 (default: each scene's own length)")
      ->option_text("K")
      ->check(cli::integerIn(1, 1000000000));
  app.add_option("--repeats", o.repeats,
                 "timed runs per scene and size, 1 to 1000 (default 3 below 10^5 particles, 1 from there)")
      ->option_text("R")
      ->check(cli::integerIn(1, 1000));
  app.add_option("--threads", o.threads,
                 "threads for the per-particle phases (forces, integration, broad phase, detection, sleeping), 1 to "
                 "1024 (default 1)")
      ->option_text("T")
      ->check(cli::integerIn(1, 1024));
  app.add_option("--seed", o.seed, "seed of the scenes' jitter and random velocities, 0 to 2^31 - 1 (default 1)")
      ->option_text("S")
      ->check(cli::integerIn(0, 2147483647));
  app.add_option("--time-limit", o.timeLimit,
                 "seconds per timed run: a run stops after the 100-step block that passes it and reports the "
                 "steps it took (default: none)")
      ->option_text("S")
      ->check(cli::integerIn(1, 1000000));
  app.add_flag("--blocks", o.blocks, "a table per block of 100 steps for every run (default: runs of 1,000+ steps)");
  app.add_option("--blocks-csv", o.blocksCsv, "append the block tables' rows to this CSV file")->option_text("FILE");
  app.add_flag("--all-pairs", o.allPairs, "test every pair (no broad phase)");
  app.add_flag("--compat", o.compat, "the course's formulation instead of the default mode");
  app.add_flag("--no-sleep", o.noSleep, "the default mode's resting particles do not sleep");
  app.add_flag("--no-hold", o.noHold, "the default mode's budget-ended zone solves hold no particle at rest");
  app.add_option("--csv", o.csv, "also write the figures to this CSV file")->option_text("FILE");
  app.add_flag_callback("--no-queries", [&o] { o.queries = false; }, "skip the narrow-phase query rates");
  app.add_flag_callback("--no-steps", [&o] { o.stepTable = false; }, "skip the ms-per-step table");
  app.add_flag("--alternatives", o.alternatives,
               "also time the broad-phase designs measured before choosing one (rain, gas, bullets)");
}

}  // namespace fosssim::bench
