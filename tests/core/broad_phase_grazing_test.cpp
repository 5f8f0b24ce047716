// The broad phase's margins, on pairs that graze (see the tests): boxes of the bare shapes miss
// collisions that the narrow phase reports, the candidates with margins none. Both kinds of
// narrow phase: the course's (absolute margins) and the default mode's exact queries (relative
// margins), near the origin and far from it.
#include "broad_phase_pairs.h"
#include "core/collision/pair_bounds.h"
#include "core/collision/pair_query.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace fosssim {
namespace {

using testing::allPairs;
using testing::candidateKeys;
using testing::Motion;

// Adds particles 1 and 2 (radius r) and the edge between them (radius r), lying across the
// separating axis at x1 + x21, `place` of its length below that point, both ends moving by d and
// the second by `wobble` more.
void addEdgeAcross(Motion& m, const Vec2& x1, const Vec2& x21, const Vec2& across, double r, double length,
                   double place, const Vec2& d, const Vec2& wobble) {
  addParticle(m.scene, 1.0, false, r);
  addParticle(m.scene, 1.0, false, r);
  at(m.qs, 1) = x1 + x21 - place * length * across;
  at(m.qs, 2) = at(m.qs, 1) + length * across;
  at(m.qe, 1) = at(m.qs, 1) + d;
  at(m.qe, 2) = at(m.qs, 2) + d + wobble;
  m.scene.edges.push_back(Edge{1, 2, r});
}

// Whether the pair of particle 0 and the other object of a sample (kind 0: particle 1; 1:
// half-plane 0; 2: edge 0) is apart by the boxes (or signed distances) of the bare shapes, their
// radii times `reach`.
bool bareShapesApart(const Motion& m, int kind, double reach) {
  const auto bare = [&](int p) { return sweptPointBox(m.qs, m.qe, p, reach * m.scene.radius[p]); };
  if (kind == 0) return !overlap(bare(0), bare(1));
  if (kind == 1) {
    const HalfPlane& h = m.scene.halfplanes[0];
    const double s0 = (at(m.qs, 0) - h.point).dot(h.normal), s1 = (at(m.qe, 0) - h.point).dot(h.normal);
    const double r = reach * m.scene.radius[0] * h.normal.norm();
    return (s0 > r && s1 > r) || (s0 < -r && s1 < -r);
  }
  return !overlap(bare(0), sweptEdgeBox(m.scene, m.qs, m.qe, 0, reach * m.scene.edges[0].radius));
}

// Pairs that graze: the closest approach lies along an axis, just outside or inside reach, with
// displacements so small that the CCD drops leading coefficients (|c| < 1e-12) and so reports
// collisions that exact arithmetic would not. These are the pairs the margins exist for: boxes
// without margins miss some of them (counted below, to show the test can fail), ours none.
TEST(BroadPhase, GrazingPairsNeedTheMargins) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  auto logU = [&](double lo, double hi) { return std::pow(10.0, u(lo, hi)); };
  // x drawn before y, and every draw below in its own statement: a call's arguments and a sum's
  // operands are evaluated in an order the compiler picks (gcc right to left, clang left to right).
  auto uv = [&](double lo, double hi) {
    const double x = u(lo, hi);
    const double y = u(lo, hi);
    return Vec2(x, y);
  };
  long hits = 0, missedWithoutMargins = 0;
  for (int sample = 0; sample < 60000; ++sample) {
    Motion m;
    const int kind = sample % 3;  // 0 PP, 1 PH, 2 PE
    const int axis = static_cast<int>(u(0, 2)), other = 1 - axis;
    const double sign = u(0, 1) < 0.5 ? -1.0 : 1.0;
    const double offset = std::vector<double>{0.0, 1.0, 1e3}[static_cast<int>(u(0, 3))];
    const double gapSign = u(0, 1) < 0.2 ? -1.0 : 1.0;
    const double gap = gapSign * logU(-16, -3);
    const double delta = logU(-9, -4);
    const double r1 = logU(-7, 0), r2 = logU(-7, 0);
    // Near the origin too: there the absolute part of the margin must do all the work.
    const double spread = offset == 0.0 && u(0, 1) < 0.5 ? 1e-5 : 1.0;
    Vec2 x1 = Vec2::Constant(offset) + spread * uv(-1, 1);
    const double d1Length = logU(-10, -3);
    Vec2 d1 = d1Length * uv(-1, 1);
    Vec2 along = Vec2::Zero(), across = Vec2::Zero();
    along[axis] = sign;
    across[other] = 1.0;
    // Relative motion mostly across the separating axis, passing the closest point; or, every
    // other sample, the worst case of the cutoff: the motion's square below 1e-12 is dropped
    // from the position quadratic while the linear term stays, which admits gaps up to about
    // y0 (2 delta - y0) / (2 R) (y0 the offset across, delta the displacement).
    const bool worst = sample % 2 == 1;
    const double crossing = worst ? u(7.1e-7, 1e-6) : delta;
    const double y0 = worst ? u(1e-12 / crossing, 2 * crossing) : u(0, 1) * crossing;
    const double gapUsed = worst && kind == 0 ? u(0, 1) * y0 * (2 * crossing - y0) / (2 * (r1 + r2)) : gap;
    Vec2 d21 = crossing * across;
    if (!worst) {
      const double slant = u(-0.2, 0.2);
      const double side = u(0, 1) < 0.5 ? -1.0 : 1.0;
      d21 = delta * (slant * along + side * across);
    }
    const Vec2 x21 = (r1 + r2 + gapUsed) * along - y0 * across;
    m.qs.resize(kind == 2 ? 6 : (kind == 0 ? 4 : 2));
    m.qe.resize(m.qs.size());
    addParticle(m.scene, 1.0, false, r1);
    at(m.qs, 0) = x1;
    at(m.qe, 0) = x1 + d1;
    if (kind == 0) {
      addParticle(m.scene, 1.0, false, r2);
      at(m.qs, 1) = x1 + x21;
      at(m.qe, 1) = at(m.qs, 1) + d1 + d21;
    } else if (kind == 1) {
      const double scale = logU(-4, 4);  // the normal is not normalised
      if (worst) {  // the same for the signed distance: normal motion nu, gap in (nu, nu + nu^2 / 2r)
        const double nu = u(1e-12 / (r1 * scale * scale), 1e-6 / scale);
        const double g = nu + u(0, 1) * nu * nu / (2 * r1);
        m.scene.halfplanes.push_back(HalfPlane{x1 - (r1 + g) * along + u(-1, 1) * across, scale * along});
        at(m.qe, 0) = x1 - nu * along + u(-1, 1) * delta * across;
      } else {
        m.scene.halfplanes.push_back(HalfPlane{x1 - (r1 + gap) * along + u(-1, 1) * across, -scale * along});
        const double slant = u(-0.2, 0.2);
        const double aside = u(-1, 1);
        at(m.qe, 0) = x1 + delta * (slant * along + aside * across);
      }
    } else {
      const double length = logU(-3, 1);
      const double place = u(0, 1);
      const double wobble = logU(-10, -5);
      addEdgeAcross(m, x1, x21, across, r2, length, place, d1 + d21, wobble * uv(-1, 1));
    }
    // Ground truth: every pair the narrow phase reports.
    for (const math::DetectionRules& rules :
         {math::DetectionRules{}, math::DetectionRules{math::QuinticForm::Reference}}) {
      const std::vector<Collision> found = allPairs(m.scene, m.qs, m.qe, rules);
      PairCandidates candidates;
      candidates.setMargins(Margins::Course);  // the course's cut-off is what these pairs graze
      candidates.build(m.scene, m.qs, m.qe);
      const std::set<uint64_t> keys = candidateKeys(m.scene, candidates);
      for (const Collision& c : found) {
        if (c.kind != static_cast<PairKind>(kind == 2 ? 1 : (kind == 1 ? 2 : 0))) continue;
        ++hits;
        EXPECT_TRUE(keys.count(pairKey(c))) << "sample " << sample << ": " << pairKindName(c.kind) << " gap " << gap;
        missedWithoutMargins += bareShapesApart(m, kind, 1.0);  // boxes without margins
      }
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(missedWithoutMargins, 0) << "no grazing pair needed the margins: the test would not notice their absence";
  std::printf("grazing pairs: %ld collisions, %ld of them missed by boxes without margins\n", hits,
              missedWithoutMargins);
}

// The default mode's exact queries (pair_query.h) on pairs that graze, near the origin and far from
// it (up to 10^7), slow and fast: every pair they report is a candidate of PairCandidates' boxes
// (Margins::Relative, the default). Those boxes' margins follow the pairs' own sizes and motions
// (and the coordinates only by an allowance for their rounding, kCoordinateRounding), so far from
// the origin they are as narrow as near it. The exact queries report no pair beyond the bare
// shapes' reach here, but many within a hair of it: boxes short of the shapes by a billionth of
// their radii miss some (counted, to show the test would notice boxes that fall short).
TEST(BroadPhase, PairsTheExactQueriesReportAreCandidatesAnywhere) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto u = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  auto logU = [&](double lo, double hi) { return std::pow(10.0, u(lo, hi)); };
  auto uv = [&](double lo, double hi) {  // x drawn before y (see above)
    const double x = u(lo, hi);
    const double y = u(lo, hi);
    return Vec2(x, y);
  };
  const double offsets[] = {0.0, 1.0, 1e3, 1e5, 1e7};
  long hits = 0, farHits = 0, missedByShortBoxes = 0;
  for (int sample = 0; sample < 30000; ++sample) {
    Motion m;
    const int kind = sample % 3;  // 0 PP, 1 PH, 2 PE
    const int axis = static_cast<int>(u(0, 2)), other = 1 - axis;
    const double sign = u(0, 1) < 0.5 ? -1.0 : 1.0;
    const double offset = offsets[static_cast<int>(u(0, 5))];
    // Gaps around the rounding of the coordinates (ulps of the offset), either side of reach.
    const double gapSign = u(0, 1) < 0.3 ? -1.0 : 1.0;
    const double gap = gapSign * logU(-17, -11) * std::max(offset, 1.0);
    const double r1 = logU(-8, 0), r2 = logU(-8, 0);
    const double motion = sample % 2 ? logU(-12, -6) : logU(-3, 0);  // slow or fast
    Vec2 x1 = Vec2::Constant(offset) + uv(-1, 1);
    Vec2 along = Vec2::Zero(), across = Vec2::Zero();
    along[axis] = sign;
    across[other] = 1.0;
    const Vec2 d1 = motion * uv(-1, 1);
    const double side = u(0, 1) < 0.5 ? -1.0 : 1.0;
    const Vec2 d21 = motion * (u(-0.2, 0.2) * along + side * across);  // passing the closest point
    const Vec2 x21 = (r1 + r2 + gap) * along - u(0, 1) * motion * side * across;
    m.qs.resize(kind == 2 ? 6 : (kind == 0 ? 4 : 2));
    m.qe.resize(m.qs.size());
    addParticle(m.scene, 1.0, false, r1);
    at(m.qs, 0) = x1;
    at(m.qe, 0) = x1 + d1;
    uint64_t key = 0;
    if (kind == 0) {
      addParticle(m.scene, 1.0, false, r2);
      at(m.qs, 1) = x1 + x21;
      at(m.qe, 1) = at(m.qs, 1) + d1 + d21;
      key = pairKey(0, PairKind::ParticleParticle, 1);
    } else if (kind == 1) {
      const double scale = logU(-4, 4);  // the normal is not normalised
      m.scene.halfplanes.push_back(HalfPlane{x1 - (r1 + gap) * along + u(-1, 1) * across, scale * along});
      at(m.qe, 0) = x1 + motion * (u(-1e-3, 0) * along + side * across);
      key = pairKey(0, PairKind::ParticleHalfPlane, 0);
    } else {
      const double length = logU(-3, 1);
      const double place = u(0, 1);
      const double wobble = logU(-12, -5);
      addEdgeAcross(m, x1, x21, across, r2, length, place, d1 + d21, wobble * uv(-1, 1));
      key = pairKey(0, PairKind::ParticleEdge, 0);
    }
    // Ground truth: the exact query over the step, as the time-ordered handler asks it at t = 0.
    math::ExactContact contact;
    const auto stepMotion = [&](int p, Vec2& x, Vec2& d) {
      x = at(m.qs, p);
      d = at(m.qe, p) - at(m.qs, p);
    };
    if (queryPair(m.scene, key, stepMotion, contact) != math::CcdOutcome::Hit) continue;
    ++hits;
    farHits += offset >= 1e5;
    PairCandidates candidates;
    candidates.build(m.scene, m.qs, m.qe);
    ASSERT_FALSE(candidates.allPairs());
    EXPECT_TRUE(candidateKeys(m.scene, candidates).count(key))
        << "sample " << sample << ": " << pairKindName(keyKind(key)) << " at offset " << offset << ", gap " << gap;
    missedByShortBoxes += bareShapesApart(m, kind, 1.0 - 1e-9);  // a billionth short of the shapes
  }
  EXPECT_GT(hits, 3000);
  EXPECT_GT(farHits, 1000);
  EXPECT_GT(missedByShortBoxes, 0) << "no pair grazed: the test would not notice boxes that fall short";
  std::printf("exact queries' grazing pairs: %ld hits (%ld at 10^5 or farther), %ld missed by boxes 1e-9 short\n", hits,
              farHits, missedByShortBoxes);
}

}  // namespace
}  // namespace fosssim
