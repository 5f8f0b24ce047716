// The broad phase against checking every pair, on random scenes built to be hard for it: radii
// over six orders of magnitude, fast movers crossing the scene in one step, nearly static pairs
// (whose CCD polynomials lose leading coefficients to the cutoff), tiny and collapsing edges,
// coordinates far from the origin, pairs placed just outside reach.
//   * every pair the narrow phase finds colliding is a candidate (swept boxes), and every pair
//     within the penalty force's reach is a candidate (static boxes);
//   * the incremental detections (after some particles move) equal fresh full detections;
//   * the candidates stay complete after update().
#include "broad_phase_pairs.h"

#include <algorithm>
#include <random>
#include <set>

namespace fosssim {
namespace {

using testing::allPairs;
using testing::candidateKeys;
using testing::Motion;

/// A random scene and step designed to stress the broad phase's margins.
Motion randomMotion(std::mt19937& rng, int n, double offset) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  // x drawn before y, in separate statements: a call's arguments are evaluated in an order the
  // compiler picks (gcc right to left, clang left to right), and both must build the same scenes.
  auto uv = [&](double lo, double hi) {
    const double x = u(lo, hi);
    const double y = u(lo, hi);
    return Vec2(x, y);
  };
  Motion m;
  m.qs.resize(2 * n);
  m.qe.resize(2 * n);
  const double size = u(0.5, 4.0);
  for (int p = 0; p < n; ++p) {
    const int style = static_cast<int>(u(0, 6));
    double r = std::pow(10.0, u(-4, 0));
    if (style == 0) r = std::pow(10.0, u(0, 1.5));  // huge
    Vec2 x = uv(-size, size);
    if (p > 0 && style <= 3) {  // near another particle: just inside or outside reach
      const int q = static_cast<int>(u(0, p));
      const double reach = r + m.scene.radius[q];
      const double angle = u(0, 6.283185307179586);
      const double gap = style == 1 ? u(-1e-6, 1e-6) * reach : (style == 2 ? u(0.9, 1.1) * reach : u(1.0, 1.0 + 1e-9) * reach);
      x = at(m.qs, q) + gap * Vec2(std::cos(angle), std::sin(angle));
      if (style == 3) x = at(m.qs, q) + (reach + std::pow(10.0, u(-9, -3))) * Vec2(std::cos(angle), std::sin(angle));
    }
    Vec2 d = uv(-1, 1);
    const int speed = static_cast<int>(u(0, 4));
    d *= speed == 0 ? 1e-8 : (speed == 1 ? 0.01 * size : (speed == 2 ? size : 0.0));  // static, slow, fast, still
    const double mass = std::pow(10.0, u(-2, 2));
    const bool fixed = u(0, 1) < 0.1;
    addParticle(m.scene, mass, fixed, r);
    at(m.qs, p) = x + Vec2(offset, -offset);
    at(m.qe, p) = at(m.qs, p) + d;
  }
  const int edges = static_cast<int>(u(0, n / 2));
  for (int k = 0; k < edges; ++k) {
    const int i = static_cast<int>(u(0, n));
    int j = static_cast<int>(u(0, n));
    if (j == i) j = (i + 1) % n;
    if (u(0, 1) < 0.2) {  // a tiny or collapsing edge
      at(m.qs, j) = at(m.qs, i) + uv(-1e-7, 1e-7);
      at(m.qe, j) = at(m.qe, i) + (u(0, 1) < 0.5 ? uv(-1e-7, 1e-7) : uv(-1, 1));
    }
    m.scene.edges.push_back(Edge{i, j, std::pow(10.0, u(-4, -1))});
  }
  const int planes = static_cast<int>(u(0, 4));
  for (int k = 0; k < planes; ++k) {
    const double length = std::pow(10.0, u(-4, 3));
    const Vec2 normal = length * uv(-1, 1).normalized();
    const int on = static_cast<int>(u(0, n));
    const Vec2 shift = uv(-0.1, 0.1);
    m.scene.halfplanes.push_back(HalfPlane{at(m.qs, on) + shift, normal});
  }
  return m;
}


void expectSame(const std::vector<Collision>& a, const std::vector<Collision>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(pairKey(a[k]), pairKey(b[k]));
    EXPECT_EQ(a[k].tau, b[k].tau);
    EXPECT_EQ(a[k].n, b[k].n);
    EXPECT_EQ(a[k].alpha, b[k].alpha);
  }
}

constexpr int kScenes = 300;

