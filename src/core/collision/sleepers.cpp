#include "sleepers.h"

#include "parallel_rows.h"

#include <algorithm>

namespace fosssim {

void Sleepers::begin(const Scene& scene, const State& start, State& state, double h) {
  h_ = h;
  const int n = scene.numParticles();
  if (!enabled_) {
    sleeping_ = 0;
    return;
  }
  if (static_cast<int>(asleep_.size()) != n) {
    asleep_.assign(n, 0);
    still_.assign(n, 0);
    moved_.assign(n, 1);
    anchor_ = start.x;
    anchorVelocity_ = start.v;
    kicks_.assign(n, 0.0);
    rest_ = start.x;
    kick_.assign(n, 0.0);
    sleeping_ = 0;
  }
  // Who may sleep: the scene's contents do not change during a run, but this costs O(N + E)
  // and keeps no stale answer if a caller edits a scene between runs.
  mayRest_.assign(n, 0);
  const bool forcesAlone =
      std::all_of(scene.forces.begin(), scene.forces.end(), [](const auto& f) { return f->actsAlone(); });
  if (forcesAlone) {
    for (int p = 0; p < n; ++p) mayRest_[p] = !scene.isFixed(p);
    for (const Edge& e : scene.edges)
      if (!scene.isFixed(e.i) || !scene.isFixed(e.j)) mayRest_[e.i] = mayRest_[e.j] = 0;
  }
  // The kicks are needed whether anyone sleeps or not (end() sums them over still runs).
  if (sleeping_ == 0) {
    forRowRanges(n, threads_, [&](int, int first, int end) {
      for (int p = first; p < end; ++p) kick_[p] = (at(state.v, p) - at(start.v, p)).norm();
    });
    return;
  }
  // By ranges of particles: each one's work is its own; the sleepers woken are counted per range.
  std::vector<int> woken(static_cast<size_t>(rowRangesFor(n, threads_)), 0);
  forRowRanges(n, threads_, [&](int range, int first, int end) {
    for (int p = first; p < end; ++p) {
      kick_[p] = (at(state.v, p) - at(start.v, p)).norm();
      if (!asleep_[p]) continue;
      // A sleeper starts the step where it fell asleep, at rest, unless someone else moved it
      // between steps (a script assigning positions or velocities, the grader's state): then it
      // wakes and takes the integrator's prediction like any particle.
      if (at(start.x, p) != at(rest_, p) || at(start.v, p) != Vec2::Zero()) {
        asleep_[p] = 0, still_[p] = 0, ++woken[range];  // wake(), its count summed below
        continue;
      }
      at(state.x, p) = at(start.x, p);
      at(state.v, p).setZero();
    }
  });
  for (int w : woken) sleeping_ -= w;
}

void Sleepers::wake(int p) {
  if (!asleep(p)) return;
  asleep_[p] = 0;
  still_[p] = 0;
  --sleeping_;
}

// A sleeper stays asleep here (its still count keeps growing); an awake particle is still when
// both its displacement over the step and its end velocity's would be below the sleep distance,
// and it sleeps once it has been still for kStepsToSleep steps and within that distance of where
// its still run began.
void Sleepers::end(const Scene& scene, const State& start, State& state) {
  if (!enabled_) return;
  const int n = scene.numParticles();
  std::vector<int> fell(static_cast<size_t>(rowRangesFor(n, threads_)), 0);  // asleep now, per range
  forRowRanges(n, threads_, [&](int range, int first, int end) {
    for (int p = first; p < end; ++p) {
      if (asleep_[p] || !mayRest_[p]) continue;
      const double reach = kSleepFraction * scene.radius[p];
      const bool still =
          (at(state.x, p) - at(start.x, p)).norm() <= reach && h_ * at(state.v, p).norm() <= reach;
      moved_[p] = !still;
      if (!still) {
        still_[p] = 0;
        continue;
      }
      if (still_[p]++ == 0) at(anchor_, p) = at(start.x, p), at(anchorVelocity_, p) = at(start.v, p), kicks_[p] = 0;
      kicks_[p] += kick_[p];
      if (still_[p] < kStepsToSleep) continue;
      if ((at(state.x, p) - at(anchor_, p)).norm() > reach) {
        still_[p] = 0;  // creeping: start a new run from here
        continue;
      }
      // Unsupported (its forces went into its motion: a ball at the top of its flight): a new run.
      // Without forces there is nothing to take up, and the distance above decides.
      if (kicks_[p] > 0.0 && (at(state.v, p) - at(anchorVelocity_, p)).norm() > 0.5 * kicks_[p]) {
        still_[p] = 0;
        continue;
      }
      // Asleep from the next step on; where it ended, at rest (its last velocity was below the
      // sleep speed: dropping it is what sleeping means).
      asleep_[p] = 1;
      moved_[p] = 0;
      at(state.v, p).setZero();
      at(rest_, p) = at(state.x, p);
      ++fell[range];
    }
  });
  for (int f : fell) sleeping_ += f;
}

}  // namespace fosssim
