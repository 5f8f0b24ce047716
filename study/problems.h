// The accuracy problems: scenes whose right answer is known independently of the simulator
// (closed_forms.h, conservation laws), each with the methods and time steps the study sweeps and
// the measurement that turns a run into errors.
#pragma once

#include "run.h"
#include "scene_builder.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace fosssim::study {

constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

/// How wrong a run was. Each problem fills what it can know; the rest stays NaN ("does not apply").
struct Metrics {
  double error = kNotApplicable;            ///< the problem's headline error (Problem::errorLabel)
  double position = kNotApplicable;         ///< largest |x - x_exact| at the end [m]
  double velocity = kNotApplicable;         ///< largest |v - v_exact| at the end [m/s]
  double energy = kNotApplicable;           ///< |E_end - E_exact| / E scale (relative), at the end only
  /// The same relative energy error over the whole run: its largest value and its root mean square
  /// over the step ends. An error that oscillates (symplectic Euler's) can be small at the end by
  /// chance; these cannot.
  double energyMax = kNotApplicable;
  double energyRms = kNotApplicable;
  /// Closest approach of the two bodies [m]; for the springs the bob's least coordinate along the
  /// spring's starting line, from the anchor (negative: it passed through the anchor).
  double minSeparation = kNotApplicable;
  double momentum = kNotApplicable;         ///< |P_end - P_0| / sum m|v_0| (relative)
  double angularMomentum = kNotApplicable;  ///< |L_end - L_0| / |L_0| (relative)
  double period = kNotApplicable;           ///< |T_measured - T_exact| / T_exact (relative)
  double contactTime = kNotApplicable;      ///< measured contact time - exact contact time [s]
};

/// Relative errors of one step end against the exact motion: the audit over time. NaN where a
/// problem has no exact value.
struct Drift {
  double energy = kNotApplicable;
  double momentum = kNotApplicable;
  double angularMomentum = kNotApplicable;
};

/// Watches one run and judges it.
class Measurement {
 public:
  virtual ~Measurement() = default;
  /// After every step.
  virtual void step(const Scene&, const State&) {}
  /// At the end of a run that completed.
  virtual Metrics finish(const Scene& scene, const State& initial, const RunResult& run) = 0;
  /// What step() gathered over the run so far (energyMax, energyRms, minSeparation), also for a
  /// run that failed part way.
  virtual Metrics overRun() const { return {}; }
  /// Energy, momentum and angular momentum at this step end against the exact motion's.
  virtual Drift drift(const Scene&, const State&) const { return {}; }
};

/// The relative energy error of every step end, folded into its maximum and root mean square.
class EnergyErrorTrack {
 public:
  void add(double relativeError) {
    max_ = std::max(max_, relativeError);
    sumSquares_ += relativeError * relativeError;
    ++count_;
  }
  void fill(Metrics& m) const {
    if (count_ == 0) return;
    m.energyMax = max_;
    m.energyRms = std::sqrt(sumSquares_ / static_cast<double>(count_));
  }

 private:
  double max_ = 0, sumSquares_ = 0;
  long count_ = 0;
};

struct Problem {
  std::string name;        ///< file-friendly id, e.g. "projectile"
  std::string title;       ///< for charts, e.g. "Projectile under gravity"
  std::string errorLabel;  ///< what Metrics::error measures, with units
  std::string kind;        ///< "integrators" (methods differ by integrator) or "collisions"
  std::vector<Method> methods;
  std::vector<double> dts;
  /// The scene for a method and a time step.
  std::function<SceneBuilder(const Method&, double dt)> scene;
  std::function<std::unique_ptr<Measurement>()> measure;
  double omega = kNotApplicable;          ///< angular frequency of a linear oscillator (springs)
  double exactMinSeparation = kNotApplicable;  ///< the exact closest approach (orbit: periapsis)
  /// The set-up's numbers and the exact answer's (from closed_forms.h), by name, for the report's
  /// table of problems (problems.csv): the page types none of them.
  std::vector<std::pair<std::string, double>> setup;
};

/// A problem with its heading filled in; its maker adds the scene and the measurement.
Problem problemHeading(std::string name, std::string title, std::string errorLabel, std::string kind,
                       std::vector<Method> methods, std::vector<double> dts);

/// Projectile, undamped and damped spring, two-body orbit: every integrator, no collisions.
std::vector<Problem> integratorProblems(bool quick);
/// Elastic disk collision, floor bounce at COR 0, 0.5, 1, Newton's cradle, billiard break: every
/// collision method with symplectic Euler (free flight is exact for every integrator).
std::vector<Problem> collisionProblems(bool quick);

/// The four integrators the study compares (aliases left out).
std::vector<Method> integratorMethods();
/// The collision methods the study compares: simple, continuous-time, hybrid (defaults), hybrid
/// with k = 0 (no penalty layer), and penalty at k = 1e2 (the default), 1e4, 1e6, all with
/// symplectic Euler.
std::vector<Method> collisionMethods();

/// Total momentum sum m_i v_i, and the scale sum m_i |v_i| that makes its error relative.
Vec2 momentum(const Scene& scene, const VecX& v);
double momentumScale(const Scene& scene, const VecX& v);

}  // namespace fosssim::study
