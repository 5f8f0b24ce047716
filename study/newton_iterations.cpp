// How many Newton iterations implicit Euler takes per step, against the time step and the
// stiffness. A particle (unit mass) held between two fixed anchors at (-1, 0) and (1, 0) by two
// springs of rest length 1, started off the line between them at (0.3, 0.8) and moving at 2 m/s
// along it: the springs' directions differ and turn within each step, so the force is nonlinear in
// the unknown velocity, the more so the larger the step and the stiffer the springs. (One spring
// alone would not do: implicit Euler's solution and every Newton iterate stay on the ray from the
// anchor through x + h v, along which a spring's force is affine in the length, so Newton is done
// after one update.) The same runs with rest length 0 (F = -k (x - a) per spring, linear) are the
// control: Newton's first update solves the step exactly and the second is round-off, so they take
// 2 iterations per step (1 once the motion has died out below the tolerance). The counts come
// from StepStats::newtonIterations (Simulator::stats()).
#include "csv.h"
#include "experiments.h"
#include "run.h"

#include "fosssim/core/forces.h"
#include "fosssim/core/integrator.h"

#include <cmath>
#include <limits>

namespace fosssim::study {
namespace {

constexpr double kMass = 1.0, kAnchor = 1.0, kSpeed = 2.0, kDuration = 2.0;
const Vec2 kStart(0.3, 0.8);

/// The particle between anchors at (-kAnchor, 0) and (kAnchor, 0), at kStart, moving at kSpeed along x.
SceneFile twoSpringScene(double k, double restLength, double dt) {
  SceneFile file;
  Scene& scene = file.scene;
  addParticle(scene, kMass, false, 0.05);
  addParticle(scene, 1.0, true, 0.05);
  addParticle(scene, 1.0, true, 0.05);
  for (int anchor : {1, 2}) {
    scene.edges.push_back(Edge{0, anchor, 0.01});
    scene.forces.push_back(std::make_unique<SpringForce>(0, anchor, k, restLength, 0.0));
  }
  scene.integrator = "implicit-euler";
  scene.dt = dt;
  scene.duration = kDuration;
  finalizeScene(scene);
  file.initial.x = VecX::Zero(6);
  file.initial.v = VecX::Zero(6);
  file.initial.x << kStart.x(), kStart.y(), -kAnchor, 0, kAnchor, 0;
  file.initial.v[0] = kSpeed;
  return file;
}

}  // namespace

RunResult runTwoSprings(double k, double restLength, double dt) {
  RunOptions run;
  run.measureOverlap = false;
  return runScene(twoSpringScene(k, restLength, dt), run);
}

Status runNewtonIterations(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/newton_iterations.csv",
                          {"rest_length", "k", "mass", "anchor", "start_x", "start_y", "speed", "omega", "dt",
                           "dt_omega", "steps", "steps_done", "outcome", "mean_iterations", "max_iterations",
                           "tolerance", "iteration_limit", "message"});
      !s)
    return s;
  std::vector<double> stiffnesses = {1e1, 1e2, 1e3, 1e4, 1e5};
  std::vector<double> dts = {1e-4, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1};
  if (options.quick) stiffnesses = {1e3}, dts = {1e-3, 1e-2};
  if (options.log) *options.log << "newton iterations: " << std::flush;
  for (double restLength : {1.0, 0.0}) {
    for (double k : stiffnesses) {
      const double omega = std::sqrt(2 * k / kMass);  // the stiffer mode: along the anchors' line
      for (double dt : dts) {
        const RunResult r = runTwoSprings(k, restLength, dt);
        const double mean = r.steps > 0 ? static_cast<double>(r.newtonIterations) / static_cast<double>(r.steps)
                                        : std::numeric_limits<double>::quiet_NaN();
        csv << restLength << k << kMass << kAnchor << kStart.x() << kStart.y() << kSpeed << omega << dt << dt * omega
            << twoSpringScene(k, restLength, dt).scene.numSteps() << r.steps << outcomeName(r.outcome) << mean
            << r.mostNewtonIterations << kNewtonRelativeTolerance << kMaxNewtonIterations << r.message;
        if (Status s = csv.endRow(); !s) return s;
      }
      if (options.log) *options.log << "." << std::flush;
    }
  }
  if (options.log) *options.log << "\n";
  return Status::ok();
}

}  // namespace fosssim::study
