#include "query_rates.h"

#include "bench_scenes.h"

#include "../src/core/collision/continuous_detection.h"
#include "../src/core/collision/pair_candidates.h"
#include "fosssim/core/integrator.h"
#include "fosssim/core/simulator.h"

#include <algorithm>
#include <ctime>
#include <random>

namespace fosssim::bench {
namespace {

constexpr int kRepeats = 5;
constexpr double kQueriesPerRepeat = 4e6;

/// CPU time of this thread: the rate is per core whatever else the machine runs.
double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// A scene and one step's motion, with the pairs to query.
struct Workload {
  Scene scene;
  VecX qs, qe;
  std::vector<uint64_t> keys;
};

QueryRate rate(const std::string& name, const Workload& w) {
  QueryRate q;
  q.name = name + " (" + std::to_string(w.keys.size()) + " pairs)";
  if (w.keys.empty()) return q;
  const ContinuousDetector detector(math::DetectionRules{});
  Collision hit;
  auto sweep = [&]() {
    long hits = 0;
    for (uint64_t key : w.keys) {
      const int i = keyParticle(key), other = keyOther(key);
      hits += keyKind(key) == PairKind::ParticleParticle
                  ? detector.particleParticle(w.scene, w.qs, w.qe, i, other, hit, nullptr)
                  : detector.particleEdge(w.scene, w.qs, w.qe, i, other, hit, nullptr);
    }
    return hits;
  };
  q.hitRate = static_cast<double>(sweep()) / static_cast<double>(w.keys.size());
  const long sweeps = std::max<long>(1, static_cast<long>(kQueriesPerRepeat / static_cast<double>(w.keys.size())));
  double best = 1e300;
  volatile long sink = 0;
  for (int r = 0; r < kRepeats; ++r) {
    const double start = cpuSeconds();
    for (long s = 0; s < sweeps; ++s) sink = sink + sweep();
    best = std::min(best, cpuSeconds() - start);
  }
  q.perSecond = static_cast<double>(sweeps) * static_cast<double>(w.keys.size()) / best;
  return q;
}

/// The candidate pairs of `kind` the broad phase finds in `scene` after `steps` steps.
Workload fromScene(const std::string& scene, int n, long steps, PairKind kind) {
  BenchScene s;
  makeScene(scene, n, "hybrid", 1, s);
  std::unique_ptr<Simulator> sim;
  Workload w;
  if (!Simulator::create(s.scene, {}, sim)) return w;
  State state = s.state;
  for (long k = 0; k < steps; ++k)
    if (!sim->step(s.scene, state)) return w;
  // The next step's motion: the integrator's prediction, as the handlers see it.
  w.qs = state.x;
  if (!findIntegrator(s.scene.integrator)->make()->step(s.scene, state, s.scene.dt)) return w;
  w.qe = state.x;
  w.scene = std::move(s.scene);
  PairCandidates candidates;
  candidates.build(w.scene, w.qs, w.qe);
  std::vector<int> row;
  for (int i = 0; i < w.scene.numParticles(); ++i) {
    row.clear();
    if (kind == PairKind::ParticleParticle) candidates.particlesOf(i, -1, row);
    else candidates.edgesOf(i, -1, row);
    for (int j : row) w.keys.push_back(pairKey(i, kind, j));
  }
  return w;
}

/// Pairs placed within reach, as in solver_rates.cpp: most must be rooted.
Workload nearPairs(PairKind kind, int count) {
  std::mt19937 rng(2024);
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  // x drawn before y, and every draw in its own statement: a call's arguments and a sum's operands are
  // evaluated in an order the compiler picks (gcc right to left, clang left to right).
  auto point = [&](double extent) {
    const double x = u(-extent, extent);
    const double y = u(-extent, extent);
    return Vec2(x, y);
  };
  Workload w;
  const int per = kind == PairKind::ParticleParticle ? 2 : 3;
  w.qs.resize(2 * per * count);
  w.qe.resize(2 * per * count);
  for (int k = 0; k < count; ++k) {
    const int p = per * k;
    const double r1 = u(0.02, 0.1), r2 = u(0.02, 0.1);
    addParticle(w.scene, 1.0, false, r1);
    addParticle(w.scene, 1.0, false, r2);
    at(w.qs, p) = point(1.0);
    if (kind == PairKind::ParticleParticle) {
      at(w.qs, p + 1) = at(w.qs, p) + point(1.5 * (r1 + r2));
    } else {
      addParticle(w.scene, 1.0, false, r2);
      const double angle = u(0, 6.283185307179586), re = u(0.015, 0.05);
      at(w.qs, p + 1) = point(1.0);
      at(w.qs, p + 2) = at(w.qs, p + 1) + u(0.2, 1.0) * Vec2(std::cos(angle), std::sin(angle));
      const double along = u(0, 1);
      const Vec2 off = point(1.5 * (r1 + re));
      at(w.qs, p) = at(w.qs, p + 1) + along * (at(w.qs, p + 2) - at(w.qs, p + 1)) + off;
      w.scene.edges.push_back(Edge{p + 1, p + 2, re});
    }
    for (int m = 0; m < per; ++m) at(w.qe, p + m) = at(w.qs, p + m) + 0.01 * point(5.0);
    w.keys.push_back(pairKey(p, kind, kind == PairKind::ParticleParticle ? p + 1 : k));
  }
  return w;
}

}  // namespace

std::vector<QueryRate> measureQueryRates() {
  std::vector<QueryRate> rates;
  rates.push_back(
      rate("PP candidates, rain pile N=10^4 (step 300)", fromScene("rain", 10000, 300, PairKind::ParticleParticle)));
  rates.push_back(rate("PP near pairs (within 1.5 reach)", nearPairs(PairKind::ParticleParticle, 4096)));
  rates.push_back(
      rate("PE candidates, chains N=10^4 (step 250)", fromScene("chains", 10000, 250, PairKind::ParticleEdge)));
  rates.push_back(rate("PE near pairs (within 1.5 reach of the edge)", nearPairs(PairKind::ParticleEdge, 4096)));
  return rates;
}

}  // namespace fosssim::bench
