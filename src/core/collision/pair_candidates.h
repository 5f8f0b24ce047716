// Internal header: the broad phase. Which pairs of a scene may interact during a step, in the
// reference's pair order.
//
// Every particle and edge gets a box (pair_bounds.h): its motion from qs to qe (equal for the
// static uses: penalty force, discrete handler), grown by its radius, an optional extra reach and
// the exactness margin. Pairs whose boxes do not overlap provably do not interact; the others are
// the candidates. Half-planes are few and infinite: each particle is tested against each of them
// by its signed distance at the two ends of its motion.
//
// Candidates come in the reference's order: row by row (particle i), particles j > i ascending,
// then edges not incident to i ascending, then half-planes ascending. A pair is also named by a
// 64-bit key that sorts in that order (pairKey), for the incremental searches.
//
// Positions may change after the build (continuous-time responses, hybrid impulse passes, rigid
// zones): update(p) refreshes particle p's box and its edges' boxes, re-filed in the grids at
// once (BoxGrid::insert, O(1)); settle() rebuilds the grids when the re-filed boxes are many.
//
// A state with a non-finite coordinate has no meaningful boxes: the candidates are then every
// pair (allPairs()), exactly what the reference checks.
#pragma once

#include "box_grid.h"
#include "pair_bounds.h"

#include "fosssim/core/collision_log.h"

#include <cstdint>
#include <vector>

namespace fosssim {

/// Sorts as the reference's pair order: particle, then kind (PP, PE, PH), then the other index.
inline uint64_t pairKey(int i, PairKind kind, int other) {
  return (static_cast<uint64_t>(i) << 33) | (static_cast<uint64_t>(kind) << 31) | static_cast<uint64_t>(other);
}
/// The key of the particle pair {p, q} (p != q), named from the lower index.
inline uint64_t particlePairKey(int p, int q) {
  return p < q ? pairKey(p, PairKind::ParticleParticle, q) : pairKey(q, PairKind::ParticleParticle, p);
}
inline int keyParticle(uint64_t key) { return static_cast<int>(key >> 33); }
inline PairKind keyKind(uint64_t key) { return static_cast<PairKind>((key >> 31) & 3u); }
inline int keyOther(uint64_t key) { return static_cast<int>(key & 0x7FFFFFFFu); }

/// The particles a pair moves: the particle, then the other particle or the edge's endpoints
/// (one particle for a half-plane).
struct PairParticles {
  int count = 0;
  int p[3] = {0, 0, 0};
};

inline PairParticles pairParticles(const Scene& scene, PairKind kind, int i, int other) {
  PairParticles out;
  out.p[0] = i;
  switch (kind) {
    case PairKind::ParticleParticle: out.p[1] = other, out.count = 2; break;
    case PairKind::ParticleEdge: out.p[1] = scene.edges[other].i, out.p[2] = scene.edges[other].j, out.count = 3; break;
    case PairKind::ParticleHalfPlane: out.count = 1; break;
  }
  return out;
}
inline PairParticles pairParticles(const Scene& scene, uint64_t key) {
  return pairParticles(scene, keyKind(key), keyParticle(key), keyOther(key));
}

class PairCandidates {
 public:
  /// Boxes and grids for the motion qs -> qe (pass the same vector twice for static positions).
  /// `extra` widens every particle and edge box (the penalty force passes half its thickness, so
  /// that boxes meet within the pair's thickness) and the half-plane reach by 2 * extra.
  /// `scene`, `qs` and `qe` must outlive the use (qe may change between update() calls).
  /// `updates`: qe will change (update()); boxes are then filed with some slack. `threads`: for
  /// the boxes and grids of this build and its rebuilds (the same candidates for any count).
  void build(const Scene& scene, const VecX& qs, const VecX& qe, double extra = 0.0, bool updates = false,
             int threads = 1);

  /// Whether the boxes carry the relative margins only (Margins::Relative, the default: exact and
  /// static narrow phases) or also the absolute ones that the course's cut-off needs
  /// (Margins::Course, CollisionSearch's), pair_bounds.h; from the next build on.
  void setMargins(Margins margins) { margins_ = margins; }

  /// Every pair is a candidate (non-finite state or forced).
  bool allPairs() const { return allPairs_; }
  /// Makes every pair a candidate until the next build (the reference's all-pairs sweep).
  void forceAllPairs() { allPairs_ = true; }