TEST(BroadPhase, EveryCollidingPairIsACandidate) {
  std::mt19937 rng(7);
  long collisions = 0;
  for (int s = 0; s < kScenes; ++s) {
    const double offset = s % 3 == 0 ? 0.0 : (s % 3 == 1 ? 1e3 : 1e6);
    Motion m = randomMotion(rng, 40 + s % 60, offset);
    PairCandidates candidates;
    candidates.build(m.scene, m.qs, m.qe);
    ASSERT_FALSE(candidates.allPairs());
    const std::set<uint64_t> keys = candidateKeys(m.scene, candidates);
    // Both quintic forms, with FOSSSim's own interval rule: the reference's (IntervalRule::Reference)
    // reads signs at r -+ 1, which for roots beyond ~1e8 steps cancels catastrophically and can
    // report far pairs at t = 0 (as the reference itself does); the broad phase does not
    // reproduce those, see collision_search.h.
    for (const math::DetectionRules& rules : {math::DetectionRules{}, math::DetectionRules{math::QuinticForm::Reference}}) {
      for (const Collision& c : allPairs(m.scene, m.qs, m.qe, rules)) {
        ++collisions;
        EXPECT_TRUE(keys.count(pairKey(c))) << "scene " << s << ": " << pairKindName(c.kind) << " (" << c.i << ", "
                                            << c.j << ") collides at " << c.tau << " but is no candidate";
      }
    }
  }
  EXPECT_GT(collisions, 1000);  // the scenes do collide
}

TEST(BroadPhase, EveryPairWithinPenaltyReachIsACandidate) {
  std::mt19937 rng(11);
  for (int s = 0; s < kScenes; ++s) {
    Motion m = randomMotion(rng, 40 + s % 60, s % 2 ? 0.0 : 1e4);
    const double thickness = s % 4 == 0 ? 0.0 : std::pow(10.0, -(s % 5));
    PairCandidates candidates;
    candidates.build(m.scene, m.qs, m.qs, 0.5 * thickness);
    const std::set<uint64_t> keys = candidateKeys(m.scene, candidates);
    const VecX& x = m.qs;
    for (int i = 0; i < m.scene.numParticles(); ++i) {
      const double ri = m.scene.radius[i];
      for (int j = i + 1; j < m.scene.numParticles(); ++j) {
        if ((at(x, j) - at(x, i)).norm() < ri + m.scene.radius[j] + thickness) {
          EXPECT_TRUE(keys.count(pairKey(i, PairKind::ParticleParticle, j))) << s << ": " << i << " " << j;
        }
      }
      for (int e = 0; e < static_cast<int>(m.scene.edges.size()); ++e) {
        const Edge& edge = m.scene.edges[e];
        if (edge.i == i || edge.j == i) continue;
        const Vec2 d = math::segmentContactVector(at(x, i), at(x, edge.i), at(x, edge.j));
        if (d.norm() < ri + edge.radius + thickness) {
          EXPECT_TRUE(keys.count(pairKey(i, PairKind::ParticleEdge, e))) << s << ": " << i << " edge " << e;
        }
      }
      for (int h = 0; h < static_cast<int>(m.scene.halfplanes.size()); ++h) {
        const HalfPlane& plane = m.scene.halfplanes[h];
        if (math::halfPlaneContactVector(at(x, i), plane.point, plane.normal).norm() < ri + thickness) {
          EXPECT_TRUE(keys.count(pairKey(i, PairKind::ParticleHalfPlane, h))) << s << ": " << i << " plane " << h;
        }
      }
    }
  }
}

// After some particles move (as impulses or rigid zones move them), the incremental detection
// and the candidates of update()/pairsOf() agree with a fresh detection of every pair.
TEST(BroadPhase, IncrementalDetectionEqualsFullDetection) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int s = 0; s < kScenes / 6; ++s) {
    // Up to 400 particles: enough changed ones for the broad phase to file them in stale grids.
    Motion m = randomMotion(rng, 60 + 7 * s, s % 2 ? 0.0 : 1e3);
    CollisionSearch search(math::DetectionRules{});
    StepStats stats;
    StepContext ctx;
    ctx.stats = &stats;
    std::vector<Collision> previous, now;
    search.detectAll(m.scene, m.qs, m.qe, ctx, previous);
    expectSame(previous, allPairs(m.scene, m.qs, m.qe, math::DetectionRules{}));
    for (int round = 0; round < 6; ++round) {
      std::vector<int> changed;
      const int n = m.scene.numParticles();
      const int moves = round % 2 ? 1 + round : 1 + (round + s) * n / 40;
      for (int k = 0; k < moves; ++k) {
        const int p = static_cast<int>(unit(rng) * n);
        // back to the start (as an immovable zone), a small nudge, or a long throw (braced: the
        // two draws come left to right under every compiler, unlike a call's arguments)
        const double pick = unit(rng);
        if (pick < 0.3) {
          at(m.qe, p) = at(m.qs, p);
        } else if (pick < 0.8) {
          at(m.qe, p) += 1e-3 * Vec2{unit(rng) - 0.5, unit(rng) - 0.5};
        } else {
          at(m.qe, p) += 3.0 * Vec2{unit(rng) - 0.5, unit(rng) - 0.5};
        }
        changed.push_back(p);
      }
      search.detectChanged(m.scene, m.qs, m.qe, ctx, previous, changed, now);
      SCOPED_TRACE("scene " + std::to_string(s) + " round " + std::to_string(round));
      expectSame(now, allPairs(m.scene, m.qs, m.qe, math::DetectionRules{}));
      previous.swap(now);
    }
  }
}

