// Internal header: the collision handlers of the collision table.
#pragma once

#include "collision_search.h"
#include "continuous_detection.h"
#include "impact_zones.h"
#include "impulse_response.h"

#include "fosssim/core/collision_handler.h"

namespace fosssim {

inline math::DetectionRules detectionRules(const HandlerOptions& options) {
  return options.compat ? math::DetectionRules::reference() : math::DetectionRules{};
}

class SimpleHandler final : public CollisionHandler {
 public:
  SimpleHandler(const CollisionSettings& settings, const HandlerOptions& options)
      : cor_(settings.cor), allPairs_(options.allPairs) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;

 private:
  double cor_;                 ///< coefficient of restitution (the scene's COR: 1 elastic .. 0 inelastic)
  bool allPairs_;              ///< every pair is a candidate (HandlerOptions::allPairs)
  PairCandidates candidates_;  ///< pairs overlapping at the end of the step
  std::vector<int> row_;       ///< scratch for forEachInRow (one row's candidates)
  std::vector<uint64_t> keys_;  ///< the step's candidate pair keys, in the reference's order
};

class ContinuousTimeHandler final : public CollisionHandler {
 public:
  ContinuousTimeHandler(const CollisionSettings& settings, const HandlerOptions& options)
      : cor_(settings.cor), search_(detectionRules(options), options.allPairs, options.threads) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;

 private:
  double cor_;              ///< coefficient of restitution (the scene's COR: 1 elastic .. 0 inelastic)
  CollisionSearch search_;  ///< continuous-time detection with the broad phase
};

class HybridHandler final : public CollisionHandler {
 public:
  HybridHandler(const CollisionSettings& settings, const HandlerOptions& options)
      : cor_(settings.cor),
        maxIterations_(settings.maxIterations),
        search_(detectionRules(options), options.allPairs, options.threads) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;
  int zoneOf(int particle) const override { return zones_.zoneOf(particle); }
  /// Pairs inside one rigid zone are exempt: the zone moved them together, as the method means.
  std::vector<Violation> unresolved(const Scene& scene, const VecX& start, const VecX& end,
                                    size_t limit) const override {
    return unresolvedCollisions(scene, start, end, [this](int p) { return zones_.zoneOf(p); }, limit);
  }

 private:
  /// Iterative impulses; true when a detection pass found nothing.
  bool impulsePasses(const Scene& scene, const State& start, State& state, StepContext& ctx);
  /// Rigid impact zones, grown until no new collision joins them. `replaced`: the observer
  /// replaced the state after the impulse passes.
  void failsafe(const Scene& scene, const State& start, State& state, StepContext& ctx, bool replaced);

  /// Applies the pass's impulses (all computed from the same end positions) and lists the
  /// particles they moved in touched_.
  void respond(const Scene& scene, const State& start, State& state, StepContext& ctx);

  double cor_;                 ///< coefficient of restitution (the scene's COR: 1 elastic .. 0 inelastic)
  int maxIterations_;          ///< impulse passes before the failsafe (the scene's maxiters; <= 0: none)
  CollisionSearch search_;     ///< continuous-time detection with the broad phase
  std::vector<Collision> collisions_, previous_;  ///< this detection's and the last one's
  /// Scratch of respond(): each collision's velocity change, in collisions_'s order.
  std::vector<VelocityChange> changes_;
  std::vector<int> touched_;   ///< particles whose end position the last responses or rigid moves changed
  std::vector<char> marked_;   ///< N: scratch for touched_
  ImpactZones zones_;          ///< the failsafe's rigid impact zones of this step
};

}  // namespace fosssim
