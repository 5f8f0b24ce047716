#include "pair_candidates.h"

#include "parallel_rows.h"

#include <algorithm>
#include <cmath>

namespace fosssim {
namespace {

/// The grids are rebuilt when the boxes re-filed since their build are this fraction of all:
/// each re-filed box costs its queries a list entry and leaves a dead sorted one behind.
constexpr size_t kRefiledFractionInverse = 4;
/// Boxes that may change (continuous-time detection) are filed this fraction of their extent
/// larger: most later changes (a particle frozen at its start by an impact zone, a rigid refit,
/// a small impulse) then stay inside, and the filed box remains a valid, conservative bound.
constexpr double kFiledSlack = 0.02;

bool contains(const Box& outer, const Box& inner) {
  return outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && inner.x1 <= outer.x1 && inner.y1 <= outer.y1;
}

/// Coordinates and radii beyond this magnitude make no grid: the difference of two coordinates, a
/// box's extent or a cell index could overflow (two particles at +-9e307 are 1.8e308 apart, which
/// is infinite). Such a scene is treated as a non-finite one: every pair is a candidate, and the
/// narrow phase decides (or reports the pair it cannot represent). 1e300 leaves room for the
/// margins and for thousands of cells.
constexpr double kLargestGridCoordinate = 1e300;

bool gridRadii(const Scene& scene) {
  for (double r : scene.radius)
    if (!(std::fabs(r) <= kLargestGridCoordinate)) return false;
  for (const Edge& e : scene.edges)
    if (!(std::fabs(e.radius) <= kLargestGridCoordinate)) return false;
  return true;
}

}  // namespace

Box PairCandidates::filed(const Box& b) const {
  if (slack_ == 0) return b;
  const double grow = slack_ * std::max(b.x1 - b.x0, b.y1 - b.y0);
  return Box{b.x0 - grow, b.y0 - grow, b.x1 + grow, b.y1 + grow};
}

double coordinateScale(const Scene& scene, const VecX& a, const VecX& b, int threads) {
  // One pass over both vectors by ranges of particles; v <= DBL_MAX fails for NaN and infinity.
  const int n = static_cast<int>(std::min(a.size(), b.size()) / 2);
  std::vector<double> largest(static_cast<size_t>(rowRangesFor(n, threads)), 0.0);
  forRowRanges(n, threads, [&](int range, int first, int end) {
    double m = 0;
    bool finite = true;
    for (long k = 2L * first; k < 2L * end; ++k) {
      const double u = std::fabs(a[k]), v = std::fabs(b[k]);
      finite = finite && u <= std::numeric_limits<double>::max() && v <= std::numeric_limits<double>::max();
      m = std::max(m, std::max(u, v));
    }
    largest[range] = finite ? m : std::numeric_limits<double>::infinity();
  });
  double s = 0;
  for (double m : largest) s = std::max(s, m);
  for (const HalfPlane& h : scene.halfplanes) {
    if (!h.point.allFinite() || !h.normal.allFinite()) return std::numeric_limits<double>::infinity();
    s = std::max(s, h.point.lpNorm<Eigen::Infinity>());
  }
  return s;
}

void PairCandidates::build(const Scene& scene, const VecX& qs, const VecX& qe, double extra, bool updates,
                           int threads) {
  scene_ = &scene;
  threads_ = threads;
  listsReadBefore_ = listsRead_;
  listsRead_ = 0;
  slack_ = updates ? kFiledSlack : 0.0;
  qs_ = &qs;
  qe_ = &qe;
  extra_ = extra;
  scale_ = coordinateScale(scene, qs, qe, threads);
  allPairs_ = !(scale_ <= kLargestGridCoordinate) || !(std::fabs(extra) <= kLargestGridCoordinate) || !gridRadii(scene);
  if (allPairs_) return;
  const int n = scene.numParticles(), edges = static_cast<int>(scene.edges.size());
  particleBoxes_.resize(n);
  forRowRanges(n, threads, [&](int, int first, int end) {
    for (int p = first; p < end; ++p) particleBoxes_[p] = filed(particleBox(scene, qs, qe, p, scale_, extra, margins_));
  });
  if (edges > 0) {  // no edge storage at all for scenes without edges
    edgeBoxes_.resize(edges);
    for (int e = 0; e < edges; ++e) edgeBoxes_[e] = filed(edgeBox(scene, qs, qe, e, scale_, extra, margins_));
    incidentStart_.assign(n + 1, 0);
    for (const Edge& e : scene.edges) ++incidentStart_[e.i + 1], ++incidentStart_[e.j + 1];
    for (int p = 0; p < n; ++p) incidentStart_[p + 1] += incidentStart_[p];
    incident_.resize(2 * static_cast<size_t>(edges));
    // Counting sort: filling each row from its end, edges in descending order, leaves the rows
    // ascending and every row start one slot to the right; shift them back.
    for (int e = edges - 1; e >= 0; --e) {
      incident_[--incidentStart_[scene.edges[e].i + 1]] = e;
      incident_[--incidentStart_[scene.edges[e].j + 1]] = e;
    }
    for (int p = 0; p < n; ++p) incidentStart_[p] = incidentStart_[p + 1];
    incidentStart_[n] = 2 * edges;
  }
  index();
}

void PairCandidates::index() {
  // Every list made before is stale now. Generation 0 means "none": at the wrap (after 2^31
  // indexings, below keepAll's kUnread bit) the lists are forgotten outright, so no old list can
  // pass for a new one.
  if (++generation_ == kUnread) {
    for (KeptList& list : kept_) list.generation = 0;
    generation_ = 1;
  }
  particleGrid_.build(particleBoxes_.data(), scene_->numParticles(), threads_);
  if (!scene_->edges.empty())
    edgeGrid_.build(edgeBoxes_.data(), static_cast<int>(scene_->edges.size()), threads_);
}

bool PairCandidates::withinScale(int p) const {
  const double x = (*qe_)[2 * p], y = (*qe_)[2 * p + 1];
  return std::fabs(x) <= scale_ && std::fabs(y) <= scale_;  // false for NaN
}

void PairCandidates::update(int p) {
  if (allPairs_) return;
  if (!withinScale(p)) {  // the margins' scale no longer holds (or the state is not finite)
    build(*scene_, *qs_, *qe_, extra_, slack_ > 0, threads_);
    return;
  }
  // A filed box that still holds the new one stays (a particle put back at its start, a rigid
  // refit's rounding, a small impulse); else the fresh box is re-filed in the grid.
  const Box fresh = particleBox(*scene_, *qs_, *qe_, p, scale_, extra_, margins_);
  const bool keeping = keepsLists();
  if (!contains(particleBoxes_[p], fresh)) {
    const Box old = particleBoxes_[p];
    if (keeping && !scene_->edges.empty()) forgetPairsNear(old);  // the lists that hold p
    particleBoxes_[p] = filed(fresh);
    particleGrid_.insert(p, particleBoxes_[p]);
    if (keeping && !scene_->edges.empty()) forgetPairsNear(particleBoxes_[p]);  // the lists that must hold it now
    if (keeping && scene_->edges.empty()) refileInLists(p, old);
  }
  if (!scene_->edges.empty()) {
    for (int k = incidentStart_[p]; k < incidentStart_[p + 1]; ++k) {
      const int e = incident_[k];
      const Box freshEdge = edgeBox(*scene_, *qs_, *qe_, e, scale_, extra_, margins_);
      if (contains(edgeBoxes_[e], freshEdge)) continue;
      if (keeping) forgetEdgePairsNear(e, edgeBoxes_[e]);
      edgeBoxes_[e] = filed(freshEdge);
      edgeGrid_.insert(e, edgeBoxes_[e]);
      if (keeping) forgetEdgePairsNear(e, edgeBoxes_[e]);
    }
  }
}

void PairCandidates::settle() {
  if (allPairs_) return;
  const size_t refiled = static_cast<size_t>(particleGrid_.inserted()) + static_cast<size_t>(edgeGrid_.inserted());
  const size_t n = static_cast<size_t>(scene_->numParticles()) + scene_->edges.size();
  if (refiled * kRefiledFractionInverse >= n && refiled > 0) index();
}

template <class Visit>
void PairCandidates::forEachParticleNear(const Box& b, Visit&& visit) const {
  particleGrid_.forEachOverlap(b, visit);
}

template <class Visit>
void PairCandidates::forEachEdgeNear(const Box& b, Visit&& visit) const {
  if (!scene_->edges.empty()) edgeGrid_.forEachOverlap(b, visit);
}

void PairCandidates::particlesOf(int i, int after, std::vector<int>& out) const {
  const int first = std::max(i, after) + 1, n = scene_->numParticles();
  if (allPairs_) {
    for (int j = first; j < n; ++j) out.push_back(j);
    return;
  }
  const size_t begin = out.size();
  particleGrid_.forEachOverlapFrom(particleBoxes_[i], first, [&](int j) { out.push_back(j); });
  std::sort(out.begin() + static_cast<long>(begin), out.end());
}

void PairCandidates::particlesBefore(int i, std::vector<int>& out) const {
  if (allPairs_) {
    for (int j = 0; j < i; ++j) out.push_back(j);
    return;
  }
  particleGrid_.forEachOverlap(particleBoxes_[i], [&](int j) {
    if (j < i) out.push_back(j);
  });
}

void PairCandidates::edgesOf(int i, int after, std::vector<int>& out) const {
  const std::vector<Edge>& edges = scene_->edges;
  const int count = static_cast<int>(edges.size());
  if (allPairs_) {
    for (int e = after + 1; e < count; ++e)
      if (edges[e].i != i && edges[e].j != i) out.push_back(e);
    return;
  }
  if (edges.empty()) return;  // no edge grid
  const size_t begin = out.size();
  edgeGrid_.forEachOverlapFrom(particleBoxes_[i], after + 1, [&](int e) {
    if (edges[e].i != i && edges[e].j != i) out.push_back(e);
  });
  std::sort(out.begin() + static_cast<long>(begin), out.end());
}

void PairCandidates::pairsOf(int p, std::vector<uint64_t>& keys) const {
  forEachPairOf(p, [&](uint64_t key) { keys.push_back(key); });
}

// Sized for this scene and of its kind (a candidates object may be built again for another scene).
bool PairCandidates::keepsLists() const {
  const size_t n = static_cast<size_t>(scene_->numParticles());
  return kept_.size() == n && (scene_->edges.empty() ? keptMore_.size() : keptKeys_.size()) == n;
}

// At pairsOf's first call: only users of pairsOf pay for the lists.
void PairCandidates::makeKeptStorage() const {
  const int n = scene_->numParticles();
  kept_.assign(n, KeptList{});
  if (scene_->edges.empty()) keptMore_.assign(n, {}), keptKeys_.clear();
  else keptKeys_.assign(n, {}), keptMore_.clear();
}

const PairCandidates::KeptList& PairCandidates::keptListOf(int p) const {
  if (!keepsLists()) makeKeptStorage();
  KeptList& list = kept_[p];
  if (list.generation == generation_) return list;
  ++listsRead_;
  if (list.generation == (generation_ | kUnread)) {  // made by keepAll, read now for the first time
    list.generation = generation_;
    return list;
  }
  keptScratch_.clear();
  forEachParticleNear(particleBoxes_[p], [&](int q) {
    if (q != p) keptScratch_.push_back(q);
  });
  std::sort(keptScratch_.begin(), keptScratch_.end());  // once here, instead of by every caller that needs pair order
  list.count = static_cast<int>(keptScratch_.size());
  const int stored = std::min(list.count, kKeptInline);
  std::copy(keptScratch_.begin(), keptScratch_.begin() + stored, list.other);
  if (list.count > kKeptInline) keptMore_[p].assign(keptScratch_.begin() + stored, keptScratch_.end());
  list.generation = generation_;
  return list;
}

void PairCandidates::beginKeepAll() {
  if (!keepsLists()) makeKeptStorage();
  const bool edges = !scene_->edges.empty();
  for (size_t p = 0; p < kept_.size(); ++p) {
    KeptList& list = kept_[p];
    if (edges) keptKeys_[p].clear();
    else if (list.count > kKeptInline) keptMore_[p].clear();
    list.count = 0;
    list.generation = generation_ | kUnread;
  }
}

const std::vector<uint64_t>& PairCandidates::keptKeysOf(int p) const {
  if (!keepsLists()) makeKeptStorage();
  std::vector<uint64_t>& keys = keptKeys_[p];
  if (kept_[p].generation == generation_) return keys;
  ++listsRead_;
  if (kept_[p].generation == (generation_ | kUnread)) {  // made by keepAll, read now for the first time
    kept_[p].generation = generation_;
    return keys;
  }
  const std::vector<Edge>& edges = scene_->edges;
  keys.clear();
  forEachParticleNear(particleBoxes_[p], [&](int q) {
    if (q != p) keys.push_back(particlePairKey(p, q));
  });
  auto edgePair = [&](int q, int e) {
    if (edges[e].i != q && edges[e].j != q) keys.push_back(pairKey(q, PairKind::ParticleEdge, e));
  };
  forEachEdgeNear(particleBoxes_[p], [&](int e) { edgePair(p, e); });
  for (int k = incidentStart_[p]; k < incidentStart_[p + 1]; ++k) {
    const int e = incident_[k];
    forEachParticleNear(edgeBoxes_[e], [&](int q) { edgePair(q, e); });
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  kept_[p].generation = generation_;
  return keys;
}

// Without edges a list is a set of particles, and p's box moving from `old` to its filed box
// changes only whether p is in the lists of the particles whose boxes meet either: each list
// that is current takes p in or out by whether it meets the new box (the lists that met
// neither neither held p nor must). Forgetting them instead had every one of them made afresh
// (a grid search and a sort) when next read: on rain at N = 10^5, thousands a step. p's own
// list is forgotten and made afresh when read.
void PairCandidates::refileInLists(int p, const Box& old) {
  const Box& now = particleBoxes_[p];
  auto follow = [&](int q) {
    const KeptList& list = kept_[q];
    if (q == p || (list.generation != generation_ && list.generation != (generation_ | kUnread))) return;
    setKept(q, p, overlap(particleBoxes_[q], now));
  };
  particleGrid_.forEachOverlap(old, follow);
  particleGrid_.forEachOverlap(now, follow);  // a particle met by both is set twice, the same way
  kept_[p].generation = 0;
}

void PairCandidates::setKept(int q, int p, bool member) {
  KeptList& list = kept_[q];
  std::vector<int>& all = keptScratch_;
  all.assign(list.other, list.other + std::min(list.count, kKeptInline));
  if (list.count > kKeptInline) all.insert(all.end(), keptMore_[q].begin(), keptMore_[q].end());
  const auto at = std::lower_bound(all.begin(), all.end(), p);
  if ((at != all.end() && *at == p) == member) return;
  if (member) all.insert(at, p);
  else all.erase(at);
  list.count = static_cast<int>(all.size());
  const int stored = std::min(list.count, kKeptInline);
  std::copy(all.begin(), all.begin() + stored, list.other);
  if (list.count > kKeptInline) keptMore_[q].assign(all.begin() + stored, all.end());
  else keptMore_[q].clear();
}

void PairCandidates::forgetPairsNear(const Box& b) {
  particleGrid_.forEachOverlap(b, [&](int q) { kept_[q].generation = 0; });
  if (!scene_->edges.empty())
    edgeGrid_.forEachOverlap(
        b, [&](int e) { kept_[scene_->edges[e].i].generation = kept_[scene_->edges[e].j].generation = 0; });
}

void PairCandidates::forgetEdgePairsNear(int e, const Box& b) {
  particleGrid_.forEachOverlap(b, [&](int q) { kept_[q].generation = 0; });
  kept_[scene_->edges[e].i].generation = kept_[scene_->edges[e].j].generation = 0;
}

size_t PairCandidates::memoryBytes() const {
  size_t kept = kept_.capacity() * sizeof(KeptList) + keptMore_.capacity() * sizeof(std::vector<int>) +
                keptScratch_.capacity() * sizeof(int);
  for (const std::vector<int>& more : keptMore_) kept += more.capacity() * sizeof(int);
  kept += keptKeys_.capacity() * sizeof(std::vector<uint64_t>);
  for (const std::vector<uint64_t>& keys : keptKeys_) kept += keys.capacity() * sizeof(uint64_t);
  return kept + particleBoxes_.capacity() * sizeof(Box) + edgeBoxes_.capacity() * sizeof(Box) +
         particleGrid_.memoryBytes() + edgeGrid_.memoryBytes() +
         (incidentStart_.capacity() + incident_.capacity()) * sizeof(int);
}

}  // namespace fosssim
