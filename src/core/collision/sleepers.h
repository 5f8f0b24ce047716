// Internal header: rest that costs nothing (the default mode's time-ordered handler).
//
// A particle that has stayed still for kStepsToSleep steps falls asleep: from then on it is an
// obstacle, like a fixed particle. The handler puts it back where the step started with zero
// velocity (whatever the integrator predicted), queries no pair whose particles are all asleep or
// fixed, and impulses and zones meet it with infinite mass. The forces between sleepers are not
// computed either (restingAtStart, ForceContext::resting), an implicit integrator leaves the
// sleepers out of its linear system, and a step in which every movable particle sleeps builds no
// broad phase: a resting pile then costs the step's passes over its particles and nothing else.
//
// What wakes a sleeper, and when (so that the default mode's promises hold):
//   * a contact that hits it harder than resting contact does: an event whose closing speed
//     exceeds twice what this step's forces gave the pair's awake particles (a particle resting
//     on a sleeper closes at about h g every step: that must not wake it, or no pile could
//     sleep) plus the sleep speed (sleepSpeed: the sleep distance over a still run). It wakes
//     in the same step, before the response, which then moves it as any other particle;
//   * a neighbour that moves: at the start of a step, every sleeper among the broad phase's
//     candidates of an awake particle that was not still in the last step wakes, if the mover
//     touches it or could reach it in this step (within its step's motion, and their boxes over
//     the step meet: the same sleepers with any broad phase or none). This is what
//     keeps a sleeper from floating when the particle under it is knocked away (one step late
//     at most: the step in which the support left).
// "Still" is measured in the scene's own scales, never in absolute units: over a step, a
// particle moved less than kSleepFraction of its radius and its velocity would move it less than
// that, and its speed is at most what would wake it (kWakeKickFactor kicks: without forces, only
// a particle exactly at rest is still, so one drifting slowly never sleeps whatever the step);
// and over the kStepsToSleep steps before it sleeps it moved less than kSleepFraction of its
// radius in all (a particle sliding slowly at constant speed does not sleep), and its forces did
// not go into its motion: its velocity changed by at most half the sum of its forces' kicks over
// those steps. A supported particle's kicks are taken up by its contacts; a ball at the top of
// its flight, with a step small enough against its radius, stays within the sleep distance for
// kStepsToSleep steps all the same, but its velocity changes by every kick.
//
// Particles whose motions are tied at a distance sleep only together, as one island: the two
// ends of an edge, the two particles of a spring, a gravitational or a vortex pair
// (Force::couples; fixed particles tie nobody). An island falls asleep in the step in which every
// member would sleep alone, and wakes whole: a hit on one member, or a mover near one, wakes all
// of it in that step (the members not hit stay where they slept for the rest of the step and move
// from the next). A scene with a force that cannot list what it ties lets nothing sleep. Nothing
// changes until a particle sleeps: a run in which none does is identical, bit for bit, to one
// with sleeping off (HandlerOptions::sleep).
#pragma once

#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"

#include <vector>

