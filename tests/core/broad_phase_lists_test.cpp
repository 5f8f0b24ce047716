// The lists of pairs the broad phase keeps per particle (PairCandidates::pairsOf, keepAll): after
// any moves they equal what its grid gives now, whether made one by one or all at once; the
// choice between the two follows the step before; and a rebuild for another scene keeps none of
// the old one's lists. Scenes from broad_phase_pairs.h (randomMotion).
#include "broad_phase_pairs.h"

#include <algorithm>
#include <random>
#include <set>

namespace fosssim {
namespace {

using testing::Motion;
using testing::randomMotion;

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
    for (int i = 0; i < n; ++i)
      c.forEachInRow(i, row, [&](PairKind kind, int other) { visit(pairKey(i, kind, other)); });
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

}  // namespace
}  // namespace fosssim
