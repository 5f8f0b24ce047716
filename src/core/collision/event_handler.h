// Internal header: the default mode's "continuous-time" and "hybrid" handling, contacts in time
// order within each step (--compat keeps the reference's handlers, collision_handlers.h).
//
//   detect   every candidate pair over the whole step (broad phase, then the scale-invariant
//            capsule query); each hit is an event (time, pair) in a min-heap;
//   respond  events in time order: bring the pair's particles to the event time, apply one
//            impulse against their current velocities (hits of one instant together, by
//            Moreau's law, never summed from stale velocities: simultaneous_hits.cpp), bend their
//            paths there, and query again only the pairs of the particles that changed, over the
//            rest of the step; stale events (a particle changed since) are dropped; resting
//            contact (closing at about the step's kick) takes COR 0 (kRestingBounceKicks);
//   failsafe a particle that has taken its quota of impulse events in this step (a resting pile,
//            a ball in a wedge: the Zeno cascades of event-driven methods) hands its contacts to
//            the impact zones of contact_zones.h, which stop them approaching without a loop;
//            the contacts that reach the zones at one instant join them first, and the zones
//            are solved once for the instant; the contacts a budget-ended solve leaves closing
//            come back at its instant, together (ContactZones::solvesNow), and at their own
//            times as well (an edge rotating toward a particle meets it only there);
//   sleep    particles at rest sleep: obstacles that cost nothing until woken (sleepers.h);
//   finish   every particle ends its last straight piece at t = 1.
// Free flight between events is exact and impulses act along the line through the contact, so
// momentum and angular momentum are kept to rounding; an impulse with COR <= 1 and a zone's
// projection never add kinetic energy. A contact closing slower than kRestingClosingFraction of
// its pair's speeds is resolved already (pair_query.h).
#pragma once

#include "contact_zones.h"
#include "continuous_detection.h"
#include "pair_candidates.h"
#include "sleepers.h"
#include "step_motion.h"

#include "fosssim/core/collision_handler.h"

#include <vector>

namespace fosssim {

/// Impulse events per particle and step for "continuous-time" before its contacts go to the
/// failsafe (hybrid's is its maxiters): far more than a Newton's cradle's ball needs (two), few
/// enough that a resting pile reaches the zones quickly. A particle's first event of the step
/// counts, and each later one that follows its previous one within 1/quota of the step or
/// within kQuotaFreeTravel of its radius of travel: a cascade that impulses do not settle (a
/// pile, a ball wedged in a V) packs its events close in space if not in time, while a fast
/// particle crossing a box spreads them over both, and at most quota of those fit in a step (so
/// a particle takes at most twice its quota). Counting every event sent two disks crossing a
/// small box five times a step at COR 1 to the zones, which jammed them and took 94% of their
/// kinetic energy.
constexpr int kContinuousEventsPerParticle = 32;
/// See kContinuousEventsPerParticle: a fraction of the particle's radius. Events of a settling
/// pile's disks, spread over the step but each a small fraction of a radius from the last,
/// count as they did (pile-rest 2,500 makes the same Gauss-Seidel updates as with every event
/// counted; with time alone, 20% more: its disks took twice the impulses before the zones).
constexpr double kQuotaFreeTravel = 0.5;

/// Impulse events a particle may take at one instant (events of the same time) before its
/// contacts there go to the failsafe, whatever its quota for the step. Impulses of one instant
/// are a simultaneous impact solved contact by contact; a particle that needs more than this many
/// is in one that they are not settling: a ball pinned between two fixed disks at COR 1 bounces
/// between them for ever at one instant, and with hybrid's quota of maxiters = 10,000 took
/// 10,000 impulses a step (28 ms a step for 8 particles, fuzz_scene_steps). A Newton's cradle's
/// ball takes two; no particle of `rain` 2,500, `chains` 1,000 or the oracle scenes reaches it
/// (their runs are the same to the bit with and without). The projection settles the rest.
constexpr int kEventsPerInstant = 32;

/// Hits closer in time than this fraction of the step are one instant, answered together
/// (simultaneous_hits.cpp). Contact times carry rounding: two contacts that mirror each other
/// meet at times apart by a few ulps once a response before them rounded differently on the two
/// sides, and a tie broken so was answered one contact at a time, in pair order, which made the
/// mirror images part at full size (the touching rack of tests/core/simultaneous_hits_test.cpp at
/// COR 0.5: 0.025 m/s within a step). Far below what distinct contacts need: disks 1e-12 of their
/// step's travel apart meet 1e-12 of a step apart.
constexpr double kSimultaneousHits = 1e-12;

class EventHandler final : public CollisionHandler {
 public:
  /// eventsPerParticle: impulse events a particle may take in a step before the failsafe (0:
  /// every contact goes to the zones at once). options: allPairs (no broad phase), threads (the
  /// first detection's rows), sleep (resting particles sleep).
  EventHandler(const CollisionSettings& settings, int eventsPerParticle, const HandlerOptions& options);
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;
  int zoneOf(int particle) const override;
  bool keepsPairsApart() const override { return true; }
  const std::vector<char>* restingAtStart(const Scene& scene, const State& start) override {
    return sleepers_.restingAtStart(scene, start);
  }
  std::vector<Violation> unresolved(const Scene& scene, const VecX& start, const VecX& end,
                                    size_t limit) const override;

