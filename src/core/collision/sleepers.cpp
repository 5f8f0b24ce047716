#include "sleepers.h"

#include "parallel_rows.h"

#include <algorithm>
#include <limits>

namespace fosssim {

void Sleepers::begin(const Scene& scene, const State& start, State& state, double h) {
  h_ = h;
  const int n = scene.numParticles();
  // The kicks, whether sleeping is on or not: the zones' held particles need them too, and end()
  // sums them over still runs.
  if (startVelocity_.size() != 2 * n) startVelocity_.setZero(2 * n), kickVector_.setZero(2 * n);
  // A sleeper's prediction is thrown away below, and its forces may have been left incomplete
  // (restingAtStart): it keeps the kick it had when it fell asleep (read if a hit wakes it).
  const bool sleepers = enabled_ && sleeping_ > 0 && static_cast<int>(asleep_.size()) == n;
  forRowRanges(n, threads_, [&](int, int first, int end) {
    for (int p = first; p < end; ++p) {
      const bool rests = sleepers && restsAtStart(start, p);
      at(kickVector_, p) = rests ? Vec2(at(restKickVector_, p)) : Vec2(at(state.v, p) - at(start.v, p));
      at(startVelocity_, p) = at(start.v, p);
    }
  });
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
    restKickVector_.setZero(2 * n);
    rest_ = start.x;
    sleeping_ = 0;
  }
  // Who may sleep, and with whom: the scene's contents do not change during a run, but this
  // costs O(N + E + forces) and keeps no stale answer if a caller edits a scene between runs.
  mayRest_.assign(n, 0);
  mayRestCount_ = 0;
  coupled_.clear();
  bool listed = true;
  for (const auto& f : scene.forces) listed = f->couples(coupled_) && listed;
  if (listed) {
    for (int p = 0; p < n; ++p) mayRest_[p] = !scene.isFixed(p);
    mayRestCount_ = static_cast<int>(std::count(mayRest_.begin(), mayRest_.end(), 1));
    for (const Edge& e : scene.edges) coupled_.emplace_back(e.i, e.j);
  } else {
    coupled_.clear();  // nothing sleeps: no islands to keep
  }
  findIslands(scene);
  if (sleeping_ == 0) return;
  // By ranges of particles: each one's work is its own; the sleepers woken are counted per range.
  std::vector<int> woken(static_cast<size_t>(rowRangesFor(n, threads_)), 0);
  forRowRanges(n, threads_, [&](int range, int first, int end) {
    for (int p = first; p < end; ++p) {
      if (!asleep_[p]) continue;
      // A sleeper starts the step where it fell asleep, at rest, unless someone else moved it
      // between steps (a script assigning positions or velocities, the grader's state): then it
      // wakes and takes the integrator's prediction like any particle.
      if (!restsAtStart(start, p)) {
        asleep_[p] = 0, still_[p] = 0, ++woken[range];  // wake(), its count summed below
        continue;
      }
      at(state.x, p) = at(start.x, p);
      at(state.v, p).setZero();
    }
  });
  for (int w : woken) sleeping_ -= w;
  // An island wakes whole: a member a caller moved woke above, its island-mates wake with it
  // (at rest where they slept: they move from the next step on).
  if (islandStart_.empty() || std::all_of(woken.begin(), woken.end(), [](int w) { return w == 0; })) return;
  for (int k = 0; k + 1 < static_cast<int>(islandStart_.size()); ++k) {
    bool awake = false;
    for (int m = islandStart_[k]; m < islandStart_[k + 1]; ++m) awake = awake || !asleep_[islandMembers_[m]];
    if (awake) wakeIsland(k);
  }
}

const std::vector<char>* Sleepers::restingAtStart(const Scene& scene, const State& start) {
  const int n = scene.numParticles();
  if (!enabled_ || sleeping_ == 0 || static_cast<int>(asleep_.size()) != n) return nullptr;
  resting_.resize(static_cast<size_t>(n));
  forRowRanges(n, threads_, [&](int, int first, int end) {
    for (int p = first; p < end; ++p) resting_[p] = static_cast<char>(scene.isFixed(p) || restsAtStart(start, p));
  });
  return &resting_;
}

int Sleepers::wake(int p) {
  if (!asleep(p)) return 0;
  const int k = islandOf_.empty() ? -1 : islandOf_[p];
  if (k >= 0) return wakeIsland(k);
  asleep_[p] = 0, still_[p] = 0, --sleeping_;
  return 1;
}

double Sleepers::wakeSpeed(const Scene& scene, const int* particles, int count, double kicksAlong) const {
  double kicks = 0, sleepSpeed = 0;
  bool sleeper = false;
  for (int k = 0; k < count; ++k) {
    const int p = particles[k];
    if (asleep(p)) sleeper = true, sleepSpeed = std::max(sleepSpeed, this->sleepSpeed(scene, p));
    else if (!scene.isFixed(p)) kicks += kick(p);
  }
  if (!sleeper) return std::numeric_limits<double>::infinity();
  return std::max(kWakeKickFactor * kicksAlong, kWakeJitterKicks * kicks) + sleepSpeed;
}

// Every member of island k that sleeps wakes (some may be awake already: a member a caller moved).
int Sleepers::wakeIsland(int k) {
  int woken = 0;
  for (int m = islandStart_[k]; m < islandStart_[k + 1]; ++m) {
    const int q = islandMembers_[m];
    if (asleep_[q]) asleep_[q] = 0, still_[q] = 0, --sleeping_, ++woken;
  }
  return woken;
}

