// Internal header: the collision handlers of the collision table.
#pragma once

#include "fosssim/core/collision_handler.h"

namespace fosssim {

class SimpleHandler final : public CollisionHandler {
 public:
  explicit SimpleHandler(const CollisionSettings& settings) : settings_(settings) {}
  Status handle(const Scene& scene, const State& start, State& state, StepContext& ctx) override;

 private:
  CollisionSettings settings_;
};

}  // namespace fosssim
