// The step loop's engine: one step = predict (integrator), detect and respond (collision handler),
// verify (finite state, no energy blow-up). Built from a scene's settings through the integrator
// and collision tables.
//
// What a simulator reads from its scene, and when: create() resolves every *setting* once (the
// integrator, dt, the collision type and its parameters: COR, maxiters, failsafe); step() reads
// the scene's *contents* (particles, geometry, forces), which it must not change either. A run
// with other settings takes a new simulator: step() refuses a scene whose settings differ from
// those it was created with, rather than running half on the old ones and half on the new.
// Everything a step needs besides the scene and the state (handler scratch, the forces' pair
// search and storage, the energy watch) belongs to the simulator, so two simulators share
// nothing and may step on different threads.
#pragma once

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/integrator.h"

#include <memory>
#include <string>

namespace fosssim {

struct SimulatorOptions {
  /// The collision handler's options (compat, allPairs, threads, ...); threads and allPairs serve the forces too.
  HandlerOptions handler;
  /// Record every continuous-time query's polynomials (for trajectory files and grading only:
  /// the reference's log holds every pair's polynomials, so every pair is then queried in the
  /// reference's order, without the broad phase; it costs time).
  bool logPolynomials = false;
  /// Stop a run whose mechanical energy grows by orders of magnitude (src/core/energy_watch.h).
  /// On for every run of the program; off only where instability is what is measured (the
  /// study, which has its own blow-up mark and classifies the outcome itself).
  bool watchEnergy = true;
};

class EnergyWatch;

class Simulator {
 public:
  /// Builds the integrator and collision handler that `scene` names. Fails on unknown keywords, on
  /// a scene that does not hold together (checkSceneShape) and on values its scene file could not
  /// hold (checkSceneValues: a mass of -1, a COR of 5), naming the element and value.
  static Status create(const Scene& scene, const SimulatorOptions& options, std::unique_ptr<Simulator>& out);

  /// Advances `state` by one step of `scene` (the scene this simulator was created for; an error
  /// if its settings changed since). On failure (non-finite state, solver failure, energy
  /// blow-up) the message names the step and particle. The scene's shape and values are checked
  /// again at every step, as a scene built in code may have changed since (an edge's index).
  Status step(const Scene& scene, State& state, StepObserver* observer = nullptr);

  /// What the last step's collision handling did.
  const CollisionLog& log() const { return log_; }
  /// The rigid impact zone that moved `particle` in the last step, or -1.
  int zoneOf(int particle) const { return handler_ ? handler_->zoneOf(particle) : -1; }
  /// Pairs of the last step that still collide somewhere along its motion (--verify): `state`
  /// is the state the last step produced. At most `limit` (0 = all). None before the first step.
  std::vector<Violation> unresolved(const Scene& scene, const State& state, size_t limit = 0) const;
  /// The state at the beginning of the last step.
  const State& lastStart() const { return start_; }
  /// What the last step cost and did (timings are measured only when enabled).
  const StepStats& stats() const { return stats_; }
  void setTiming(bool on) { timing_ = on; }
  /// The scene's collision handling, and whether it promises that no pair is left colliding
  /// after a step (what unresolved() checks; see CollisionHandler::keepsPairsApart).
  CollisionType collisionType() const { return collision_->type; }
  bool keepsPairsApart() const { return handler_ && handler_->keepsPairsApart(); }
  /// What this scene's trajectory records contain.
  const RecordLayout& layout() const { return collision_->layout; }
  /// The largest energy growth (in multiples of the scene's energy scale) seen in this run; 0
  /// when the watch is off for this scene (see src/core/energy_watch.h).
  double energyGrowth() const;

  ~Simulator();

 private:
  Simulator();
  const CollisionEntry* collision_ = nullptr;  ///< the collision table's row of the scene's collision type (create)
  std::string integratorKeyword_;  ///< the settings create() read (see the top of this file)
  double dt_ = 0;                  ///< the time step create() read (scene.dt)
  CollisionSettings settings_;     ///< the collision settings create() read (scene.collision): step() refuses others
  /// Built by create() from the integrator table's row of the scene's keyword.
  std::unique_ptr<Integrator> integrator_;
  /// The integrator holds the particles the handler keeps at rest where they are (the implicit
  /// methods: they leave the system); otherwise (the explicit methods, which predict each
  /// particle from its own force alone) their forces may be left incomplete.
  bool holdsResting_ = false;
  std::unique_ptr<CollisionHandler> handler_;  ///< null for "none" and "penalty"
  CollisionLog log_;  ///< what the last step's collision handling did (log()); cleared at each step
  StepStats stats_;  ///< what the last step cost and did (stats())
  bool timing_ = false;  ///< whether step() measures phase timings (setTiming)
  ForceContext forces_;  ///< the forces' pair search (allPairs, threads) and storage
  State start_;  ///< the state at the beginning of the current step (scratch)
  std::unique_ptr<EnergyWatch> energyWatch_;  ///< part of the verify phase
};

/// Checks that every position and velocity is finite; otherwise names the first bad particle.
/// `threads`: ranges of particles checked at once (the same answer for any count).
Status checkFinite(const State& state, int threads = 1);

}  // namespace fosssim