// pairsOf keeps each particle's pairs between calls until a box they depend on is re-filed: a
// particle box that meets it, and with edges the boxes of the edges it meets or ends. Without
// edges the list is a particle's neighbours in one cache line (a long one spilling over); with
// edges, every particle and edge pair that involves it. After every round of moves (back to the
// start, nudges within the filed slack, long throws that re-file), every particle's kept list
// must equal what the grid gives now (particlesOf and edgesOf, which keep nothing), each pair
// once and in pair order. Lists are asked for before the moves too, so stale ones would be
// returned if a re-filed box did not forget them.
// keepAll: the lists made all at once from every row's keys (as the event handler's first
// detection reads them), ascending: the same checks then apply to them from the first round.
void keepAllFromRows(PairCandidates& c, int n) {
  std::vector<int> row;
  c.keepAll([&](auto&& visit) {
    for (int i = 0; i < n; ++i) c.forEachInRow(i, row, [&](PairKind kind, int other) { visit(pairKey(i, kind, other)); });
  });
}

void checkKeptPairLists(bool withEdges, uint32_t seed, bool keepAll = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long refiledPairsSeen = 0, longListsSeen = 0, edgePairsSeen = 0;
  for (int s = 0; s < 40; ++s) {
    Motion m = randomMotion(rng, 60 + 5 * s, s % 2 ? 0.0 : 1e3);
    if (!withEdges) m.scene.edges.clear();
    const int n = m.scene.numParticles();
    PairCandidates c;
    c.build(m.scene, m.qs, m.qe, 0.0, /*updates=*/true);
    ASSERT_FALSE(c.allPairs());
    std::vector<uint64_t> keys;
    if (keepAll) {  // over lists made one by one (long ones spilled), as from the second step on
      for (int p = 0; p < n; ++p) c.pairsOf(p, keys);
      c.build(m.scene, m.qs, m.qe, 0.0, /*updates=*/true);
      keepAllFromRows(c, n);
    }
    std::vector<int> row;
    std::vector<std::set<uint64_t>> before(n);
    auto listed = [&](int p) {  // pairsOf's particle and edge pairs, checked for order and repeats
      keys.clear();
      c.pairsOf(p, keys);
      std::vector<uint64_t> pairs;
      for (uint64_t k : keys)
        if (keyKind(k) != PairKind::ParticleHalfPlane) pairs.push_back(k);
      EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end())) << "particle " << p;
      EXPECT_EQ(std::adjacent_find(pairs.begin(), pairs.end()), pairs.end()) << "particle " << p << ": listed twice";
      return std::set<uint64_t>(pairs.begin(), pairs.end());
    };
    for (int round = 0; round < 8; ++round) {
      for (int p = 0; p < n; ++p) before[p] = listed(p);
      const int moves = 1 + (round + s) % 7 * n / 20;
      for (int k = 0; k < moves; ++k) {
        const int p = static_cast<int>(unit(rng) * n);
        const double pick = unit(rng);
        if (pick < 0.2) at(m.qe, p) = at(m.qs, p);
        else if (pick < 0.5) at(m.qe, p) += 1e-9 * Vec2{unit(rng) - 0.5, unit(rng) - 0.5};
        else at(m.qe, p) += 3.0 * Vec2{unit(rng) - 0.5, unit(rng) - 0.5};
        c.update(p);
      }
      c.settle();
      // What the grid holds now, every pair once, under each particle it involves.
      std::vector<std::set<uint64_t>> truth(n);
      for (int i = 0; i < n; ++i) {
        c.forEachInRow(i, row, [&](PairKind kind, int other) {
          if (kind == PairKind::ParticleHalfPlane) return;
          const uint64_t key = pairKey(i, kind, other);
          const PairParticles pair = pairParticles(m.scene, key);
          for (int k = 0; k < pair.count; ++k) truth[pair.p[k]].insert(key);
        });
      }
      SCOPED_TRACE("scene " + std::to_string(s) + " round " + std::to_string(round));
      ASSERT_EQ(c.sortedPairs(), m.scene.edges.empty());
      for (int p = 0; p < n; ++p) {
        const std::set<uint64_t> now = listed(p);
        EXPECT_EQ(now, truth[p]) << "particle " << p;
        refiledPairsSeen += now != before[p];
        longListsSeen += truth[p].size() > 16;
        for (uint64_t k : now) edgePairsSeen += keyKind(k) == PairKind::ParticleEdge;
      }
    }
  }
  EXPECT_GT(refiledPairsSeen, 100);  // the moves did change lists: a list kept blindly would fail
  // Huge disks and long throws: lists longer than a kept list's cache line holds (14) were checked.
  EXPECT_GT(longListsSeen, 100);
  if (withEdges) {
    EXPECT_GT(edgePairsSeen, 1000);
  }
}

