// The failsafe's zones for one step, set up as the event loop sets them up, for tests that drive
// ContactZones directly (failsafe_budget_test.cpp, contact_zones_test.cpp).
#pragma once

#include "../../src/core/collision/contact_zones.h"
#include "test_scenes.h"

namespace fosssim::testing {

/// Paths, broad phase and zones for one step of `s` in which every particle moves with its
/// velocity (no sleepers).
struct StepZones {
  StepMotion motion;
  PairCandidates candidates;  // reads motion's vectors: a StepZones stays where it was made
  ContactZones zones;
  StepZones(const TestScene& s, long updatesPerRow, bool hold) {
    motion.begin(s.state.x, s.state.x + s.scene.dt * s.state.v);
    candidates.build(s.scene, motion.from(), motion.end(), 0.0, /*updates=*/true);
    zones.reset(s.scene.numParticles());
    zones.setUpdatesPerRow(updatesPerRow);
    zones.setHold(hold);
  }
  StepZones(const StepZones&) = delete;
  StepZones& operator=(const StepZones&) = delete;
};

}  // namespace fosssim::testing