namespace fosssim {

/// Steps a particle must stay still before it sleeps. In steps, not seconds: scale-free, and long
/// enough that a ball at the top of its flight (still for one step) never sleeps. Box2D's time to
/// sleep, half a second, is 30 steps at its usual 60 Hz. The still run's other tests (the distance
/// in all, the kicks taken up) keep a slow slider or a falling ball awake whatever the length, and
/// a shorter run lets a settled pile sleep sooner. Measured with 60 and with 30
/// (fosssim-bench --scenes pile-low-cor0,pile-low-cor0.5,pile-high-cor0.5,pile-rest --sizes 2500
/// --steps 1000, two runs each, ms/step): pile-low-cor0 2.64-2.79 -> 2.35-2.45, pile-low-cor0.5
/// 3.08-3.10 -> 2.79-3.12, pile-high-cor0.5 2.91-3.03 -> 2.54-2.55, pile-rest 1.85-1.97 ->
/// 1.12-1.13; the oracles and every test but the count of the resting disk's steps are unchanged.
constexpr int kStepsToSleep = 30;

/// "Still": moving less than this fraction of the particle's radius per step (and in all over the
/// kStepsToSleep steps). A settled pile jitters by a few 10^-3 of its radius per step while its
/// failsafe stops and restarts neighbours (docs/performance-history.md): at 10^-3 the
/// benchmark's resting pile (pile-rest, 2,500 disks) was still 27% awake after 1,000 steps and
/// cost 12 ms/step; at 2 10^-3, 1.3% and 1.7 ms/step; at 3 10^-3 it was asleep by step 800 and
/// cost 0.35-0.43 ms/step from there (fosssim-bench --scenes pile-rest --sizes 2500 --steps 1000
/// --blocks; still runs of 60 steps then). The benchmark's "at rest" stays the stricter
/// |v| < 10^-3 r/dt.
constexpr double kSleepFraction = 3e-3;

/// A sleeper wakes when a contact closes faster than this many times what the step's forces gave
/// the awake particles of the pair along its normal (plus the sleep speed): resting contact
/// closes by about once ...
constexpr double kWakeKickFactor = 2.0;

/// ... and faster than this many of their kicks whatever the normal. A kick across a contact does
/// not close it, but a settling pile's particles move by up to about a kick in any direction
/// (the holds stop what is slower than kHeldKickFactor of one): with the normal's part alone,
/// neighbours side by side in pile-rest (2,500 disks) woke each other at 0.4 kick for ever, and
/// 0.4% of the pile never slept (its last block 0.31 ms/step against 0.075). With the whole kick
/// twice, as before, a disk sliding into a sleeper slower than 2 g h met it as a wall.
constexpr double kWakeJitterKicks = 1.0;

class Sleepers {
 public:
  /// Sleeping on or off (off: nothing ever sleeps, and nothing here costs more than the kicks).
  void setEnabled(bool on) { enabled_ = on; }
  /// Threads for the per-particle passes at a step's start and end (the same result for any).
  void setThreads(int threads) { threads_ = threads; }

  /// Step start: sizes the storage, works out who may sleep in this scene, and puts every
  /// sleeper back at its start position with zero velocity in `state` (the integrator's
  /// prediction); a sleeper that does not start the step where it fell asleep, at rest (moved
  /// between steps by a caller), wakes instead. h: the step.
  void begin(const Scene& scene, const State& start, State& state, double h);

  /// Before begin(), with the step's start: per particle (size N), 1 for each sleeper that
  /// begin() will put back where it rests (the sleepers a caller did not move) and for each
  /// fixed particle (never moved, whatever its force), or null when none sleeps. Valid until
  /// the next call.
  const std::vector<char>* restingAtStart(const Scene& scene, const State& start);

  /// Whether any particle sleeps in this step (nothing else here is needed when none does).
  bool any() const { return sleeping_ > 0; }
  bool asleep(int p) const { return sleeping_ > 0 && asleep_[p]; }
  /// Whether every movable particle sleeps in this step (after begin(): nothing moves).
  bool allAsleep() const { return sleeping_ > 0 && sleeping_ == mayRestCount_; }
  /// Wakes p and the rest of its island (no-op if awake): they count as moving again from now
  /// on. Returns how many woke.
  int wake(int p);
  /// The speed above which a contact of particles[0..count) hits its sleepers harder than
  /// resting contact does: kWakeKickFactor times `kicksAlong`, what this step's forces gave its
  /// awake movable particles along the contact's normal (ContactZones::kicksAlong), or
  /// kWakeJitterKicks times their whole kicks if more, plus the largest sleep speed of its
  /// sleepers. Infinite when none of them sleeps. Events compare their closing speed with it,
  /// the zones what a row's impulse stopped (ContactZones). Twice the whole kicks, as it was, let
  /// a disk sliding along a floor under gravity slower than 2 g h hit a sleeper as a wall (1,000
  /// kg at 0.15 m/s into 1 kg asleep, COR 0.5, dt 0.01: it bounced back at -0.075 m/s and the
  /// sleeper stayed, where both move on, at 0.150 and 0.225).
  double wakeSpeed(const Scene& scene, const int* particles, int count, double kicksAlong) const;
  /// Whether one of particles[0..count) sleeps (before the kicks along a contact are worked out).
  bool anyAsleep(const int* particles, int count) const {
    for (int k = 0; k < count; ++k)
      if (asleep(particles[k])) return true;
    return false;
  }
  /// Whether p did not stay still in the last step (a neighbour that moves wakes sleepers).
  bool movedLastStep(int p) const { return moved_.empty() || moved_[p] != 0; }
  /// The velocity change this step's forces gave particle p (|predicted v - start v|); known
  /// from begin() on, whether sleeping is on or not. A sleeper put back at rest keeps the kick
  /// of the step it fell asleep in (its forces may not have been computed whole: restingAtStart).
  double kick(int p) const { return kickVector(p).norm(); }
  /// The same velocity change as a vector (its direction: gravity's, in a pile under gravity).
  Vec2 kickVector(int p) const { return kickVector_.segment<2>(2 * p); }
  /// Particle p's velocity at the step's start, before this step's kick (known from begin() on).
  Vec2 startVelocity(int p) const { return startVelocity_.segment<2>(2 * p); }
  /// Particle p's speed at the step's start.
  double startSpeed(int p) const { return startVelocity(p).norm(); }
  /// The sleep speed of particle p: the speed at which it could stay within the sleep distance
  /// over a whole still run (kSleepFraction of its radius in kStepsToSleep steps). Not the
  /// distance per step over h: at a small step that is fast (3 10^-3 r / h: 1.5 m/s for r = 0.1
  /// at dt 2 10^-4), and a ball of Newton's cradle hitting a sleeper at 1 m/s bounced off it as
  /// off a wall.
  double sleepSpeed(const Scene& scene, int p) const {
    return kSleepFraction * scene.radius[p] / (kStepsToSleep * h_);
  }

