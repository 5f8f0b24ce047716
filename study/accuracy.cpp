// The accuracy matrix: every problem x method x dt, judged by the problem's own measurement and
// timed separately (timeRun), so that measuring never inflates the cost that is reported.
#include "experiments.h"

#include "csv.h"

#include <cmath>
#include <thread>

namespace fosssim::study {

AccuracyCell measureAccuracy(const Problem& problem, const Method& method, double dt, const StudyOptions& options,
                             bool timed) {
  AccuracyCell cell;
  SceneFile file;
  if (Status s = problem.scene(method, dt).build(problem.name + ".xml", file); !s) {
    cell.run.outcome = Outcome::Error;
    cell.run.message = s.message();
    return cell;
  }
  std::unique_ptr<Measurement> measure = problem.measure();
  cell.run = runScene(file, RunOptions{}, [&](const Scene& scene, const State& s) { measure->step(scene, s); });
  const Metrics over = measure->overRun();  // also for a run that failed part way
  if (cell.run.ok()) cell.metrics = measure->finish(file.scene, file.initial, cell.run);
  cell.metrics.energyMax = over.energyMax;
  cell.metrics.energyRms = over.energyRms;
  cell.metrics.minSeparation = over.minSeparation;
  if (!cell.run.ok()) return cell;
  if (timed) {
    cell.timing = timeRunSpread(file, cell.run.steps, options.timingRepeats, options.timingBudget);
    cell.wallSeconds = cell.timing.min;
  }
  return cell;
}

Status runAccuracy(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/accuracy.csv",
                          {"problem", "title", "kind", "error_label", "method", "integrator", "collision", "dt",
                           "steps", "outcome", "sim_time", "wall_s", "wall_per_sim_s", "us_per_step", "error",
                           "position_error", "velocity_error", "energy_error", "momentum_error", "angmom_error",
                           "period_error", "contact_time_error", "collisions", "overlap_steps", "overlap_pair_steps",
                           "max_overlap", "failsafe_steps", "energy_error_max", "energy_error_rms",
                           "min_separation", "exact_min_separation", "omega", "wall_s_median", "wall_s_max",
                           "timing_repeats", "message"});
      !s)
    return s;
  std::vector<Problem> problems = integratorProblems(options.quick);
  for (Problem& p : collisionProblems(options.quick)) problems.push_back(std::move(p));
  for (const Problem& p : problems) {
    if (options.log) *options.log << "accuracy: " << p.name << std::flush;
    for (const Method& m : p.methods) {
      for (double dt : p.dts) {
        const AccuracyCell c = measureAccuracy(p, m, dt, options, true);
        const RunResult& r = c.run;
        const double simTime = r.final.time;
        csv << p.name << p.title << p.kind << p.errorLabel << m.label << m.integrator << m.collision.type << dt
            << r.steps << outcomeName(r.outcome) << simTime << c.wallSeconds << c.wallSeconds / simTime
            << 1e6 * c.wallSeconds / static_cast<double>(r.steps) << c.metrics.error << c.metrics.position
            << c.metrics.velocity << c.metrics.energy << c.metrics.momentum << c.metrics.angularMomentum
            << c.metrics.period << c.metrics.contactTime << r.collisions << r.overlap.stepsWithOverlap
            << r.overlap.pairSteps << r.overlap.deepest << r.failsafeSteps << c.metrics.energyMax
            << c.metrics.energyRms << c.metrics.minSeparation << p.exactMinSeparation << p.omega
            << c.timing.median << c.timing.max << static_cast<long>(c.timing.repeats) << r.message;
        if (Status s = csv.endRow(); !s) return s;
      }
      if (options.log) *options.log << "." << std::flush;
    }
    if (options.log) *options.log << "\n";
  }
  if (Status s = writeProblemSetups(problems, options); !s) return s;
  return runAudit(options);
}

Status writeProblemSetups(const std::vector<Problem>& problems, const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/problems.csv", {"problem", "name", "value"}); !s) return s;
  // The study's own marks, quoted by the page's definitions: the blow-up mark of every run.
  csv << "study" << "blow_up" << RunOptions{}.energyGrowthLimit;
  if (Status s = csv.endRow(); !s) return s;
  // The machine the timings come from, as the run saw it (0: the library could not tell).
  csv << "study" << "hardware_threads" << static_cast<long>(std::thread::hardware_concurrency());
  if (Status s = csv.endRow(); !s) return s;
  for (const Problem& p : problems)
    for (const auto& [name, value] : p.setup) {
      csv << p.name << name << value;
      if (Status s = csv.endRow(); !s) return s;
    }
  return Status::ok();
}

}  // namespace fosssim::study
