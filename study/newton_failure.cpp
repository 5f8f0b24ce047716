// Where implicit Euler's Newton iteration fails: the two-body orbit started at apoapsis with a
// range of eccentricities (the higher, the closer and stiffer the periapsis) over a sweep of dt.
// A step fails when Newton has not converged in 100 iterations; the simulator reports it and the
// run stops (outcome "solver-failure"). The stiffness that matters is the pull's at periapsis,
// w_p = sqrt(mu / r_p^3), so the chart puts dt w_p on its axis. Each run also records Newton's
// iterations per step (StepStats::newtonIterations): their mean over the steps done and the most
// in one step (the failed step's kMaxNewtonIterations included).
#include "closed_forms.h"
#include "csv.h"
#include "experiments.h"

#include <cmath>
#include <limits>

namespace fosssim::study {

Status runNewtonFailure(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/newton_failure.csv",
                          {"integrator", "mu", "apoapsis", "periods", "eccentricity", "periapsis", "omega_periapsis",
                           "dt", "dt_omega", "steps", "steps_done", "outcome", "min_separation", "mean_iterations",
                           "max_iterations", "message"});
      !s)
    return s;
  const double mu = 1.0, mass = 0.5, periods = 2;  // G = 1, two bodies of 0.5: mu = G (m1 + m2) = 1
  std::vector<double> eccentricities = {0.2, 0.4, 0.6, 0.8, 0.9};
  std::vector<double> dts = {0.05, 0.02, 0.01, 0.005, 0.002, 0.001};
  if (options.quick) eccentricities = {0.4}, dts = {0.05, 0.01};
  for (const char* integrator : {"implicit-euler", "linearized-implicit-euler"}) {
    if (options.log) *options.log << "newton: " << integrator << std::flush;
    for (double e : eccentricities) {
      // At apoapsis r = 1 the speed is sqrt(mu (1 - e) / r), across the separation.
      const Vec2 r0(1, 0), v0(0, std::sqrt(mu * (1 - e)));
      const KeplerOrbit orbit(mu, r0, v0);
      const double rp = orbit.semiMajorAxis() * (1 - orbit.eccentricity());
      const double wp = std::sqrt(mu / (rp * rp * rp));
      for (double dt : dts) {
        SceneBuilder x;
        x.duration(periods * orbit.period()).integrator(integrator, dt);
        const int a = x.particle(-0.5 * r0, -0.5 * v0, mass, false, 0.001);
        const int b = x.particle(0.5 * r0, 0.5 * v0, mass, false, 0.001);
        x.gravitational(a, b, 1.0);
        SceneFile file;
        if (Status s = x.build("orbit.xml", file); !s) return s;
        double closest = r0.norm();
        RunOptions run;
        run.measureOverlap = false;
        const RunResult r = runScene(file, run, [&](const Scene&, const State& s) {
          closest = std::min(closest, (at(s.x, 1) - at(s.x, 0)).norm());
        });
        csv << integrator << mu << r0.norm() << periods << orbit.eccentricity() << rp << wp << dt << dt * wp
            << file.scene.numSteps() << r.steps << outcomeName(r.outcome) << closest
            << (r.steps > 0 ? static_cast<double>(r.newtonIterations) / static_cast<double>(r.steps)
                            : std::numeric_limits<double>::quiet_NaN())
            << r.mostNewtonIterations << r.message;
        if (Status s = csv.endRow(); !s) return s;
      }
      if (options.log) *options.log << "." << std::flush;
    }
    if (options.log) *options.log << "\n";
  }
  return Status::ok();
}

}  // namespace fosssim::study
