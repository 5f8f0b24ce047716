// Throughput of complete CCD queries (build the polynomials, solve, contact vector), in
// queries per second on one core. Not a test: run the Release build and read the figures.
//
// Inputs imitate a simulation step (dt = 0.01, speeds up to ~5, particles of radius
// 0.02-0.1, edges 0.2-1 long): "scene" pairs are spread over a 2x2 box, so most are far
// apart, as in an all-pairs sweep; "near" pairs are placed within reach of each other, so
// every polynomial is built and most of them must be rooted. Each kind is timed through
// the fast path (no log) and the logging path (all polynomials returned).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <vector>

#include "fosssim/math/ccd.h"

using namespace fosssim::math;

namespace {

constexpr int kInputs = 4096;    // distinct inputs, cycled (fits in L2)
constexpr int kSweeps = 400;     // passes over the inputs per timed repeat
constexpr int kRepeats = 5;      // best of

std::mt19937 rng(2024);
double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
Vec2 point(double extent) { return Vec2(uniform(-extent, extent), uniform(-extent, extent)); }
Vec2 displacement() { return 0.01 * point(5.0); }
Vec2 around(const Vec2& c, double reach) { return c + point(reach); }

PPInput makePP(bool near) {
  PPInput in;
  in.x1 = point(1.0);
  in.r1 = uniform(0.02, 0.1);
  in.r2 = uniform(0.02, 0.1);
  in.x2 = near ? around(in.x1, 1.5 * (in.r1 + in.r2)) : point(1.0);
  in.d1 = displacement();
  in.d2 = displacement();
  return in;
}

PEInput makePE(bool near) {
  PEInput in;
  in.x2 = point(1.0);
  const double angle = uniform(0.0, 6.283185307179586);
  in.x3 = in.x2 + uniform(0.2, 1.0) * Vec2(std::cos(angle), std::sin(angle));
  in.rv = uniform(0.02, 0.1);
  in.re = uniform(0.015, 0.05);
  in.x1 = near ? around(in.x2 + uniform(0.0, 1.0) * (in.x3 - in.x2), 1.5 * (in.rv + in.re)) : point(1.0);
  in.d1 = displacement();
  in.d2 = displacement();
  in.d3 = displacement();
  return in;
}

PHInput makePH(bool near) {
  PHInput in;
  in.m = point(1.0);
  in.p = point(1.0);
  in.r = uniform(0.02, 0.1);
  const Vec2 unit = in.m.normalized();
  in.x1 = near ? in.p + uniform(-1.5, 1.5) * in.r * unit + 0.5 * Vec2(-unit.y(), unit.x()) * uniform(-1, 1)
               : point(1.0);
  in.d1 = displacement();
  return in;
}

// CPU time of this thread, not wall time: the figure is per core, and must not depend on
// what else the (shared, 2-core) machine is running.
double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

template <class Input, class Query>
void run(const char* name, const std::vector<Input>& inputs, Query query) {
  volatile double sink = 0.0;
  int hits = 0;
  for (const Input& in : inputs) hits += query(in, &sink);  // warm-up, and the hit rate
  double best = 1e300;
  for (int r = 0; r < kRepeats; ++r) {
    const double start = cpuSeconds();
    for (int s = 0; s < kSweeps; ++s)
      for (const Input& in : inputs) query(in, &sink);
    const double seconds = cpuSeconds() - start;
    best = std::min(best, seconds);
  }
  const double perSecond = static_cast<double>(kSweeps) * inputs.size() / best;
  std::printf("%-26s %8.2f M queries/s  %6.1f ns/query  (hits %4.1f%%)\n", name, perSecond / 1e6,
              1e9 / perSecond, 100.0 * hits / inputs.size());
}

template <class Input, class Make, class Detect>
void kind(const char* label, Make make, Detect detect) {
  for (bool near : {false, true}) {
    std::vector<Input> inputs;
    for (int i = 0; i < kInputs; ++i) inputs.push_back(make(near));
    char name[64];
    std::snprintf(name, sizeof name, "%s %s fast", label, near ? "near " : "scene");
    run(name, inputs, [&](const Input& in, volatile double* sink) {
      Contact c;
      const bool hit = detect(in, &c, nullptr);
      if (hit) *sink = *sink + c.tau;
      return hit;
    });
    std::snprintf(name, sizeof name, "%s %s log", label, near ? "near " : "scene");
    PairPolynomials log;  // reused, as the simulator's per-pair scratch would be
    run(name, inputs, [&](const Input& in, volatile double* sink) {
      Contact c;
      const bool hit = detect(in, &c, &log);
      *sink = *sink + log.polys[0].c[0] + (hit ? c.tau : 0.0);
      return hit;
    });
  }
}

}  // namespace

int main() {
  kind<PPInput>("PP", makePP, [](const PPInput& in, Contact* c, PairPolynomials* l) { return detectPP(in, c, l); });
  kind<PEInput>("PE", makePE, [](const PEInput& in, Contact* c, PairPolynomials* l) { return detectPE(in, c, l); });
  kind<PHInput>("PH", makePH, [](const PHInput& in, Contact* c, PairPolynomials* l) { return detectPH(in, c, l); });
  return 0;
}