TEST(BroadPhase, KeptPairListsFollowEveryRefiledBox) { checkKeptPairLists(false, 17); }
TEST(BroadPhase, KeptPairListsWithEdgesFollowEveryRefiledBox) { checkKeptPairLists(true, 19); }
TEST(BroadPhase, ListsKeptAllAtOnceAreThoseMadeOneByOneAndFollowEveryRefiledBox) {
  checkKeptPairLists(false, 23, /*keepAll=*/true);
}
TEST(BroadPhase, ListsWithEdgesKeptAllAtOnceAreThoseMadeOneByOneAndFollowEveryRefiledBox) {
  checkKeptPairLists(true, 37, /*keepAll=*/true);
}

// keepsAllNext: lists are made all at once in a step after one whose event loop read the lists of
// at least an eighth of the particles, whether it made them one by one or read them made all at
// once (counted either way, so the choice does not flip every other step), and not after a step
// that read fewer.
void checkKeepAllChoice(bool withEdges) {
  std::mt19937 rng(31);
  Motion m = randomMotion(rng, 160, 0.0);
  while (withEdges && m.scene.edges.empty()) m = randomMotion(rng, 160, 0.0);
  if (!withEdges) m.scene.edges.clear();
  const int n = m.scene.numParticles();
  PairCandidates c;
  std::vector<uint64_t> keys;
  auto step = [&](int read, bool keepAll) {  // a build, then the event loop reads `read` lists
    c.build(m.scene, m.qs, m.qe, 0.0, /*updates=*/true);
    const bool next = c.keepsAllNext();
    if (keepAll) keepAllFromRows(c, n);
    for (int p = 0; p < read; ++p) c.pairsOf(p, keys);
    return next;
  };
  ASSERT_EQ(n % 8, 0);
  EXPECT_FALSE(step(n / 8, false));    // nothing was read before the first step
  EXPECT_TRUE(step(n / 8, true));      // an eighth was read, made one by one
  EXPECT_TRUE(step(n / 8 - 1, false)); // an eighth was read, made all at once
  EXPECT_FALSE(step(0, false));        // one list fewer
  // Reading a list twice counts it once: twice n / 16 reads of n / 16 lists are not an eighth.
  EXPECT_FALSE(step(n / 16, false));
  for (int p = 0; p < n / 16; ++p) c.pairsOf(p, keys);
  EXPECT_FALSE(step(0, false));
}

TEST(BroadPhase, ListsAreKeptAllAtOnceAfterAStepThatReadManyOfThem) { checkKeepAllChoice(false); }
TEST(BroadPhase, ListsWithEdgesAreKeptAllAtOnceAfterAStepThatReadManyOfThem) { checkKeepAllChoice(true); }