 private:
  struct Event {
    double t = 0;      ///< step fraction
    uint64_t key = 0;  ///< the pair
    Vec2 normal = Vec2::Zero();  ///< unit, from the particle toward the other object
    double alpha = 0;  ///< particle-edge: the edge parameter
    uint32_t version[3] = {0, 0, 0};  ///< the pair's particles' versions when it was found
  };
  /// Earliest first; equal times in pair order, so the result never depends on discovery order.
  /// A function object, not a function: the heap's algorithms then inline the comparison (through
  /// a function pointer GCC kept the calls, 1-2% of a pile's step).
  struct Later {
    bool operator()(const Event& a, const Event& b) const { return a.t > b.t || (a.t == b.t && a.key > b.key); }
  };

  /// Queries every candidate pair over the step: rows in contiguous ranges, one per thread
  /// (parallel_rows.h), whose events join the heap, so the result is the same for any count.
  Status detectAll(const Scene& scene, StepContext& ctx);
  /// Queries every pair of the particles in changed_ over [T, 1].
  Status detectChanged(const Scene& scene, double T, StepContext& ctx);
  /// Queries one pair over [T, 1]; a contact is appended to `out` as an event. Reads only.
  Status query(const Scene& scene, uint64_t key, double T, StepStats& stats, std::vector<Event>& out) const;
  void pushEvents(std::vector<Event>& events);
  /// Whether detectChanged queries `key` from changed particle p: no lower particle of the pair
  /// is in changed_ (which lists it too).
  bool listsFrom(const Scene& scene, uint64_t key, int p) const;
  /// Solves, at time T, the zones that contacts of the instant T joined (each once).
  void solvePendingZones(const Scene& scene, double T, State& state, StepContext& ctx);
  bool stale(const Scene& scene, const Event& e) const;
  /// Whether the pair cannot meet: a sleeper and nothing that moves (the others fixed or asleep).
  bool sleepingPair(const Scene& scene, uint64_t key) const;
  /// Wakes the sleepers of the event's pair if it closes harder than resting contact (sleepers.h);
  /// closing: its closing speed (m/s, as the kicks and the sleep speed it is compared with).
  /// Wakes the sleepers of event e's pair if its contact closes faster than Sleepers::wakeSpeed
  /// with the pair's kicks along its normal.
  void wakeIfHit(const Scene& scene, const Event& e, double closing, StepStats& stats);
  /// Whether the pair's boxes over the step (motion_'s start to end, grown by the radii and
  /// kTouchingSlack of them) meet: a test the broad phase's candidates always pass.
  bool stepBoxesMeet(const Scene& scene, uint64_t key) const;
  /// Wakes every sleeper among the candidates of a particle that moved in the last step.
  void wakeNearMoving(const Scene& scene, StepStats& stats);
  /// What an event asks for, read from the current motions and zones (assess).
  enum class Route { Resolved, Zones, Impulse };
  struct Assessment {
    Route route = Route::Resolved;
    double closing = 0;   ///< its closing rate (displacement per step along its normal, closingSpeed's)
    double deepest = -1;  ///< the step fraction where a curving contact overlaps deepest (-1: not curving)
  };
  /// Where event e goes: resolved already (nothing to do), to the zones, or an impulse. With
  /// `wake`, the sleepers it hits wake first (wakeIfHit), as its response needs; without, it is a
  /// look that changes nothing (respondTogether's choice of the hits to solve together).
  Assessment assess(const Scene& scene, const Event& e, double h, StepStats& stats, bool wake);
  /// Applies the event's impulse (or hands it to the zones, or answers the hits of its instant
  /// with it); fills changed_. Returns how many other events it answered.
  long respond(const Scene& scene, const Event& e, State& state, StepContext& ctx);
  /// Applies event e's impulse (closing: its closing rate, assess's).
  void impulse(const Scene& scene, const Event& e, double closing, State& state, StepContext& ctx);
  /// Adds velocity change dv to particle p at step fraction T (state, path, quota, changed_).
  void applyChange(const Scene& scene, int p, const Vec2& dv, double T, State& state, double h);
  /// Event e is a hit (its sleepers woken), and if its instant holds other hits they are answered
  /// together, as one round (simultaneous_hits.cpp). Returns false, having changed nothing but
  /// what assess(wake) changes, when e is to be answered alone; `taken` counts the other events
  /// it answered.
  bool respondTogether(const Scene& scene, const Event& e, State& state, StepContext& ctx, long& taken);
  /// Answers the hits group_ names in tied_ together at step fraction T (simultaneous_hits.cpp);
  /// false, nothing changed, when its exact solve cannot take them.
  bool respondAsOne(const Scene& scene, double T, State& state, StepContext& ctx);
  /// Whether event e, assessed as a, is a hit: an impulse closing harder than resting contact,
  /// which bounces at the scene's COR.
  bool isHit(const Scene& scene, const Event& e, const Assessment& a, double h) const;
  /// The sizes of what this step's forces gave the event's two sides along its normal, summed
  /// (m/s; sleepers.h's kicks; an obstacle's is 0, an edge's is its contact point's).
  void logReferencePolynomials(const Scene& scene, const State& start, const State& state, StepContext& ctx);
  /// An error naming the first fixed particle that starts the step moving, if any (the default
  /// mode keeps pairs apart against fixed particles at rest; the reference moves one at its
  /// initial velocity, and --compat does).
  Status fixedAtRest(const Scene& scene, const State& start) const;

