#include "collision_search.h"

#include "parallel_rows.h"

#include <algorithm>
#include <chrono>

namespace fosssim {
namespace {

/// detectChanged queries every pair again (detectAll) when more than 1/kFullPassRatio of the
/// particles changed: collecting and sorting their pairs' keys then costs more than the rows.
constexpr size_t kFullPassRatio = 4;

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// Whether collision c involves a particle marked in `mark` (an edge's endpoints included).
bool involvesMarked(const Scene& scene, const Collision& c, const std::vector<char>& mark) {
  const PairParticles pair = pairParticles(scene, c.kind, c.i, c.j);
  for (int k = 0; k < pair.count; ++k)
    if (mark[pair.p[k]]) return true;
  return false;
}

}  // namespace

bool CollisionSearch::prepare(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx) {
  builtQs_ = builtQe_ = nullptr;
  if (forceAll_ || logging(ctx)) return false;
  const StepTimer timer(ctx.timing, ctx.stats->broadPhase);
  candidates_.build(scene, qs, qe, 0.0, /*updates=*/true, threads_);
  if (candidates_.allPairs()) return false;
  builtQs_ = &qs;
  builtQe_ = &qe;
  return true;
}

int CollisionSearch::collectRows(int first, int end, std::vector<uint64_t>& keys, std::vector<int>& row) const {
  keys.clear();
  int i = first;
  for (; i < end && keys.size() < blockSize_; ++i)
    candidates_.forEachInRow(i, row, [&](PairKind kind, int other) { keys.push_back(pairKey(i, kind, other)); });
  return i;
}

bool CollisionSearch::query(const Scene& scene, const VecX& qs, const VecX& qe, uint64_t key, Collision& hit,
                            StepStats& stats) const {
  const int i = keyParticle(key), other = keyOther(key);
  const PairKind kind = keyKind(key);
  ++stats.candidatePairs;
  ++stats.queries[static_cast<int>(kind)];
  switch (kind) {
    case PairKind::ParticleParticle: return detector_.particleParticle(scene, qs, qe, i, other, hit, nullptr);
    case PairKind::ParticleEdge: return detector_.particleEdge(scene, qs, qe, i, other, hit, nullptr);
    case PairKind::ParticleHalfPlane: return detector_.particleHalfPlane(scene, qs, qe, i, other, hit, nullptr);
  }
  return false;
}

void CollisionSearch::referenceSweep(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx,
                                     const std::function<void(const Collision&)>& onHit) {
  const StepTimer timer(ctx.timing, ctx.stats->narrowPhase);
  detector_.setStats(ctx.stats);
  detector_.forEachCollision(scene, qs, qe, ctx.log ? &ctx.log->polynomials : nullptr, onHit);
}

void CollisionSearch::detectAll(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx,
                                std::vector<Collision>& out) {
  out.clear();
  if (!prepare(scene, qs, qe, ctx)) {
    referenceSweep(scene, qs, qe, ctx, [&](const Collision& c) { out.push_back(c); });
    return;
  }
  // Rows in blocks of about kKeysPerBlock candidates (collision_search.h): the list stays small
  // (in cache, and bounded even when a diverging step makes every box overlap every other). With
  // threads, each takes a contiguous range of rows; the ranges' collisions are joined in order.
  const int n = scene.numParticles();
  const int ranges = rowRangesFor(n, threads_);
  if (workers_.size() < static_cast<size_t>(ranges)) workers_.resize(ranges);
  const auto start = std::chrono::steady_clock::now();
  forRowRanges(n, threads_, [&](int range, int first, int end) {
    Worker& w = workers_[range];
    w.out.clear();
    w.stats.clear();
    Collision hit;
    for (int row = first; row < end;) {
      {
        const StepTimer timer(ctx.timing, w.stats.broadPhase);
        row = collectRows(row, end, w.keys, w.row);
      }
      const StepTimer timer(ctx.timing, w.stats.narrowPhase);
      for (uint64_t key : w.keys)
        if (query(scene, qs, qe, key, hit, w.stats)) w.out.push_back(hit);
    }
  });
  for (int k = 0; k < ranges; ++k) out.insert(out.end(), workers_[k].out.begin(), workers_[k].out.end());
  joinRangeStats(ranges, [&](int k) -> const StepStats& { return workers_[k].stats; }, start, ctx.timing, *ctx.stats);
}

void CollisionSearch::detectChanged(const Scene& scene, const VecX& qs, const VecX& qe, StepContext& ctx,
                                    const std::vector<Collision>& previous, const std::vector<int>& changed,
                                    std::vector<Collision>& out) {
  const int n = scene.numParticles();
  if (forceAll_ || logging(ctx) || builtQs_ != &qs || builtQe_ != &qe || candidates_.allPairs() ||
      kFullPassRatio * changed.size() > static_cast<size_t>(n)) {
    detectAll(scene, qs, qe, ctx, out);
    return;
  }
  out.clear();
  {
    const StepTimer timer(ctx.timing, ctx.stats->broadPhase);
    if (mark_.size() != static_cast<size_t>(n)) mark_.assign(n, 0);
    for (int p : changed) candidates_.update(p);
    candidates_.settle();
    keys_.clear();
    for (int p : changed) {
      if (mark_[p]) continue;
      mark_[p] = 1;
      candidates_.pairsOf(p, keys_);
    }
    std::sort(keys_.begin(), keys_.end());
    keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
  }
  {
    // Merge, in pair order: the previous collisions of unchanged pairs (a query depends only on
    // its pair's positions) and the fresh queries of the pairs that involve a changed particle.
    const StepTimer timer(ctx.timing, ctx.stats->narrowPhase);
    Collision hit;
    size_t k = 0;
    for (const Collision& c : previous) {
      if (involvesMarked(scene, c, mark_)) continue;
      const uint64_t carried = pairKey(c);
      for (; k < keys_.size() && keys_[k] < carried; ++k)
        if (query(scene, qs, qe, keys_[k], hit, *ctx.stats)) out.push_back(hit);
      out.push_back(c);
    }
    for (; k < keys_.size(); ++k)
      if (query(scene, qs, qe, keys_[k], hit, *ctx.stats)) out.push_back(hit);
  }
  for (int p : changed) mark_[p] = 0;
}

void CollisionSearch::sweep(const Scene& scene, const VecX& qs, VecX& qe, StepContext& ctx,
                            const std::function<void(const Collision&)>& onHit) {
  if (!prepare(scene, qs, qe, ctx)) {
    referenceSweep(scene, qs, qe, ctx, onHit);
    return;
  }
  // Walk the rows' candidates in order, collected block by block as the walk reaches them. A
  // response changes its pair's particles: their boxes are refreshed and every pair they are now
  // part of that comes later joins a min-heap of extra keys, merged with the list as the walk
  // goes (a key in both is queried once).
  const auto walkStart = std::chrono::steady_clock::now();
  double rebroad = 0;
  extra_.clear();
  keys_.clear();
  const auto later = std::greater<uint64_t>();
  Collision hit;
  size_t pos = 0;
  int row = 0;
  for (;;) {
    if (pos == keys_.size() && row < scene.numParticles()) {
      const auto collectStart = ctx.timing ? std::chrono::steady_clock::now() : walkStart;
      row = collectRows(row, scene.numParticles(), keys_, row_);
      pos = 0;
      if (ctx.timing) rebroad += seconds(collectStart, std::chrono::steady_clock::now());
      continue;
    }
    if (pos == keys_.size() && extra_.empty()) break;
    uint64_t key = pos < keys_.size() ? keys_[pos] : ~uint64_t{0};
    if (!extra_.empty() && extra_.front() < key) key = extra_.front();
    while (pos < keys_.size() && keys_[pos] == key) ++pos;
    while (!extra_.empty() && extra_.front() == key) {
      std::pop_heap(extra_.begin(), extra_.end(), later);
      extra_.pop_back();
    }
    if (!query(scene, qs, qe, key, hit, *ctx.stats)) continue;
    const PairParticles pair = pairParticles(scene, hit.kind, hit.i, hit.j);
    const int* particles = pair.p;
    const int count = pair.count;
    Vec2 before[3];
    for (int k = 0; k < count; ++k) before[k] = at(qe, particles[k]);
    onHit(hit);
    const auto rebroadStart = ctx.timing ? std::chrono::steady_clock::now() : walkStart;
    bool moved = false;
    for (int k = 0; k < count; ++k) {
      if (at(qe, particles[k]) == before[k]) continue;
      candidates_.update(particles[k]);
      moved = true;
    }
    if (moved) candidates_.settle();
    for (int k = 0; k < count; ++k) {
      const int p = particles[k];
      if (at(qe, p) == before[k]) continue;
      const size_t first = extra_.size();
      candidates_.pairsOf(p, extra_);
      size_t kept = first;
      for (size_t m = first; m < extra_.size(); ++m)
        if (extra_[m] > key) extra_[kept++] = extra_[m];
      extra_.resize(kept);
      for (size_t m = first; m < kept; ++m)
        std::push_heap(extra_.begin(), extra_.begin() + static_cast<long>(m) + 1, later);
    }
    if (ctx.timing) rebroad += seconds(rebroadStart, std::chrono::steady_clock::now());
  }
  if (ctx.timing) {
    // Responses are interleaved with the queries: they count as narrow phase, as before;
    // collecting candidates and refreshing boxes count as broad phase.
    ctx.stats->broadPhase += rebroad;
    ctx.stats->narrowPhase += seconds(walkStart, std::chrono::steady_clock::now()) - rebroad;
  }
}

size_t CollisionSearch::memoryBytes() const {
  size_t bytes = candidates_.memoryBytes() + (keys_.capacity() + extra_.capacity()) * sizeof(uint64_t) +
                 row_.capacity() * sizeof(int) + mark_.capacity();
  for (const Worker& w : workers_)
    bytes +=
        w.keys.capacity() * sizeof(uint64_t) + w.row.capacity() * sizeof(int) + w.out.capacity() * sizeof(Collision);
  return bytes;
}

}  // namespace fosssim
