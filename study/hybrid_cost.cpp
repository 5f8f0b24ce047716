// The hybrid handler's cost on a dense pile, against maxiters: how often the impulse passes give
// up and the rigid-zone failsafe runs, how large the zones grow, and where the time goes. The same
// pile with the other collision methods is measured alongside, for comparison.
#include "csv.h"
#include "experiments.h"
#include "pile.h"

#include <algorithm>
#include <cmath>

namespace fosssim::study {
namespace {

/// Mean height of the disks' centres: a settled pile sits low; a frozen one stays up.
double meanHeight(const State& s) {
  double sum = 0;
  for (int i = 0; i < s.numParticles(); ++i) sum += at(s.x, i).y();
  return sum / std::max(1, s.numParticles());
}

}  // namespace

Status runHybridCost(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/hybrid.csv",
                          {"method", "collision", "maxiters", "particles", "dt", "steps", "outcome", "wall_per_sim_s",
                           "us_per_step", "integrate_us", "narrow_us", "response_us", "failsafe_us", "failsafe_steps",
                           "failsafe_fraction", "mean_zones", "largest_zone", "mean_failsafe_particles",
                           "most_failsafe_particles", "mean_passes", "collisions_per_step", "overlap_steps",
                           "max_overlap", "kinetic_end", "mean_height_start", "mean_height_end", "cor", "message"});
      !s)
    return s;
  const double dt = 0.002, cor = 0.5;
  const int columns = options.quick ? 3 : 8, rows = options.quick ? 2 : 5;
  std::vector<Method> methods;
  const std::vector<int> iterations =
      options.quick ? std::vector<int>{0, 2} : std::vector<int>{0, 1, 2, 3, 5, 10, 20, 50, 100};
  for (int maxiters : iterations) {
    CollisionChoice c{"hybrid"};
    c.cor = cor;
    c.maxIterations = maxiters;
    methods.push_back(Method{"hybrid", "symplectic-euler", c});
  }
  for (const Method& m : collisionMethods())
    if (m.collision.type != "hybrid" && (!options.quick || m.collision.type == "simple")) {
      Method copy = m;
      copy.collision.cor = cor;
      methods.push_back(copy);
    }
  if (options.log) *options.log << "hybrid cost: " << columns * rows << " disks" << std::flush;
  for (const Method& m : methods) {
    SceneFile file;
    if (Status s = pileScene(m, dt, columns, rows).build("pile.xml", file); !s) return s;
    RunOptions ro;
    ro.phaseTimings = true;
    const RunResult r = runScene(file, ro);
    const double steps = std::max(1L, r.steps);
    const double perStep = 1e6 / steps;
    const bool hybrid = m.collision.type == "hybrid";
    csv << m.label << m.collision.type << (hybrid ? static_cast<double>(m.collision.maxIterations) : kNotApplicable)
        << file.scene.numParticles() << dt << r.steps << outcomeName(r.outcome) << r.stepSeconds / r.final.time
        << r.stepSeconds * perStep << r.phases.integrate * perStep << r.phases.narrowPhase * perStep
        << r.phases.response * perStep << r.phases.failsafe * perStep << r.failsafeSteps
        << (hybrid ? r.failsafeSteps / steps : kNotApplicable)
        // Zone counts and passes come from the handler's StepStats; zero means it does not count them.
        << (r.zoneSum > 0 ? static_cast<double>(r.zoneSum) / r.failsafeSteps : kNotApplicable)
        << (r.largestZone > 0 ? static_cast<double>(r.largestZone) : kNotApplicable)
        << (r.failsafeSteps ? static_cast<double>(r.failsafeParticles) / r.failsafeSteps : kNotApplicable)
        << static_cast<long>(r.mostFailsafeParticles)
        << (hybrid && r.impulsePasses > 0 ? r.impulsePasses / steps : kNotApplicable) << r.collisions / steps
        << r.overlap.stepsWithOverlap << r.overlap.deepest << kineticEnergy(file.scene, r.final.v)
        << meanHeight(file.initial) << meanHeight(r.final) << file.scene.collision.cor << r.message;
    if (Status s = csv.endRow(); !s) return s;
    if (options.log) *options.log << "." << std::flush;
  }
  if (options.log) *options.log << "\n";
  return Status::ok();
}

}  // namespace fosssim::study