  double cor_;  ///< coefficient of restitution (the scene's COR: 1 elastic .. 0 inelastic)
  /// A particle's quota of impulse events per step before the failsafe (0: every contact goes to the zones).
  int eventsPerParticle_;
  bool allPairs_;              ///< every pair is a candidate (HandlerOptions::allPairs)
  int threads_;                ///< threads for the detection's rows, the broad phase and the per-particle passes (>= 1)
  StepMotion motion_;          ///< every particle's straight pieces over the step, bent by the responses
  PairCandidates candidates_;  ///< the broad phase over motion_'s from -> end, refreshed as paths bend
  ContactZones zones_;         ///< the failsafe's impact zones of this step
  Sleepers sleepers_;          ///< the particles at rest: obstacles until woken
  ContinuousDetector logger_{math::DetectionRules{}};  ///< builds the trajectory log's polynomials
  std::vector<Event> heap_;  ///< the events still to handle: a min-heap by time, then pair (Later)
  /// One per row range of detectAll: its events, scratch and counts. A cache line of its own:
  /// each thread writes its worker's vectors and counts all the time.
  struct alignas(64) Worker {
    std::vector<Event> events;
    std::vector<uint64_t> keys;  ///< its rows' candidate keys (all of them when they make the kept lists: keepAll)
    std::vector<int> row;
    StepStats stats;
    Status status = Status::ok();  ///< its range's first failure (ok when none)
  };
  std::vector<Worker> workers_;    ///< one per row range of the last detectAll (grown, never shrunk)
  std::vector<int> pendingZones_;  ///< zones contacts joined at the current instant, not solved yet
  std::vector<Event> found_;      ///< scratch: detectChanged's events before they join the heap
  std::vector<Event> tied_;       ///< scratch: respondTogether's events of one instant (a hit's, then the rest)
  std::vector<int> group_;        ///< scratch: respondTogether's hits (indices into tied_), by group
  std::vector<int> bodies_;       ///< scratch: respondTogether's particles, in the order of its solve's bodies
  std::vector<int> events_;       ///< N: each particle's impulse events in this step that count toward its quota
  /// A particle's impulse events at the instant of its last one (kEventsPerInstant).
  struct InstantEvents {
    double t = -1.0;  ///< the time of its last impulse event in this step (-1: none yet)
    int count = 0;    ///< impulse events it took at t
  };
  std::vector<InstantEvents> atInstant_;  ///< N
  std::vector<int> changed_;      ///< particles whose path the last response bent
  std::vector<int> wakeFrom_;     ///< scratch: the sleepers or the movers wakeNearMoving searches from
  std::vector<uint64_t> keys_;    ///< scratch: pairs to query
  std::vector<char> inChanged_;   ///< N: whether the particle is in changed_ (detectChanged's scratch, all 0 between)
};

}  // namespace fosssim
