// The audit over time: energy, momentum and angular momentum against the exact motion at every
// sampled step end, for each integrator on each integrator problem at one time step (a run that
// fails is recorded up to its failure). Written to audit_series.csv; the accuracy matrix reports
// only the end of a run and the largest energy error, this shows how each error grows or swings.
#include "csv.h"
#include "experiments.h"

#include <cmath>

namespace fosssim::study {

namespace {

/// The time step each problem is audited at: coarse enough to show every method's character,
/// fine enough that implicit Euler's Newton converges on the orbit (it fails at 0.01 and above).
double auditStep(const std::string& problem) { return problem == "orbit" ? 0.005 : 0.01; }

constexpr int kSamples = 200;

}  // namespace

Status runAudit(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/audit_series.csv",
                          {"problem", "title", "method", "dt", "step", "time", "energy_error", "momentum_error",
                           "angmom_error", "outcome"});
      !s)
    return s;
  for (const Problem& p : integratorProblems(options.quick)) {
    if (options.log) *options.log << "audit: " << p.name << std::flush;
    const double dt = auditStep(p.name);
    for (const Method& m : p.methods) {
      SceneFile file;
      if (Status s = p.scene(m, dt).build(p.name + ".xml", file); !s) return s;
      const std::unique_ptr<Measurement> measure = p.measure();
      const long steps = file.scene.numSteps();
      const long every = std::max(1L, steps / kSamples);
      struct Sample {
        long step;
        double time;
        Drift drift;
      };
      std::vector<Sample> samples;
      const RunResult r = runScene(file, RunOptions{}, [&](const Scene& scene, const State& s) {
        if (s.step % every == 0 || s.step == steps) samples.push_back({s.step, s.time, measure->drift(scene, s)});
      });
      for (const Sample& x : samples) {
        csv << p.name << p.title << m.label << dt << x.step << x.time << x.drift.energy << x.drift.momentum
            << x.drift.angularMomentum << outcomeName(r.outcome);
        if (Status s = csv.endRow(); !s) return s;
      }
      if (options.log) *options.log << "." << std::flush;
    }
    if (options.log) *options.log << "\n";
  }
  return Status::ok();
}

}  // namespace fosssim::study
