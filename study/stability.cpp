#include "stability.h"

#include "csv.h"
#include "experiments.h"

#include <cmath>

namespace fosssim::study {

SceneBuilder springRow(int bobs, double k, const std::string& integrator, double dt) {
  SceneBuilder x;
  x.integrator(integrator, dt).duration(1.0);  // the probe sets its own number of steps
  int previous = x.particle(Vec2(0, 0), Vec2(0, 0), 1.0, true, 0.05);
  for (int i = 1; i <= bobs; ++i) {
    // Small enough that the amplitude can grow 1000-fold (energy 1e6-fold, the blow-up mark)
    // before a bob could pass its neighbour, where |x_j - x_i| stops being linear.
    const double shift = (i % 2 ? 1e-4 : -1e-4);
    const int bob = x.particle(Vec2(i + shift, 0), Vec2(0, 0), 1.0, false, 0.05);
    x.spring(x.edge(previous, bob), k, 1.0);
    previous = bob;
  }
  return x;
}

double highestFrequency(int bobs, double k) {
  return 2 * std::sqrt(k) * std::sin((2 * bobs - 1) * M_PI / (4 * bobs + 2));
}

namespace {
/// A probe runs this many periods of the fastest mode (at least 200 steps)...
constexpr double kHorizonPeriods = 10;
/// ...and the bisection on omega dt stops when its bracket's ratio is below this.
constexpr double kBisectionRatio = 1.001;
}  // namespace

long stabilityHorizon(double omegaMax, double dt) {
  const double periods = kHorizonPeriods * 2 * M_PI / omegaMax;
  return std::max(200L, static_cast<long>(std::ceil(periods / dt)));
}

RunResult probeStability(int bobs, double k, const std::string& integrator, double dt) {
  SceneFile file;
  if (Status s = springRow(bobs, k, integrator, dt).build("spring-row.xml", file); !s) {
    RunResult r;
    r.outcome = Outcome::Error;
    r.message = s.message();
    return r;
  }
  RunOptions options;
  options.measureOverlap = false;
  options.steps = stabilityHorizon(highestFrequency(bobs, k), dt);
  return runScene(file, options);
}

StabilityLimit findStabilityLimit(int bobs, double k, const std::string& integrator, double sLow, double sHigh) {
  StabilityLimit out;
  const double omega = highestFrequency(bobs, k);
  auto probe = [&](double s, RunResult* result) {
    ++out.probes;
    RunResult r = probeStability(bobs, k, integrator, s / omega);
    const bool ok = r.ok();
    if (result) *result = std::move(r);
    return ok;
  };
  RunResult failure;
  if (probe(sHigh, &failure)) {
    out.capped = true;
    out.largestStable = sHigh / omega;
    out.smallestUnstable = kNotApplicable;
    return out;
  }
  if (!probe(sLow, &out.failure)) {
    out.largestStable = kNotApplicable;
    out.smallestUnstable = sLow / omega;
    return out;
  }
  double lo = sLow, hi = sHigh;
  while (hi / lo > kBisectionRatio) {
    const double mid = std::sqrt(lo * hi);
    RunResult r;
    if (probe(mid, &r)) {
      lo = mid;
    } else {
      hi = mid;
      failure = std::move(r);
    }
  }
  out.largestStable = lo / omega;
  out.smallestUnstable = hi / omega;
  out.failure = std::move(failure);
  return out;
}

Status runStability(const StudyOptions& options) {
  CsvWriter csv;
  if (Status s = csv.open(options.outDir + "/stability.csv",
                          {"system", "bobs", "integrator", "k", "omega_max", "largest_stable_dt",
                           "smallest_unstable_dt", "capped", "dt_tried_max", "dt_tried_min", "failure",
                           "failure_step", "probes", "horizon_periods", "bisection_ratio", "message"});
      !s)
    return s;
  // omega dt: far below and far above every limit (quick: fewer steps in the lowest probe)
  const double sLow = options.quick ? 1e-1 : 1e-2, sHigh = 1e2;
  std::vector<double> ks;
  for (int e = 0; e <= (options.quick ? 2 : 12); e += (options.quick ? 2 : 1)) ks.push_back(std::pow(10.0, e / 2.0));
  for (int bobs : {1, 10}) {
    const std::string system = bobs == 1 ? "single spring" : "row of " + std::to_string(bobs) + " springs";
    for (const Method& m : integratorMethods()) {
      if (options.log) *options.log << "stability: " << system << ", " << m.label << std::flush;
      for (double k : ks) {
        const double omega = highestFrequency(bobs, k);
        const StabilityLimit limit = findStabilityLimit(bobs, k, m.integrator, sLow, sHigh);
        const bool failed = !std::isnan(limit.smallestUnstable);
        csv << system << bobs << m.integrator << k << omega << limit.largestStable << limit.smallestUnstable
            << (limit.capped ? 1L : 0L) << sHigh / omega << sLow / omega
            << (failed ? outcomeName(limit.failure.outcome) : "") << (failed ? limit.failure.final.step : 0L)
            << limit.probes << kHorizonPeriods << kBisectionRatio << (failed ? limit.failure.message : std::string());
        if (Status s = csv.endRow(); !s) return s;
        if (options.log) *options.log << "." << std::flush;
      }
      if (options.log) *options.log << "\n";
    }
  }
  if (Status s = runDampedStability(options); !s) return s;
  if (Status s = runNewtonFailure(options); !s) return s;
  return runNewtonIterations(options);
}

}  // namespace fosssim::study
