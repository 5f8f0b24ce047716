// Internal header: the default mode's continuous-time query of one pair over part of a step, on
// the scale-invariant capsule CCD of the math library (ccd_exact.h), and the pair's closing
// speed along a contact normal. Shared by the time-ordered handler and its verification.
#pragma once

#include "pair_candidates.h"

#include "fosssim/core/scene.h"
#include "fosssim/math/ccd_exact.h"
#include "fosssim/math/geometry.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace fosssim {

/// Queries pair `key` over an interval of the step. motion(p, x, d) gives particle p's position
/// x at the interval's start and its displacement d over the interval. On a hit, `contact`
/// holds the time as a fraction of the interval, the unit normal from the particle toward the
/// other object and the edge parameter.
template <class Motion>
math::CcdOutcome queryPair(const Scene& scene, uint64_t key, Motion&& motion, math::ExactContact& contact) {
  const int i = keyParticle(key), other = keyOther(key);
  Vec2 x1, d1;
  motion(i, x1, d1);
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: {
      Vec2 x2, d2;
      motion(other, x2, d2);
      return math::exactPP(math::PPInput{x1, d1, scene.radius[i], x2, d2, scene.radius[other]}, &contact);
    }
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      Vec2 x2, d2, x3, d3;
      motion(e.i, x2, d2);
      motion(e.j, x3, d3);
      return math::exactPE(math::PEInput{x1, d1, scene.radius[i], x2, d2, x3, d3, e.radius}, &contact);
    }
    case PairKind::ParticleHalfPlane: {
      const HalfPlane& h = scene.halfplanes[other];
      return math::exactPH(math::PHInput{x1, d1, scene.radius[i], h.point, h.normal}, &contact);
    }
  }
  return math::CcdOutcome::Miss;
}

/// How fast pair `key` closes along `normal` (unit, from the particle toward the other object),
/// given each particle's rate(p): positive when approaching. `scale` receives the sum of the
/// pair's rates' magnitudes, against which a closing speed is judged to be rounding.
template <class Rate>
double closingSpeed(const Scene& scene, uint64_t key, const Vec2& normal, double alpha, Rate&& rate, double& scale) {
  const int i = keyParticle(key), other = keyOther(key);
  const Vec2 vi = rate(i);
  Vec2 vo = Vec2::Zero();
  scale = vi.norm();
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: vo = rate(other), scale += vo.norm(); break;
    case PairKind::ParticleEdge: {
      const Vec2 va = rate(scene.edges[other].i), vb = rate(scene.edges[other].j);
      vo = (1.0 - alpha) * va + alpha * vb;
      scale += va.norm() + vb.norm();
      break;
    }
    case PairKind::ParticleHalfPlane: break;
  }
  return (vi - vo).dot(normal);
}

/// Closing speeds at or below this fraction of the pair's own speeds are the rounding left by a
/// resolved contact (an inelastic response leaves a closing speed of a few ulps of the speeds):
/// an impulse cannot act on them (one along a normal that does not close would add energy).
constexpr double kRestingClosingFraction = 1e-9;

/// Overlap depths below this fraction of a pair's length scale (its coordinates and radii) are
/// rounding. A pair counts as penetrating only when its overlap deepens by more than this.
constexpr double kDepthTolerance = 1e-10;

/// Overlap depth of pair `key` (positive: overlapping) with its particles at position(p).
template <class Position>
double pairDepth(const Scene& scene, uint64_t key, Position&& position) {
  const int i = keyParticle(key), other = keyOther(key);
  const Vec2 x = position(i);
  switch (keyKind(key)) {
    case PairKind::ParticleParticle: return scene.radius[i] + scene.radius[other] - (position(other) - x).norm();
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[other];
      return scene.radius[i] + e.radius - math::segmentContactVector(x, position(e.i), position(e.j)).norm();
    }
    case PairKind::ParticleHalfPlane: {
      const HalfPlane& h = scene.halfplanes[other];
      return scene.radius[i] - (x - h.point).dot(h.normal) / h.normal.norm();
    }
  }
  return 0;
}