// Union-find over the coupled pairs of movable particles (a fixed end ties nobody); only islands
// of two or more are kept (a lone particle sleeps by itself, as it always did). The islands
// depend on the ties and the fixed flags alone, so they are found again only when one of those
// changed (a caller edited the scene): comparing costs a pass, not the union-find's allocations.
void Sleepers::findIslands(const Scene& scene) {
  const int n = scene.numParticles();
  bool same = coupled_ == islandTies_ && static_cast<int>(islandFixed_.size()) == n;
  for (int p = 0; same && p < n; ++p) same = islandFixed_[p] == static_cast<char>(scene.isFixed(p));
  if (same) return;
  islandTies_ = coupled_;
  islandFixed_.resize(static_cast<size_t>(n));
  for (int p = 0; p < n; ++p) islandFixed_[p] = static_cast<char>(scene.isFixed(p));
  islandOf_.clear();
  islandStart_.clear();
  islandMembers_.clear();
  if (coupled_.empty()) return;
  std::vector<int> parent(static_cast<size_t>(n));
  for (int p = 0; p < n; ++p) parent[p] = p;
  const auto root = [&](int p) {
    while (parent[p] != p) p = parent[p] = parent[parent[p]];
    return p;
  };
  bool any = false;
  for (const auto& [a, b] : coupled_) {
    if (a == b || scene.isFixed(a) || scene.isFixed(b)) continue;
    const int ra = root(a), rb = root(b);
    if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb), any = true;
  }
  if (!any) return;
  // Islands numbered by their smallest particle, members in particle order (CSR).
  islandOf_.assign(n, -1);
  ready_.assign(n, 0);
  std::vector<int> count(static_cast<size_t>(n), 0), index(static_cast<size_t>(n), -1);
  for (int p = 0; p < n; ++p) ++count[root(p)];
  islandStart_.push_back(0);
  for (int p = 0; p < n; ++p) {
    if (root(p) != p || count[p] < 2) continue;
    index[p] = static_cast<int>(islandStart_.size()) - 1;
    islandStart_.push_back(islandStart_.back() + count[p]);
  }
  islandMembers_.resize(static_cast<size_t>(islandStart_.back()));
  std::vector<int> fill(islandStart_.begin(), islandStart_.end() - 1);
  for (int p = 0; p < n; ++p) {
    const int k = index[root(p)];
    if (k < 0) continue;
    islandOf_[p] = k;
    islandMembers_[static_cast<size_t>(fill[k]++)] = p;
  }
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
      if (!islandOf_.empty()) ready_[p] = 0;
      if (asleep_[p] || !mayRest_[p]) continue;
      const double reach = kSleepFraction * scene.radius[p], kicked = kick(p);  // a norm: taken once
      const bool still = (at(state.x, p) - at(start.x, p)).norm() <= reach && h_ * at(state.v, p).norm() <= reach &&
                         at(state.v, p).norm() <= kWakeKickFactor * kicked;
      moved_[p] = !still;
      if (!still) {
        still_[p] = 0;
        continue;
      }
      if (still_[p]++ == 0) at(anchor_, p) = at(start.x, p), at(anchorVelocity_, p) = at(start.v, p), kicks_[p] = 0;
      kicks_[p] += kicked;
      // Creeping: still in every step, yet a sleep distance from where its run began. It starts a
      // new run from here, and counts as moved, so that the sleepers it can reach wake
      // (EventHandler::wakeNearMoving): checked only at the run's end, and without counting as
      // moved, a disk creeping at 2.6 cm/s (r 0.1, dt 0.01) from under a sleeper it had been
      // knocked from left the sleeper hovering for good, 0.2 m above the floor.
      if ((at(state.x, p) - at(anchor_, p)).norm() > reach) {
        still_[p] = 0;
        moved_[p] = 1;
        continue;
      }
      if (still_[p] < kStepsToSleep) continue;
      // Unsupported (its forces went into its motion: a ball at the top of its flight): a new run.
      // Without forces there is nothing to take up, and the distance above decides.
      if (kicks_[p] > 0.0 && (at(state.v, p) - at(anchorVelocity_, p)).norm() > 0.5 * kicks_[p]) {
        still_[p] = 0;
        continue;
      }
      // A member of an island waits for the others (below).
      if (!islandOf_.empty() && islandOf_[p] >= 0) {
        ready_[p] = 1;
        continue;
      }
      fallAsleep(p, state);
      ++fell[range];
    }
  });
  for (int f : fell) sleeping_ += f;
  // An island sleeps when every member is ready in the same step.
  for (size_t k = 0; k + 1 < islandStart_.size(); ++k) {
    bool all = true;
    for (int m = islandStart_[k]; m < islandStart_[k + 1] && all; ++m) all = ready_[islandMembers_[m]] != 0;
    if (!all) continue;
    for (int m = islandStart_[k]; m < islandStart_[k + 1]; ++m) fallAsleep(islandMembers_[m], state), ++sleeping_;
  }
}

// Asleep from the next step on; where it ended, at rest (its last velocity was below the sleep
// speed: dropping it is what sleeping means).
void Sleepers::fallAsleep(int p, State& state) {
  asleep_[p] = 1;
  at(restKickVector_, p) = at(kickVector_, p);
  moved_[p] = 0;
  at(state.v, p).setZero();
  at(rest_, p) = at(state.x, p);
}

}  // namespace fosssim