  /// Step end: counts who stayed still, and puts to sleep those still for kStepsToSleep steps.
  void end(const Scene& scene, const State& start, State& state);
  /// Particles asleep now.
  int sleeping() const { return sleeping_; }

 private:
  bool enabled_ = true;          ///< sleeping on (setEnabled); off, nothing sleeps
  int threads_ = 1;              ///< threads for the per-particle passes (setThreads)
  double h_ = 1;                 ///< the step h, as begin() got it
  int sleeping_ = 0;             ///< particles asleep now (sleeping())
  std::vector<char> mayRest_;    ///< N: may sleep in this scene (see the top of this file)
  std::vector<char> asleep_;     ///< N
  std::vector<int> still_;       ///< N: consecutive steps still
  std::vector<char> moved_;      ///< N: was not still in its last step awake (a woken sleeper has not moved)
  VecX anchor_;                  ///< 2N: position when the particle's still run began
  VecX anchorVelocity_;          ///< 2N: velocity when the particle's still run began
  std::vector<double> kicks_;    ///< N: sum of kick() over the particle's still run
  VecX rest_;                    ///< 2N: a sleeper's position (where it fell asleep)
  VecX kickVector_;              ///< 2N: this step's predicted v - start v (kick() is its norm)
  VecX restKickVector_;          ///< 2N: a sleeper's kick vector in the step it fell asleep
  std::vector<char> resting_;    ///< N: restingAtStart's answer
  int mayRestCount_ = 0;         ///< particles that may sleep (movable, when the forces list their ties)
  VecX startVelocity_;           ///< 2N: start v (the step's velocities before its kicks)
  std::vector<std::pair<int, int>> coupled_;  ///< pairs the forces and edges tie (see Force::couples)
  std::vector<int> islandOf_;    ///< N: island of two or more particles, or -1 (empty: none)
  std::vector<int> islandStart_; ///< islands + 1: each island's first index into islandMembers_
  std::vector<int> islandMembers_;  ///< the islands' particles, island by island
  std::vector<char> ready_;      ///< N: an island member that would sleep now were it alone
  std::vector<std::pair<int, int>> islandTies_;  ///< coupled_ when the islands were last found
  std::vector<char> islandFixed_;  ///< N: the fixed flags when the islands were last found

  void findIslands(const Scene& scene);  ///< from coupled_, unless it and the fixed flags are unchanged
  int wakeIsland(int k);  ///< wakes island k's sleepers; returns how many
  void fallAsleep(int p, State& state);
  /// Asleep, and starts the step where it fell asleep at rest (not moved by a caller).
  bool restsAtStart(const State& start, int p) const {
    return asleep_[p] && at(start.x, p) == at(rest_, p) && at(start.v, p) == Vec2::Zero();
  }
};

}  // namespace fosssim
