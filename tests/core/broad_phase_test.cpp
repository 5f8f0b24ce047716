// The broad phase against checking every pair, on random scenes built to be hard for it: radii
// over six orders of magnitude, fast movers crossing the scene in one step, nearly static pairs
// (whose CCD polynomials lose leading coefficients to the cutoff), tiny and collapsing edges,
// coordinates far from the origin, pairs placed just outside reach.
//   * every pair the narrow phase finds colliding is a candidate (swept boxes), and every pair
//     within the penalty force's reach is a candidate (static boxes);
//   * the incremental detections (after some particles move) equal fresh full detections;
//   * the candidates stay complete after update().
// The lists of pairs it keeps per particle: broad_phase_lists_test.cpp.
#include "broad_phase_pairs.h"

#include <algorithm>
#include <random>
#include <set>

namespace fosssim {
namespace {

using testing::allPairs;
using testing::candidateKeys;
using testing::Motion;
using testing::randomMotion;



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
    candidates.setMargins(Margins::Course);  // the course's narrow phase below (CollisionSearch's boxes)
    candidates.build(m.scene, m.qs, m.qe);
    ASSERT_FALSE(candidates.allPairs());
    const std::set<uint64_t> keys = candidateKeys(m.scene, candidates);
    // Both quintic forms, with FOSSSim's own interval rule: the reference's (IntervalRule::Reference)
    // reads signs at r -+ 1, which for roots beyond ~1e8 steps cancels catastrophically and can
    // report far pairs at t = 0 (as the reference itself does); the broad phase does not
    // reproduce those, see collision_search.h.
    for (const math::DetectionRules& rules :
         {math::DetectionRules{}, math::DetectionRules{math::QuinticForm::Reference}}) {
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
        .forEachCollision(m.scene, m.qs, qeReference, nullptr,
                          [&](const Collision& c) { respond(c, qeReference, reference); });
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

// A scene's candidates do not depend on where it sits. A square of n x n touching disks (radius
// 0.05 on a grid of spacing 0.1, all falling by the same small step) has as candidates exactly
// its touching pairs, along the rows and columns and along the diagonals (whose boxes touch too):
// 2 n (n - 1) + 2 (n - 1)^2, near the origin and 2^17 m from it, whose rounding (ulps of 3e-11)
// the margins' allowance covers. With margins of 4e-6 of the coordinates, the far square's boxes
// were 0.5 m wider than its disks, and every disk was a candidate of some 400 others.
TEST(BroadPhase, CandidatesDoNotDependOnWhereTheSceneSits) {
  const int n = 30;
  const long touching = 2L * n * (n - 1) + 2L * (n - 1) * (n - 1);
  for (const double offset : {0.0, -1.0, 131072.0, -131072.0}) {
    Motion m;
    m.qs.resize(2 * n * n);
    m.qe.resize(2 * n * n);
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) {
        const int p = row * n + col;
        addParticle(m.scene, 1.0, false, 0.05);
        at(m.qs, p) = Vec2(offset + 0.1 * col, offset + 0.1 * row);
        at(m.qe, p) = at(m.qs, p) + Vec2(0.0, -2.45e-4);
      }
    PairCandidates candidates;
    candidates.build(m.scene, m.qs, m.qe);
    ASSERT_FALSE(candidates.allPairs());
    EXPECT_EQ(static_cast<long>(candidateKeys(m.scene, candidates).size()), touching) << "offset " << offset;
  }
}

}  // namespace
}  // namespace fosssim
