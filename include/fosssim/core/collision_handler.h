// Collision handlers: after the integrator's prediction, detect and respond to collisions.
#pragma once

#include "fosssim/core/collision_log.h"
#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"
#include "fosssim/core/step_stats.h"
#include "fosssim/core/status.h"
#include "fosssim/core/verify.h"

#include <memory>
#include <string>
#include <vector>

namespace fosssim {

/// Sees the state in the middle of collision handling (handlers whose layout has midStep): a
/// trajectory writer records it, the grader compares it with the reference's record.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// Returns a state whose positions and velocities the step is to go on from instead of
  /// `state`'s, or nullptr to go on from `state`. Only grading replaces it: the course's grader
  /// continues every step from the reference's mid-step record, so that one early difference
  /// is not reported at every later record. The handler copies the replacement before it goes on.
  virtual const State* midStep(const CollisionLog& log, const State& state) = 0;
};

/// Choices that do not belong to the scene file.
struct HandlerOptions {
  /// Reproduce the reference simulator's own formulas where they differ from exact mathematics
  /// (the particle-edge approach quintic, and how roots at the end of a step count: see README
  /// "Course compatibility").
  bool compat = false;
  /// Check every pair in the reference's order, without the broad phase (the results are the
  /// same; this exists so that tests and measurements can show it).
  bool allPairs = false;
  /// Threads for the broad and narrow phase (1: none besides the caller's). The results are the
  /// same for every count: work is split into ranges whose results are joined in pair order.
  int threads = 1;
  /// Default mode: particles that stay still for a while sleep (are not moved or searched) until
  /// a contact or a moving neighbour wakes them (src/core/collision/sleepers.h). A run in which
  /// no particle sleeps is identical with it on or off. --compat never sleeps.
  bool sleep = true;
  /// Default mode: Gauss-Seidel updates a failsafe solve may spend per row it adds (0: the
  /// tuned kZoneUpdatesPerRow of src/core/collision/zone_tuning.h). For tests and measurements:
  /// a starved failsafe must still leave no contact closing unseen, only cost more events.
  long zoneUpdatesPerRow = 0;
  /// Default mode: a failsafe solve that ends on its budget holds the particles it has brought
  /// to rest (stops them for the rest of the step; src/core/collision/contact_zones.h). Off (for
  /// tests and measurements), such a solve's contacts only come back as events.
  bool hold = true;
};

/// Everything a handler may use during one step besides the scene and the two states.
struct StepContext {
  double dt = 0;
  CollisionLog* log = nullptr;          ///< never null; polynomials only if log->polynomials.enabled()
  StepObserver* observer = nullptr;     ///< may be null
  StepStats* stats = nullptr;           ///< never null; handlers add their timings and counts
  bool timing = false;                  ///< measure phase times into *stats
};

/// The mid-step seam for handlers: shows `state` to the observer (if any) and takes the
/// replacement it returns. True when the positions were replaced by different ones.
bool showMidStep(StepContext& ctx, State& state);

class CollisionHandler {
 public:
  virtual ~CollisionHandler() = default;
  /// start: the state at the beginning of the step; state: the integrator's prediction, changed
  /// in place into the collision-free end of the step.
  virtual Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) = 0;
  /// Diagnostics: the rigid impact zone that moved `particle` in the last step, or -1 (only
  /// the hybrid handler has zones).
  virtual int zoneOf(int /*particle*/) const { return -1; }
  /// Whether the handler promises what unresolved() checks: no pair left colliding after a
  /// step (the default mode's time-ordered handling). The course's methods do not.
  virtual bool keepsPairsApart() const { return false; }
  /// Called before the integrator's prediction, with the step's start: the particles (size N,
  /// 1 each) this step will keep where they rest whatever is predicted for them (the default
  /// mode's sleepers, and the fixed particles with them), or null when none sleeps. Their
  /// predicted forces may be incomplete (ForceContext::resting); the handler must then read
  /// nothing of their prediction. Valid until the step's handle() returns.
  virtual const std::vector<char>* restingAtStart(const Scene& /*scene*/, const State& /*start*/) {
    return nullptr;
  }
  /// The verification seam: pairs that still collide somewhere along the last step's motion
  /// from start to end (at most `limit`, 0 = all), what --verify reports. By default the motion
  /// is the straight line from start to end and every pair counts; handlers whose particles
  /// bend within a step check their own paths, and handlers that move zones rigidly exempt the
  /// pairs inside one zone.
  virtual std::vector<Violation> unresolved(const Scene& scene, const VecX& start, const VecX& end,
                                            size_t limit) const;
};

/// One row of the collision table: the keyword of <collision type="..."> and what it builds.
struct CollisionEntry {
  CollisionType type;      ///< the row's method; collisionTable()[int(type)] is this row
  const char* keyword;
  /// Builds the handler; nullptr for types without one ("none", "penalty").
  std::unique_ptr<CollisionHandler> (*make)(const CollisionSettings&, const HandlerOptions&);
  bool addsPenaltyForce;   ///< the loader adds a PenaltyForce with the defaults below
  double defaultK;         ///< penalty stiffness when the scene gives none
  double defaultThickness; ///< penalty thickness when the scene gives none
  RecordLayout layout;     ///< what this type writes into trajectory records
  const char* summary;
};

const std::vector<CollisionEntry>& collisionTable();
/// The row of `keyword`, or nullptr when no row has it: what readers of keywords call, once.
const CollisionEntry* findCollisionType(const std::string& keyword);
/// The row of a method (an index, no search).
const CollisionEntry& collisionEntry(CollisionType type);
/// The keyword of <collision type="..."> that selects `type`.
inline const char* collisionKeyword(CollisionType type) { return collisionEntry(type).keyword; }

}  // namespace fosssim