  /// Appends the particles j > max(i, after) whose boxes meet particle i's, ascending.
  void particlesOf(int i, int after, std::vector<int>& out) const;
  /// Appends the particles j < i whose boxes meet particle i's (in no particular order).
  void particlesBefore(int i, std::vector<int>& out) const;
  /// Calls visit(j) for every particle j whose box meets particle p's (p itself included), in no
  /// particular order: particlesOf and particlesBefore together, without the sort. Not with
  /// allPairs().
  template <class Visit>
  void forEachParticleMeetingParticle(int p, Visit&& visit) const {
    particleGrid_.forEachOverlap(particleBoxes_[p], visit);
  }
  /// Calls visit(j) for every particle j whose box meets edge e's, in no particular order: the
  /// particles whose edgesOf lists e (and e's endpoints). Not with allPairs().
  template <class Visit>
  void forEachParticleMeetingEdge(int e, Visit&& visit) const {
    particleGrid_.forEachOverlap(edgeBoxes_[e], visit);
  }
  /// Appends the edges e > after not incident to i whose boxes meet particle i's, ascending.
  void edgesOf(int i, int after, std::vector<int>& out) const;
  /// Whether particle i may reach half-plane h.
  bool nearPlane(int i, int h) const {
    return allPairs_ || nearHalfPlane(*scene_, *qs_, *qe_, i, h, scale_, 2 * extra_, margins_);
  }

  /// Visits row i's candidates in the reference's order: visit(kind, other) for the particles
  /// j > i, then the edges not incident to i, then the half-planes i may reach (every
  /// half-plane with `everyPlane`), each ascending. `row` is scratch storage.
  template <class Visit>
  void forEachInRow(int i, std::vector<int>& row, Visit&& visit, bool everyPlane = false) const {
    row.clear();
    particlesOf(i, -1, row);
    for (int j : row) visit(PairKind::ParticleParticle, j);
    if (!scene_->edges.empty()) {
      row.clear();
      edgesOf(i, -1, row);
      for (int e : row) visit(PairKind::ParticleEdge, e);
    }
    const int planes = static_cast<int>(scene_->halfplanes.size());
    for (int h = 0; h < planes; ++h)
      if (everyPlane || nearPlane(i, h)) visit(PairKind::ParticleHalfPlane, h);
  }

  /// Particle p's end position changed (qe as given at the build, changed in place).
  void update(int p);
  /// After update() calls: rebuilds the grids when the boxes re-filed since their build are a
  /// good share of all (queries are right either way; this only keeps them fast).
  void settle();
  /// Appends the keys of every candidate pair that involves particle p (as the particle, the
  /// other particle or an edge endpoint), each once, then its half-plane pairs ascending.
  /// p's particle and edge pairs are kept from one call to the next (the event loop asks for the
  /// same particles' pairs after every solve that moves them: on rain at N = 10^5, 90,000 calls
  /// a step against 550 re-filed boxes): with edges until a box they depend on is re-filed,
  /// without edges updated as boxes are re-filed; keepAll() makes them all at once. They come
  /// ascending: in scenes without edges the whole list is then ascending (sortedPairs()); with
  /// edges a half-plane key may sort before an earlier particle-edge key of a higher particle.
  /// With every pair a candidate (allPairs()) nothing is kept. Not for concurrent use.
  void pairsOf(int p, std::vector<uint64_t>& keys) const;
  /// Calls visit(key) for each of pairsOf(p)'s keys, in its order, reading the kept list where
  /// it lies: grow and detectChanged ask for thousands of lists a step, and copying each out took
  /// 4% of rain's time at N = 10^4. visit must not call pairsOf, forEachPairOf, update or settle
  /// (they may rebuild the list being read).
  template <class Visit>
  void forEachPairOf(int p, Visit&& visit) const {
    if (allPairs_) {
      forEachPairOfAll(p, visit);
    } else if (scene_->edges.empty()) {
      forEachKept(p, [&](int q) { visit(particlePairKey(p, q)); });
    } else {
      for (uint64_t key : keptKeysOf(p)) visit(key);
    }
    const int planes = static_cast<int>(scene_->halfplanes.size());
    for (int h = 0; h < planes; ++h)
      if (nearPlane(p, h)) visit(pairKey(p, PairKind::ParticleHalfPlane, h));
  }
  /// Whether pairsOf's lists are worth making all at once from the step's first detection
  /// (keepAll): between the last two builds (the last step) pairsOf read the lists of at least a
  /// kKeepAllFractionInverse-th of the particles (a pile whose zones ask for thousands a step;
  /// not a gas, whose impulses ask for a few).
  bool keepsAllNext() const {
    return !allPairs_ && listsReadBefore_ * kKeepAllFractionInverse >= static_cast<long>(scene_->numParticles());
  }
  /// Makes every particle's pairsOf list at once, from every candidate pair: forEachPair(visit)
  /// must call visit(key) for the key of every candidate particle pair (i, j), i < j, and
  /// particle-edge pair, in ascending order (the rows of the step's first detection, each a
  /// forEachInRow(i) row), and may call it for half-plane keys, which are skipped. Each key goes
  /// to the list of every particle it involves, and since the keys come ascending so does each
  /// list: the lists are exactly those pairsOf would make one by one (the same boxes, overlap
  /// being symmetric), without a grid search and a sort each. On rain (N = 10^4) the event loop
  /// made about 6,000 lists a step one by one, a tenth of its time; on chains 1,000 making them
  /// (with edges) took a tenth as well. Right after build(), not with allPairs().
  template <class ForEachPair>
  void keepAll(ForEachPair&& forEachPair) {
    beginKeepAll();
    if (scene_->edges.empty()) {
      forEachPair([&](uint64_t key) {
        if (keyKind(key) != PairKind::ParticleParticle) return;
        keep(keyParticle(key), keyOther(key));
        keep(keyOther(key), keyParticle(key));
      });
      return;
    }
    forEachPair([&](uint64_t key) {
      if (keyKind(key) == PairKind::ParticleHalfPlane) return;
      const PairParticles pair = pairParticles(*scene_, key);
      for (int k = 0; k < pair.count; ++k) {
        std::vector<uint64_t>& keys = keptKeys_[pair.p[k]];
        if (keys.empty() || keys.back() != key) keys.push_back(key);  // an edge's two ends may be one particle
      }
    });
  }
  /// Whether pairsOf keeps its lists and so appends its keys ascending and each once: scenes
  /// without edges. (The kept particle pairs are sorted; pairs (q, p) with q < p sort before
  /// (p, q) with q > p, and those before p's half-plane pairs, which follow ascending.)
  bool sortedPairs() const { return !allPairs_ && scene_->edges.empty(); }