/// The fractions of [t, tb] at which pairDeepening samples a pair, in increasing order:
/// geometrically closer to t (a pair passing through penetrates soon after its contact: 2^-39 ..
/// 2^-1) and evenly (an edge's rotation deepens slowly: k/32), then tb itself.
inline const std::vector<double>& deepeningSamples() {
  static const std::vector<double> fractions = [] {
    std::vector<double> f;
    for (double g = 0.5; g > 1e-12; g *= 0.5) f.push_back(g);
    for (int k = 1; k <= 32; ++k) f.push_back(k / 32.0);
    std::sort(f.begin(), f.end());
    f.erase(std::unique(f.begin(), f.end()), f.end());
    return f;
  }();
  return fractions;
}

/// Pair `key`'s length scale at time t (its particles' coordinates and radii), which
/// kDepthTolerance is a fraction of.
template <class Position>
double pairLength(const Scene& scene, uint64_t key, Position&& position, double t) {
  const PairParticles pair = pairParticles(scene, key);
  double length = 0;
  for (int k = 0; k < pair.count; ++k) length += position(pair.p[k], t).norm() + scene.radius[pair.p[k]];
  return length;
}

/// How much pair `key` deepens its overlap between t and tb, with its particles at position(p,
/// s) at time s: the largest amount by which its depth at a sample s exceeds the least depth it
/// had between t and s (or touching, if it was apart then). An overlap the pair already has does
/// not count, but one that eases and then deepens again does, from where it eased to (an edge
/// rotating back into a disk it overlaps: measured from t alone, the deeper overlap at t hid the
/// second approach, which --verify then found). `length` receives the pair's length scale at t
/// and `when` (optional) the time of the deepest point of the largest rise (tb if none).
template <class Position>
double pairDeepening(const Scene& scene, uint64_t key, Position&& position, double t, double tb, double& length,
                     double* when = nullptr) {
  auto depthAt = [&](double s) { return pairDepth(scene, key, [&](int p) { return position(p, s); }); };
  double least = std::max(depthAt(t), 0.0), rise = -std::numeric_limits<double>::infinity(), best = tb;
  for (double f : deepeningSamples()) {
    const double s = f < 1.0 ? t + f * (tb - t) : tb;
    const double d = depthAt(s);
    if (d - least > rise) rise = d - least, best = s;
    least = std::min(least, std::max(d, 0.0));
  }
  if (when) *when = best;
  length = pairLength(scene, key, position, t);
  return rise;
}

/// Whether a particle-particle or particle-half-plane pair whose particles move in straight lines
/// over [t, tb], and that closes at rate `closing` at t (closingSpeed's: displacement per unit of
/// t), provably deepens its overlap there by at most kDepthTolerance of its `length`
/// (pairLength): its distance is convex in time (linear against a half-plane), so its depth is
/// concave and lies below its tangent at t, and it deepens by at most closing (tb - t). Then
/// pairDeepening, whose samples cannot exceed the true deepening, would say the same: a resting
/// pile's contacts skip its 80 samples (4% of rain's time at 10^4). A particle-edge pair (the
/// edge may rotate) is never settled here.
inline bool cannotDeepen(PairKind kind, double closing, double t, double tb, double length) {
  return kind != PairKind::ParticleEdge && closing * (tb - t) <= kDepthTolerance * length;
}

/// The step fraction in [t, 1] at which pair `key` overlaps deepest, if its overlap deepens there
/// by more than kDepthTolerance of its length; -1 if it does not. `closing`: its closing rate at t
/// (closingSpeed's), with which cannotDeepen settles a straight pair without pairDeepening's
/// samples. (The event loop's and the zones' test of a contact that barely closes.)
template <class Position>
double deepeningTime(const Scene& scene, uint64_t key, Position&& position, double closing, double t) {
  if (cannotDeepen(keyKind(key), closing, t, 1.0, pairLength(scene, key, position, t))) return -1.0;
  double length = 0, when = 1.0;
  return pairDeepening(scene, key, position, t, 1.0, length, &when) > kDepthTolerance * length ? when : -1.0;
}

}  // namespace fosssim
