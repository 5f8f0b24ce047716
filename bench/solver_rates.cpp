// fosssim-bench-solver: throughput of complete CCD queries (build the polynomials, solve, contact
// vector) on Google Benchmark, one benchmark per query kind x input set x logging path. Not a
// test: run the Release build and read items_per_second (queries per second of CPU time, one
// core), e.g. build/bench/fosssim-bench-solver --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true. Links fosssim_math only.
//
// Inputs imitate a simulation step (dt = 0.01, speeds up to ~5, particles of radius
// 0.02-0.1, edges 0.2-1 long): "scene" pairs are spread over a 2x2 box, so most are far
// apart, as in an all-pairs sweep; "near" pairs are placed within reach of each other, so
// every polynomial is built and most of them must be rooted. Each kind is timed through
// the fast path (no-log) and the logging path (log: all polynomials returned).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fosssim/math/ccd.h"

using namespace fosssim::math;

namespace {

constexpr int kInputs = 4096;  // distinct inputs, one pass over them per iteration (fits in L2)

std::mt19937 rng;
double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
/// x drawn before y, and every draw in its own statement: a call's arguments and a sum's operands
/// are evaluated in an order the compiler picks (gcc right to left, clang left to right).
Vec2 point(double extent) {
  const double x = uniform(-extent, extent);
  const double y = uniform(-extent, extent);
  return Vec2(x, y);
}
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
  if (near) {
    const double along = uniform(-1.5, 1.5);
    const double across = uniform(-1, 1);
    in.x1 = in.p + along * in.r * unit + 0.5 * Vec2(-unit.y(), unit.x()) * across;
  } else {
    in.x1 = point(1.0);
  }
  in.d1 = displacement();
  return in;
}

// Each input set draws from its own seed, so that a benchmark's inputs do not depend on which
// others ran before it (--benchmark_filter) nor on how often Google Benchmark calls it.
template <class Input, class Make>
std::vector<Input> inputSet(Make make, bool near, unsigned seed) {
  rng.seed(seed);
  std::vector<Input> inputs;
  inputs.reserve(kInputs);
  for (int i = 0; i < kInputs; ++i) inputs.push_back(make(near));
  return inputs;
}

// One iteration is one pass over the input set. The log is reused, as the simulator's per-pair
// scratch would be. Google Benchmark times CPU time of this thread by default: the figure is per
// core, and does not depend on what else the (shared) machine is running.
template <class Input, class Detect>
void queries(benchmark::State& state, const std::vector<Input>& inputs, Detect detect, bool logged) {
  PairPolynomials log;
  PairPolynomials* const logOrNull = logged ? &log : nullptr;
  long hits = 0;
  for (const Input& in : inputs) {  // the hit rate (Google Benchmark warms up on its own)
    Contact c;
    hits += detect(in, &c, logOrNull);
  }
  for (auto _ : state) {
    double sum = 0.0;
    for (const Input& in : inputs) {
      Contact c;
      const bool hit = detect(in, &c, logOrNull);
      sum += (hit ? c.tau : 0.0) + (logged ? log.polys[0].c[0] : 0.0);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(inputs.size()));
  state.counters["hits%"] = 100.0 * static_cast<double>(hits) / static_cast<double>(inputs.size());
}

// Registers <label>/{scene,near}/{no-log,log}.
template <class Input, class Make, class Detect>
void registerKind(const std::string& label, unsigned seed, Make make, Detect detect) {
  for (bool near : {false, true}) {
    for (bool logged : {false, true}) {
      const std::string name = label + (near ? "/near" : "/scene") + (logged ? "/log" : "/no-log");
      const unsigned setSeed = seed + (near ? 1 : 0);
      benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
        queries(state, inputSet<Input>(make, near, setSeed), detect, logged);
      });
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  registerKind<PPInput>("PP", 2024, makePP,
                        [](const PPInput& in, Contact* c, PairPolynomials* l) { return detectPP(in, c, l); });
  registerKind<PEInput>("PE", 2026, makePE,
                        [](const PEInput& in, Contact* c, PairPolynomials* l) { return detectPE(in, c, l); });
  registerKind<PHInput>("PH", 2028, makePH,
                        [](const PHInput& in, Contact* c, PairPolynomials* l) { return detectPH(in, c, l); });
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
