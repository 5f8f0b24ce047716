// The collision penalty force. For a pair at distance vector n (from the particle to the closest
// point of the other object), radii r1 and r2 (r2 = 0 for a half-plane) and |n| < r1 + r2 + h:
//   E = k/2 (|n| - r1 - r2 - h)^2,  dE/dx_particle = -k (|n| - r1 - r2 - h) n/|n|
// and the other object takes the opposite gradient: the other particle whole, an edge's endpoints
// weighted (1 - alpha) and alpha at the closest point's parameter alpha (held fixed: by the
// envelope theorem that is the exact gradient where alpha is interior). An exact overlap
// (|n| = 0) has no direction and gets no force. The expressions keep the reference's order of
// operations (the gap as |n| - r1 - r2 - h, the unit vector first): course grading
// compares velocities to 1e-10, and contact-heavy scenes amplify last-bit differences.
#include "fosssim/core/forces.h"

#include "core/collision/parallel_rows.h"
#include "core/forces/penalty_scratch.h"

#include "fosssim/math/geometry.h"

#include <algorithm>
#include <vector>

namespace fosssim {
namespace {

/// The rows of resting particles that hold no pair acting on a moving particle: those whose box
/// meets no moving particle's box and no box of an edge with a moving endpoint (the candidates'
/// relation is symmetric: a row lists exactly the boxes that meet its particle's). Found from
/// the moving side, so it pays only when most particles rest (the caller asks only then; null
/// with every pair a candidate: every row is read, and restsWhole alone drops the resting pairs).
const char* skipRows(const Scene& scene, const PairCandidates& candidates, const char* rests, int threads,
                     PenaltyScratch& scratch) {
  const int n = scene.numParticles();
  if (candidates.allPairs()) return nullptr;
  std::vector<char>& skip = scratch.skipRows;
  skip.assign(rests, rests + n);
  const int ranges = rowRangesFor(n, threads);
  if (scratch.border.size() < static_cast<size_t>(ranges)) scratch.border.resize(ranges);
  // Each range lists the resting particles its moving particles meet; they are marked after the
  // join, so no two threads write one byte. Then the edges with an endpoint that moves.
  forRowRanges(n, threads, [&](int range, int first, int end) {
    std::vector<int>& border = scratch.border[range];
    border.clear();
    auto mark = [&](int j) {
      if (rests[j]) border.push_back(j);
    };
    for (int p = first; p < end; ++p)
      if (!rests[p]) candidates.forEachParticleMeetingParticle(p, mark);
  });
  for (size_t e = 0; e < scene.edges.size(); ++e) {
    const Edge& edge = scene.edges[e];
    if (rests[edge.i] && rests[edge.j]) continue;
    candidates.forEachParticleMeetingEdge(static_cast<int>(e), [&](int j) { skip[j] = 0; });
  }
  for (int range = 0; range < ranges; ++range)
    for (int j : scratch.border[range]) skip[j] = 0;
  return skip.data();
}

/// Visits every pair within reach, in the reference's order (for each particle i: particles
/// j > i, edges not incident to i, half-planes). The broad phase proposes the pairs whose boxes
/// (grown by the radius, half the thickness and the exactness margin) meet, in that order; the
/// test |n| < r1 + r2 + h below is the reference's, so exactly the same pairs are visited in the
/// same order, and the gradient sums come out the same to the last bit.
///
/// With `resting` (ForceContext::resting: particles whose force nobody reads), the pairs whose
/// particles all rest are left out, and so is the row of a resting particle that holds no other
/// pair (skipRows below). Each pair left acts on a particle that moves and is visited in the
/// same order as without `resting`, so every moving particle's sums are the same to the last bit.
template <class Visit>
void forEachPenaltyPair(const Scene& scene, const VecX& x, double thickness, ForceContext& context,
                        const std::vector<char>* resting, Visit&& visit) {
  PenaltyScratch& scratch = context.penaltyScratch();
  PairCandidates& candidates = scratch.candidates;
  std::vector<std::vector<int>>& rows = scratch.rows;
  std::vector<std::vector<PenaltyPair>>& found = scratch.found;
  const int n = scene.numParticles(), threads = context.threads();
  const char* rests = resting && static_cast<int>(resting->size()) == n ? resting->data() : nullptr;
  const long restCount = rests ? std::count_if(rests, rests + n, [](char r) { return r != 0; }) : 0;
  if (restCount == n && n > 0) return;  // every pair acts on resting particles only
  // A negative thickness shrinks the reach; the boxes are then simply not widened.
  candidates.build(scene, x, x, std::max(0.0, 0.5 * thickness), false, threads);
  if (context.allPairs()) candidates.forceAllPairs();
  const char* skip = 2 * restCount >= n ? skipRows(scene, candidates, rests, threads, scratch) : nullptr;
  // Whether a pair acts on resting particles only (a half-plane has none of its own: a = b = -1).
  auto restsWhole = [rests](int i, int a, int b) {
    return rests && rests[i] && (a < 0 || rests[a]) && (b < 0 || rests[b]);
  };
  // Rows [first, end), each pair within reach handed to `take`.
  auto scan = [&](int first, int end, std::vector<int>& row, auto&& take) {
    auto consider = [&](int i, const Vec2& d, double r1, double r2, int a, int b, double alpha) {
      if (restsWhole(i, a, b)) return;
      const double length = d.norm();
      if (length < r1 + r2 + thickness) take(PenaltyPair{i, d, length, length - r1 - r2 - thickness, a, b, alpha});
    };
    for (int i = first; i < end; ++i) {
      if (skip && skip[i]) continue;
      const Vec2 xi = at(x, i);
      const double ri = scene.radius[i];
      candidates.forEachInRow(i, row, [&](PairKind kind, int other) {
        switch (kind) {
          case PairKind::ParticleParticle:
            consider(i, at(x, other) - xi, ri, scene.radius[other], other, -1, 0.0);
            break;
          case PairKind::ParticleEdge: {
            const Edge& e = scene.edges[other];
            double alpha = 0;
            const Vec2 d = math::segmentContactVector(xi, at(x, e.i), at(x, e.j), &alpha);
            consider(i, d, ri, e.radius, e.i, e.j, alpha);
            break;
          }
          case PairKind::ParticleHalfPlane: {
            const HalfPlane& plane = scene.halfplanes[other];
            consider(i, math::halfPlaneContactVector(xi, plane.point, plane.normal), ri, 0.0, -1, -1, 0.0);
            break;
          }
        }
      });
    }
  };
  const int ranges = rowRangesFor(n, threads);
  if (rows.size() < static_cast<size_t>(ranges)) rows.resize(ranges), found.resize(ranges);
  if (ranges <= 1) {
    scan(0, n, rows[0], visit);
    return;
  }
  // With threads: each range of rows lists its pairs, then they are visited in row order, so
  // the sums come out exactly as with one thread.
  // Each range works on its own vectors moved out of the shared arrays and back: their headers
  // sit side by side there, and every push_back would write a cache line the other thread uses.
  forRowRanges(n, threads, [&](int range, int first, int end) {
    std::vector<int> row = std::move(rows[range]);
    std::vector<PenaltyPair> pairs = std::move(found[range]);
    pairs.clear();
    scan(first, end, row, [&](const PenaltyPair& p) { pairs.push_back(p); });
    rows[range] = std::move(row);
    found[range] = std::move(pairs);
  });
  for (int range = 0; range < ranges; ++range)
    for (const PenaltyPair& p : found[range]) visit(p);
}

}  // namespace

double PenaltyForce::energy(const Scene& scene, const VecX& x, const VecX& v) const {
  ForceContext context;
  return energyWith(scene, x, v, context);
}

void PenaltyForce::addGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE) const {
  ForceContext context;
  addGradientWith(scene, x, v, gradE, context);
}

double PenaltyForce::energyWith(const Scene& scene, const VecX& x, const VecX&, ForceContext& context) const {
  double e = 0;
  forEachPenaltyPair(scene, x, thickness_, context, nullptr,
                     [&](const PenaltyPair& p) { e += 0.5 * k_ * p.gap * p.gap; });
  return e;
}

void PenaltyForce::addGradientWith(const Scene& scene, const VecX& x, const VecX&, VecX& gradE,
                                   ForceContext& context) const {
  forEachPenaltyPair(scene, x, thickness_, context, context.resting(), [&](const PenaltyPair& p) {
    if (p.length == 0.0) return;
    const Vec2 nhat = divide(p.n, p.length);
    at(gradE, p.i) -= k_ * p.gap * nhat;
    if (p.b >= 0) {  // edge a-b
      at(gradE, p.a) += (1 - p.alpha) * k_ * p.gap * nhat;
      at(gradE, p.b) += p.alpha * k_ * p.gap * nhat;
    } else if (p.a >= 0) {  // particle a
      at(gradE, p.a) += k_ * p.gap * nhat;
    }
  });
}

}  // namespace fosssim
