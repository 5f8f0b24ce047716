// Internal header: the collision handlers of the collision table.
#pragma once

#include "continuous_detection.h"
#include "impact_zones.h"
#include "impulse_response.h"

#include "fosssim/core/collision_handler.h"

namespace fosssim {

inline math::QuinticForm quinticForm(const HandlerOptions& options) {
  return options.compat ? math::QuinticForm::Reference : math::QuinticForm::Exact;
}

class SimpleHandler final : public CollisionHandler {
 public:
  explicit SimpleHandler(const CollisionSettings& settings) : cor_(settings.cor) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;

 private:
  double cor_;
};

class ContinuousTimeHandler final : public CollisionHandler {
 public:
  ContinuousTimeHandler(const CollisionSettings& settings, const HandlerOptions& options)
      : cor_(settings.cor), detector_(quinticForm(options)) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;

 private:
  double cor_;
  ContinuousDetector detector_;
};

class HybridHandler final : public CollisionHandler {
 public:
  HybridHandler(const CollisionSettings& settings, const HandlerOptions& options)
      : cor_(settings.cor), maxIterations_(settings.maxIterations), detector_(quinticForm(options)) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;
  int zoneOf(int particle) const override { return zones_.zoneOf(particle); }

 private:
  /// Iterative impulses; true when a detection pass found nothing.
  bool impulsePasses(const Scene& scene, const State& start, State& state, StepContext& ctx);
  /// Rigid impact zones, grown until no new collision joins them.
  void failsafe(const Scene& scene, const State& start, State& state, StepContext& ctx);

  double cor_;
  int maxIterations_;
  ContinuousDetector detector_;
  std::vector<Collision> collisions_;
  std::vector<VelocityChange> changes_;
  ImpactZones zones_;
  VecX predicted_;  ///< 2N: the end positions before the failsafe moves zones rigidly
};

}  // namespace fosssim