  /// Bytes held (capacity), for the benchmark's memory figures.
  size_t memoryBytes() const;

 private:
  static constexpr int kKeptInline = 14;  ///< neighbours stored in the line; a disk in a pile has about 6-10
  struct alignas(64) KeptList {
    uint32_t generation = 0;  ///< 0: none
    int32_t count = 0;        ///< all of p's: the first kKeptInline in `other`, the rest in keptMore_[p]
    int32_t other[kKeptInline] = {};  ///< the list's first kKeptInline particles, ascending
  };
  /// keepsAllNext(): at least this inverse fraction of the particles had lists made one by one.
  /// Making all of them costs about a list entry per candidate pair and a line per particle
  /// (rain 10^4: about 3 pairs per particle), one by one a grid search and a sort per list; a
  /// gas needs lists for a few hundred particles of 10^5 a step.
  static constexpr long kKeepAllFractionInverse = 8;
  void index();  ///< (re)builds the main grids from the current boxes (and forgets pairsOf's lists)
  void beginKeepAll();  ///< every list empty and current (keepAll)
  /// Appends q to p's list (keepAll).
  void keep(int p, int q) {
    KeptList& list = kept_[p];
    if (list.count < kKeptInline) list.other[list.count] = q;
    else keptMore_[p].push_back(q);
    ++list.count;
  }
  /// With every pair a candidate: visit(key) for p's particle pairs, then its edge pairs (as the
  /// particle, then as an endpoint), each once; nothing is kept.
  template <class Visit>
  void forEachPairOfAll(int p, Visit&& visit) const {
    const std::vector<Edge>& edges = scene_->edges;
    const int n = scene_->numParticles();
    for (int q = 0; q < n; ++q)
      if (q != p) visit(particlePairKey(p, q));
    auto edgePair = [&](int q, int e) {
      if (edges[e].i != q && edges[e].j != q) visit(pairKey(q, PairKind::ParticleEdge, e));
    };
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
      edgePair(p, e);
      if (edges[e].i == p || edges[e].j == p)
        for (int q = 0; q < n; ++q) edgePair(q, e);
    }
  }
  /// Forgets the kept lists that a particle box b (before or after a re-filing) may enter: those
  /// of the particles whose boxes meet b, and with edges those of the endpoints of the edges
  /// whose boxes meet b (they list b's particle against the edge).
  void forgetPairsNear(const Box& b);
  /// Scenes without edges: particle p's box was re-filed from `old` to particleBoxes_[p]; the
  /// current lists take p in or out, p's own is forgotten.
  void refileInLists(int p, const Box& old);
  /// Puts p into q's list (ascending) or takes it out.
  void setKept(int q, int p, bool member);
  /// The same for edge e's box b: the particles whose boxes meet b, and e's endpoints (whose
  /// boxes meet b anyway, as b holds their paths; named so as not to rest on how boxes grow).
  void forgetEdgePairsNear(int e, const Box& b);
  bool keepsLists() const;  ///< whether kept lists exist yet (made at pairsOf's first call)
  void makeKeptStorage() const;
  /// Calls f(q) for the particles q of p's kept list (scenes without edges), ascending (so in the order
  /// of their pairs' keys), after making the list afresh if a re-filed box has made it stale.
  template <class F>
  void forEachKept(int p, F&& f) const {
    const KeptList& list = keptListOf(p);
    const int stored = list.count < kKeptInline ? list.count : kKeptInline;
    for (int k = 0; k < stored; ++k) f(list.other[k]);
    if (list.count > kKeptInline)
      for (int q : keptMore_[p]) f(q);
  }
  const KeptList& keptListOf(int p) const;
  /// With edges: p's particle and edge pair keys, ascending, each once (made afresh if stale).
  const std::vector<uint64_t>& keptKeysOf(int p) const;
  bool withinScale(int p) const;
  Box filed(const Box& b) const;  ///< b grown by the slack
  template <class Visit>
  void forEachParticleNear(const Box& b, Visit&& visit) const;
  template <class Visit>
  void forEachEdgeNear(const Box& b, Visit&& visit) const;

