// "Model no more than a scene needs": for representative scenes, which parts of the simulator
// the scene uses (forces, integrator, pair kinds the collision code visits) and what each costs
// per step. Forces are timed by wrapping them (timed_force.h); the integrator's solve is the rest
// of its phase; detection, response and failsafe come from the simulator's own StepStats.
#include "csv.h"
#include "experiments.h"
#include "number_text.h"
#include "pile.h"
#include "robustness.h"
#include "stability.h"
#include "timed_force.h"

#include <algorithm>
#include <cmath>

namespace fosssim::study {
namespace {

struct ProfileCase {
  std::string scene;  ///< what the scene is
  SceneBuilder builder;
  Method method;
};

Method find(const std::vector<Method>& methods, const std::string& label) {
  for (const Method& m : methods)
    if (m.label == label) return m;
  return methods.front();
}

ProfileCase fromProblem(const std::vector<Problem>& problems, const std::string& name, const std::string& label,
                        double dt) {
  for (const Problem& p : problems)
    if (p.name == name) {
      const Method m = find(p.methods, label);
      return ProfileCase{p.title, p.scene(m, dt), m};
    }
  return ProfileCase{name, SceneBuilder(), Method{}};
}

std::vector<ProfileCase> cases(bool quick) {
  std::vector<Problem> problems = integratorProblems(true);
  for (Problem& p : collisionProblems(true)) problems.push_back(std::move(p));
  std::vector<ProfileCase> out = {
      fromProblem(problems, "projectile", "symplectic-euler", 1e-3),
      fromProblem(problems, "spring", "symplectic-euler", 1e-3),
      fromProblem(problems, "spring", "implicit-euler", 1e-3),
      fromProblem(problems, "orbit", "symplectic-euler", 1e-3),
      fromProblem(problems, "disks", "continuous-time", 1e-3),
      fromProblem(problems, "bounce-cor0.5", "hybrid", 1e-3),
      fromProblem(problems, "cradle", "continuous-time", 1e-3),
      fromProblem(problems, "billiards", "simple", 1e-3),
      fromProblem(problems, "billiards", "continuous-time", 1e-3),
      fromProblem(problems, "billiards", "hybrid", 1e-3),
      fromProblem(problems, "billiards", "penalty k=1e4", 1e-3),
  };
  for (const char* integrator : {"symplectic-euler", "implicit-euler", "linearized-implicit-euler"}) {
    const Method m{integrator, integrator, CollisionChoice{}};
    constexpr int bobs = 10;
    constexpr double k = 100;
    out.push_back(ProfileCase{"Row of " + std::to_string(bobs) + " springs (k = " + numberText(k) + ")",
                              springRow(bobs, k, integrator, 1e-3), m});
  }
  const std::vector<Method> collision = collisionMethods();
  for (const char* label : {"simple", "continuous-time", "hybrid"}) {
    const Method m = find(collision, label);
    constexpr double speed = 10;
    out.push_back(
        ProfileCase{"Disk against a thin edge (" + numberText(speed) + " m/s)", edgeThrowScene(m, speed, 1e-4), m});
  }
  for (const char* label : {"hybrid", "penalty k=1e4"}) {
    Method m = find(collision, label);
    m.collision.cor = 0.5;
    const int columns = quick ? 3 : 8, rows = quick ? 2 : 5;
    out.push_back(ProfileCase{"Dense pile (" + std::to_string(columns * rows) + " disks in a box)",
                              pileScene(m, 0.002, columns, rows), m});
  }
  if (quick) out.resize(4);
  return out;
}

/// Pairs the collision code visits per detection pass, by kind: every particle pair, every
/// particle with every edge it is not an end of, every particle with every half-plane (no
/// broad phase prunes them). The penalty force visits the same pairs every force evaluation.
void pairCounts(const Scene& scene, long counts[3]) {
  const long n = scene.numParticles();
  counts[0] = n * (n - 1) / 2;
  counts[1] = (n - 2) * static_cast<long>(scene.edges.size());  // an edge's two ends are excluded
  counts[2] = n * static_cast<long>(scene.halfplanes.size());
}

}  // namespace

Status runProfile(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/profile.csv",
                          {"scene", "method", "integrator", "collision", "particles", "edges", "halfplanes", "forces",
                           "pp_pairs", "pe_pairs", "ph_pairs", "pp_queries", "pe_queries", "ph_queries", "steps",
                           "total_us", "forces_us", "force_breakdown", "jacobians_us", "solve_us", "broad_us",
                           "narrow_us", "response_us", "failsafe_us", "collision_other_us", "collisions_per_step",
                           "failsafe_fraction"});
      !s)
    return s;
  const double overhead = clockOverhead();
  for (const ProfileCase& c : cases(options.quick)) {
    if (options.log) *options.log << "profile: " << c.scene << ", " << c.method.label << "\n";
    // The run with the least total step time of a few: phases of an undisturbed run.
    RunResult best;
    std::vector<ForceTime> bestForces;
    std::vector<std::string> keywords;
    SceneFile file;
    double spent = 0;
    for (int repeat = 0; repeat < 3 && (repeat == 0 || spent < 1.0); ++repeat) {
      if (Status s = c.builder.build("profile.xml", file); !s) return s;
      std::vector<ForceTime> times(file.scene.forces.size());
      keywords.clear();
      for (size_t f = 0; f < file.scene.forces.size(); ++f) {
        keywords.push_back(file.scene.forces[f]->keyword());
        file.scene.forces[f] = std::make_unique<TimedForce>(std::move(file.scene.forces[f]), &times[f]);
      }
      RunOptions ro;
      ro.phaseTimings = true;
      ro.measureOverlap = false;
      if (options.quick) ro.steps = std::min(200L, file.scene.numSteps());
      RunResult r = runScene(file, ro);
      spent += r.stepSeconds;
      if (repeat == 0 || r.phases.total < best.phases.total) {
        best = std::move(r);
        bestForces = times;
      }
    }
    const double steps = std::max(1L, best.steps), us = 1e6 / steps;
    const StepStats& p = best.phases;
    double gradient = 0, jacobian = 0;
    long calls = 0;
    std::string forces, breakdown;
    for (size_t f = 0; f < bestForces.size(); ++f) {
      gradient += bestForces[f].gradient;
      jacobian += bestForces[f].jacobian;
      calls += bestForces[f].calls + bestForces[f].jacobianCalls;
      forces += (f ? "+" : "") + keywords[f];
      char item[96];
      std::snprintf(item, sizeof item, "%s%s:%.4g", f ? ";" : "", keywords[f].c_str(), bestForces[f].gradient * us);
      breakdown += item;
    }
    // The integrator phase also paid for the wrappers' clock reads; they are no part of the solve.
    const double solve = std::max(0.0, p.integrate - gradient - jacobian - calls * overhead);
    const double collision = p.total - p.integrate;
    const double other = std::max(0.0, collision - p.broadPhase - p.narrowPhase - p.response - p.failsafe);
    long pairs[3];
    pairCounts(file.scene, pairs);
    csv << c.scene << c.method.label << c.method.integrator << c.method.collision.type
        << file.scene.numParticles() << static_cast<long>(file.scene.edges.size())
        << static_cast<long>(file.scene.halfplanes.size()) << forces << pairs[0] << pairs[1] << pairs[2]
        << p.queries[0] / steps << p.queries[1] / steps << p.queries[2] / steps << best.steps << p.total * us
        << gradient * us << breakdown << jacobian * us << solve * us << p.broadPhase * us << p.narrowPhase * us
        << p.response * us << p.failsafe * us << other * us << best.collisions / steps
        << (c.method.collision.type == "hybrid" ? best.failsafeSteps / steps : kNotApplicable);
    if (Status s = csv.endRow(); !s) return s;
  }
  return Status::ok();
}

}  // namespace fosssim::study