// One candidates object built again for another scene of as many particles, first without
// edges, then with them, and back: its kept lists must be made for the new scene's kind (a list of
// neighbours, or of particle and edge pairs), never read from the old one's storage.
TEST(BroadPhase, ARebuildForAnotherSceneKeepsNoListOfTheOldOne) {
  std::mt19937 rng(29);
  Motion withEdges = randomMotion(rng, 80, 0.0);
  while (withEdges.scene.edges.empty()) withEdges = randomMotion(rng, 80, 0.0);
  Motion without = randomMotion(rng, 80, 0.0);
  without.scene.edges.clear();
  PairCandidates reused;
  std::vector<uint64_t> keys, fresh;
  for (const Motion* m : {&without, &withEdges, &without}) {
    reused.build(m->scene, m->qs, m->qe, 0.0, /*updates=*/true);
    PairCandidates once;
    once.build(m->scene, m->qs, m->qe, 0.0, /*updates=*/true);
    for (int p = 0; p < m->scene.numParticles(); ++p) {
      keys.clear();
      fresh.clear();
      reused.pairsOf(p, keys);
      once.pairsOf(p, fresh);
      ASSERT_EQ(keys, fresh) << "particle " << p << (m == &withEdges ? " (with edges)" : "");
    }
  }
}

// The continuous-time handler's sequential sweep: each hit moves its pair's particles at once
// (here: sends them back toward their start, or throws them far), and later pairs must see it.
// With small candidate blocks, the walk crosses many block boundaries.
TEST(BroadPhase, SequentialSweepEqualsReferenceSweep) {
  std::mt19937 rng(23);
  for (int s = 0; s < kScenes / 6; ++s) {
    Motion m = randomMotion(rng, 80 + 5 * s, s % 2 ? 0.0 : 1e3);
    auto respond = [&](const Collision& c, VecX& qe, std::vector<uint64_t>& seen) {
      seen.push_back(pairKey(c));
      int particles[3] = {c.i, c.j, c.kind == PairKind::ParticleEdge ? m.scene.edges[c.j].j : -1};
      if (c.kind == PairKind::ParticleEdge) particles[1] = m.scene.edges[c.j].i;
      if (c.kind == PairKind::ParticleHalfPlane) particles[1] = -1;
      for (int p : particles) {
        if (p < 0) continue;
        if (seen.size() % 5 == 0) at(qe, p) += Vec2(2.0, -1.5);  // a long throw
        else at(qe, p) = at(m.qs, p) + c.tau * (at(qe, p) - at(m.qs, p));
      }
    };
    VecX qeReference = m.qe, qeSweep = m.qe;
    std::vector<uint64_t> reference, swept;
    ContinuousDetector(math::DetectionRules{})
        .forEachCollision(m.scene, m.qs, qeReference, nullptr, [&](const Collision& c) { respond(c, qeReference, reference); });
    CollisionSearch search(math::DetectionRules{});
    search.setBlockSize(16 + s);
    StepStats stats;
    StepContext ctx;
    ctx.stats = &stats;
    search.sweep(m.scene, m.qs, qeSweep, ctx, [&](const Collision& c) { respond(c, qeSweep, swept); });
    ASSERT_EQ(reference, swept) << "scene " << s;
    ASSERT_TRUE(qeReference == qeSweep) << "scene " << s;
    // detectAll with small blocks too.
    std::vector<Collision> all;
    search.detectAll(m.scene, m.qs, m.qe, ctx, all);
    expectSame(all, allPairs(m.scene, m.qs, m.qe, math::DetectionRules{}));
  }
}

TEST(BroadPhase, NonFiniteStatesCheckEveryPair) {
  std::mt19937 rng(17);
  Motion m = randomMotion(rng, 30, 0.0);
  m.qe[5] = std::numeric_limits<double>::quiet_NaN();
  PairCandidates candidates;
  candidates.build(m.scene, m.qs, m.qe);
  EXPECT_TRUE(candidates.allPairs());
  std::vector<int> row;
  candidates.particlesOf(3, -1, row);
  EXPECT_EQ(row.size(), 26u);  // particles 4..29
}

// Finite but huge coordinates (+-9e307: their difference overflows) or radii make no grid either
// (the issue: the cell arithmetic overflowed, NaN was cast to int, SIGSEGV): every pair is a
// candidate, as for a non-finite state; and a whole step with every handler runs without a crash.
TEST(BroadPhase, CoordinatesBeyondTheGridCheckEveryPair) {
  std::mt19937 rng(18);
  for (const double huge : {9e307, -9e307, 1e301}) {
    Motion m = randomMotion(rng, 30, 0.0);
    m.qs[4] = m.qe[4] = huge;
    PairCandidates candidates;
    candidates.build(m.scene, m.qs, m.qe);
    EXPECT_TRUE(candidates.allPairs()) << huge;
  }
  Motion m = randomMotion(rng, 30, 0.0);
  m.scene.radius[7] = 1e305;
  PairCandidates candidates;
  candidates.build(m.scene, m.qs, m.qe);
  EXPECT_TRUE(candidates.allPairs());
}

}  // namespace
}  // namespace fosssim