  const Scene* scene_ = nullptr;  ///< the build's scene
  const VecX* qs_ = nullptr;      ///< the build's start positions (2N)
  const VecX* qe_ = nullptr;      ///< the build's end positions (2N; read again as they change, update())
  /// The build's extra reach, its coordinate scale (the largest |coordinate|, for the margins) and
  /// the filing slack (a fraction of a box's extent; 0 without updates).
  double extra_ = 0, scale_ = 0, slack_ = 0;
  Margins margins_ = Margins::Relative;  ///< setMargins
  int threads_ = 1;        ///< threads for the build's boxes and grids, and its rebuilds
  bool allPairs_ = false;  ///< every pair is a candidate until the next build (a non-finite or huge state, or forced)
  /// Per particle (N) and per edge: its box over the motion, as filed (slack included).
  std::vector<Box> particleBoxes_, edgeBoxes_;
  BoxGrid particleGrid_, edgeGrid_;  ///< the grids of particleBoxes_ and edgeBoxes_ (box id: particle or edge index)
  std::vector<int> incidentStart_, incident_;  ///< edges of each particle (compressed rows)
  // pairsOf's lists. Without edges: the particles q != p whose boxes meet p's, ascending. A list
  // is good while its generation equals generation_ (or generation_ | kUnread, made by keepAll
  // and not read yet), which every index() advances; a re-filed box of particle p takes p in or
  // out of the good lists of the particles it met before or meets now (refileInLists) and
  // forgets p's own list. A list fills one cache line, its generation included: the event loop
  // reads thousands a step in no particular order, and with a heap vector per particle (and the
  // generations apart) each read cost three cache misses.
  mutable std::vector<KeptList> kept_;               ///< N, made at pairsOf's first call
  mutable std::vector<std::vector<int>> keptMore_;   ///< N: a list's particles past kKeptInline (rare)
  // With edges, each particle's whole list of keys (its generation in kept_): the pairs with
  // its particle neighbours, with the edges its box meets, and those of the particles its edges'
  // boxes meet against those edges.
  mutable std::vector<std::vector<uint64_t>> keptKeys_;  ///< N, made at pairsOf's first call
  mutable std::vector<int> keptScratch_;             ///< scratch: a list being made
  /// Lists pairsOf read since the last build: each list made one by one (again if it was
  /// forgotten and made anew), and each made by keepAll at its first read (it carries kUnread in
  /// its generation until then); a list read again while good does not count.
  mutable long listsRead_ = 0;
  long listsReadBefore_ = 0;  ///< listsRead_ at the last build: the last step's (keepsAllNext)
  /// The generation bit of a list keepAll made and pairsOf has not read yet (generation_ stays below it).
  static constexpr uint32_t kUnread = 1u << 31;
  uint32_t generation_ = 0;  ///< the good lists' generation (see kept_); every index() advances it
};

}  // namespace fosssim
