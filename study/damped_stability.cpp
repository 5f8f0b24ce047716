#include "damped_stability.h"

#include "csv.h"
#include "experiments.h"
#include "problems.h"
#include "run.h"
#include "scene_builder.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace fosssim::study {

double dampedStabilityLimit(const std::string& integrator, double omega, double gamma) {
  if (integrator == "explicit-euler") {
    if (gamma <= 0) return kNotApplicable;  // never stable
    if (gamma <= omega) return 2 * gamma / (omega * omega);
    return 2 / (gamma + std::sqrt(gamma * gamma - omega * omega));
  }
  if (integrator == "symplectic-euler") return 2 / (gamma + std::sqrt(gamma * gamma + omega * omega));
  return kNotApplicable;  // the implicit methods: A-stable on a linear damped spring
}

std::vector<double> dampedGrid(double omega) {
  std::vector<double> grid;
  for (double s = 0.01; s <= 100 * 1.0000001; s *= 1.01) grid.push_back(s / omega);
  return grid;
}

namespace {

constexpr double kRest = 1.0, kStretch = 1e-3;
// The spring stays linear while the bob stays on its side of the anchor (|u| < kRest): a growth
// of the energy by 1e5 (the amplitude by 316, to 0.32) is far from that, and far above what the
// phase of a stable run can show (symplectic Euler's energy swings by (2 + w h)/(2 - w h) within
// a period, 200 at w h = 1.98).
constexpr double kGrown = 1e5, kDecayed = 1e-12, kNeutral = 1.01;

}  // namespace

DampedProbe probeDamped(const std::string& integrator, double omega, double gamma, double dt, long steps) {
  DampedProbe out;
  const double k = omega * omega, b = 2 * gamma;  // unit mass
  SceneBuilder x;
  x.integrator(integrator, dt).duration(steps * dt);
  const int anchor = x.particle(Vec2(0, 0), Vec2(0, 0), 1.0, true, 0.05);
  const int bob = x.particle(Vec2(kRest + kStretch, 0), Vec2(0, 0), 1.0, false, 0.05);
  x.spring(x.edge(anchor, bob), k, kRest, b);
  SceneFile file;
  std::unique_ptr<Simulator> sim;
  Status s = x.build("damped-spring.xml", file);
  if (s) s = Simulator::create(file.scene, studySimulatorOptions(), sim);
  if (!s) {
    out.message = s.message();
    return out;
  }
  State state = file.initial;
  auto energy = [&] {
    const double u = at(state.x, 1).norm() - kRest;
    return 0.5 * at(state.v, 1).squaredNorm() + 0.5 * k * u * u;
  };
  const double e0 = energy();
  // Maxima of the first and the second half: each half holds many periods of the slowest phase
  // the energy shows near a limit, so its maximum is the envelope's at that half's start or end.
  double firstHalf = 0, secondHalf = 0;
  for (long n = 1; n <= steps; ++n) {
    if (Status st = sim->step(file.scene, state); !st) {
      out.message = st.message();
      out.steps = n - 1;
      out.growth = INFINITY;
      return out;
    }
    const double e = energy();
    out.steps = n;
    if (!(e < kGrown * e0)) {  // also NaN
      out.growth = std::log(e / e0) / n;
      return out;
    }
    if (e < kDecayed * e0) {
      out.stable = true;
      out.growth = std::log(e / e0) / n;
      return out;
    }
    double& half = 2 * n <= steps ? firstHalf : secondHalf;
    half = std::max(half, e);
  }
  // A neutral mode (undamped symplectic Euler, |eigenvalue| = 1) keeps its envelope: the halves'
  // maxima then differ by how close their samples come to the envelope, far less than 1 %.
  out.stable = secondHalf <= kNeutral * firstHalf;
  out.growth = std::log(secondHalf / firstHalf) / (steps / 2.0);
  return out;
}

double DampedLimit::largestStable() const { return index >= 0 ? grid[index] : kNotApplicable; }

double DampedLimit::smallestUnstable() const {
  return index + 1 < static_cast<int>(grid.size()) ? grid[index + 1] : kNotApplicable;
}

DampedLimit findDampedLimit(const std::string& integrator, double omega, double gamma, long steps) {
  DampedLimit out;
  out.grid = dampedGrid(omega);
  auto stable = [&](int i) {
    ++out.probes;
    return probeDamped(integrator, omega, gamma, out.grid[i], steps).stable;
  };
  int lo = 0, hi = static_cast<int>(out.grid.size()) - 1;
  if (stable(hi)) {
    out.index = hi;
    out.capped = true;
    return out;
  }
  if (!stable(lo)) return out;  // index -1
  while (hi - lo > 1) {  // grid[lo] stable, grid[hi] unstable
    const int mid = (lo + hi) / 2;
    (stable(mid) ? lo : hi) = mid;
  }
  out.index = lo;
  return out;
}

Status runDampedStability(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/damped_stability.csv",
                          {"integrator", "omega", "zeta", "gamma", "largest_stable_dt", "smallest_unstable_dt",
                           "capped", "none_stable", "grid_min_dt", "grid_max_dt", "grid_ratio", "closed_form_dt",
                           "probes", "steps", "neutral_margin"});
      !s)
    return s;
  const double omega = 10;  // k = 100 on a unit mass
  const long steps = options.quick ? 4000 : 50000;
  std::vector<double> zetas = {0, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5};
  if (options.quick) zetas = {0, 0.5, 2};
  for (const Method& m : integratorMethods()) {
    if (options.log) *options.log << "stability: damped spring, " << m.label << std::flush;
    for (double zeta : zetas) {
      const double gamma = zeta * omega;
      const DampedLimit limit = findDampedLimit(m.integrator, omega, gamma, steps);
      csv << m.integrator << omega << zeta << gamma << limit.largestStable() << limit.smallestUnstable()
          << (limit.capped ? 1L : 0L) << (limit.index < 0 ? 1L : 0L) << limit.grid.front() << limit.grid.back()
          << limit.grid[1] / limit.grid[0] << dampedStabilityLimit(m.integrator, omega, gamma)
          << static_cast<long>(limit.probes) << steps << kNeutral - 1;
      if (Status s = csv.endRow(); !s) return s;
      if (options.log) *options.log << "." << std::flush;
    }
    if (options.log) *options.log << "\n";
  }
  return Status::ok();
}

}  // namespace fosssim::study
