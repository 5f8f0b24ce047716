// Checking a step of the time-ordered handler after the fact (--verify, tests). Its particles
// move on straight pieces that bend at contacts, so a straight-line detection from start to end
// would test a chord the particles never followed. Instead every pair is tested piece by piece:
// between consecutive bends of its particles both move in straight lines, and the ordinary
// continuous-time query applies. A pair that comes into contact on a piece and overlaps deeper
// than rounding before the piece ends (pair_query.h) is reported, unless one rigid zone moved
// all of it.
//
// Candidates: each particle's whole path lies in the box spanned by the corners (lowest and
// highest coordinates) of its path points, so the broad phase is built on those corners.
#include "event_handler.h"
#include "pair_query.h"

#include <algorithm>

namespace fosssim {
namespace {


/// Each particle's path: start, its breaks in time order, end.
class Paths {
 public:
  Paths(const VecX& start, const VecX& end, const std::vector<MotionBreak>& breaks) : start_(start), end_(end) {
    const int n = static_cast<int>(start.size() / 2);
    first_.assign(n + 1, 0);
    for (const MotionBreak& b : breaks) ++first_[b.particle + 1];
    for (int p = 0; p < n; ++p) first_[p + 1] += first_[p];
    points_.resize(breaks.size());
    std::vector<int> fill(first_.begin(), first_.end() - 1);
    for (const MotionBreak& b : breaks) points_[fill[b.particle]++] = b;  // breaks come in time order
  }

  /// Position of particle p at step fraction t.
  Vec2 at(int p, double t) const {
    double t0 = 0, t1 = 1;
    Vec2 x0 = fosssim::at(start_, p), x1 = fosssim::at(end_, p);
    for (int k = first_[p]; k < first_[p + 1]; ++k) {
      if (points_[k].t <= t) t0 = points_[k].t, x0 = points_[k].x;
      else {
        t1 = points_[k].t, x1 = points_[k].x;
        break;
      }
    }
    return t1 > t0 ? Vec2(x0 + (t - t0) / (t1 - t0) * (x1 - x0)) : x0;
  }

  void appendTimes(int p, std::vector<double>& times) const {
    for (int k = first_[p]; k < first_[p + 1]; ++k) times.push_back(points_[k].t);
  }

  /// Lowest and highest coordinates of every path (2N each).
  void corners(VecX& lo, VecX& hi) const {
    lo = start_.cwiseMin(end_);
    hi = start_.cwiseMax(end_);
    for (const MotionBreak& b : points_) {
      fosssim::at(lo, b.particle) = fosssim::at(lo, b.particle).cwiseMin(b.x);
      fosssim::at(hi, b.particle) = fosssim::at(hi, b.particle).cwiseMax(b.x);
    }
  }

 private:
  const VecX& start_;
  const VecX& end_;
  std::vector<int> first_;
  std::vector<MotionBreak> points_;
};

}  // namespace

std::vector<Violation> EventHandler::unresolved(const Scene& scene, const VecX& start, const VecX& end,
                                                size_t limit) const {
  std::vector<Violation> found;
  const Paths paths(start, end, motion_.breaks());
  VecX lo, hi;
  paths.corners(lo, hi);
  PairCandidates candidates;
  candidates.build(scene, lo, hi);
  std::vector<double> times;
  auto check = [&](uint64_t key) {
    const PairParticles pair = pairParticles(scene, key);
    times.assign({0.0, 1.0});
    for (int k = 0; k < pair.count; ++k) paths.appendTimes(pair.p[k], times);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    for (size_t s = 0; s + 1 < times.size(); ++s) {
      const double ta = times[s], tb = times[s + 1];
      math::ExactContact contact;
      const auto motion = [&](int p, Vec2& x, Vec2& d) {
        x = paths.at(p, ta);
        d = paths.at(p, tb) - x;
      };
      if (queryPair(scene, key, motion, contact) == math::CcdOutcome::Miss) continue;
      const double t = ta + contact.tau * (tb - ta);
      // A contact is a violation only if the pair's overlap deepens beyond rounding before its
      // piece ends: a shallower one is the contact that ended the piece seen a little early
      // (event times and interpolated pieces agree only to rounding; the time of first contact
      // is ill-conditioned for a pair closing slowly) or a disk sliding over a joint a few ulps
      // below touching. An overlap the step starts with was judged when it formed. A contact
      // exactly at t = 1 belongs to the next step, which starts with it.
      double length = 0;
      const auto position = [&](int p, double at) { return paths.at(p, at); };
      if (pairDeepening(scene, key, position, t, tb, length) <= kDepthTolerance * length) continue;
      bool exempt = keyKind(key) != PairKind::ParticleHalfPlane;  // as in EventHandler::respond
      int zone = -2;
      for (int k = 0; k < pair.count; ++k) {
        if (scene.isFixed(pair.p[k])) {
          exempt = false;
          continue;
        }
        const int z = zoneOf(pair.p[k]);
        exempt = exempt && z >= 0 && (zone == -2 || z == zone);
        zone = z;
      }
      if (exempt && zone != -2) return;
      found.push_back(Violation{keyKind(key), keyParticle(key), keyOther(key), t});
      return;
    }
  };
  std::vector<int> row;
  const int n = scene.numParticles();
  // The corners' box is not the motion: every half-plane is tested (they are few).
  for (int i = 0; i < n && (limit == 0 || found.size() < limit); ++i)
    candidates.forEachInRow(i, row, [&](PairKind kind, int other) { check(pairKey(i, kind, other)); },
                            /*everyPlane=*/true);
  if (limit > 0 && found.size() > limit) found.resize(limit);
  return found;
}

}  // namespace fosssim
