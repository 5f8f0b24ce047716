// The failsafe's zones for one step, set up as the event loop sets them up, for tests that drive
// ContactZones directly (failsafe_budget_test.cpp, contact_zones_test.cpp).
#pragma once

#include "../../src/core/collision/contact_zones.h"
#include "test_scenes.h"

namespace fosssim::testing {

/// Paths, broad phase and zones for one step of `s` in which every particle moves with its
/// velocity (no sleepers). With `start` (the state before the step's forces), the zones also see
/// the step's kicks, s's velocities less start's, as in a real step: they decide which particles
/// may be held and whether a budget-ended solve may be rescued exactly (ContactZones::RowsAt::
/// mayRescue); without, the zones know no kicks: any cluster may be rescued.
struct StepZones {
  StepMotion motion;
  PairCandidates candidates;  // reads motion's vectors: a StepZones stays where it was made
  ContactZones zones;
  Sleepers kicks;  // sleeping off: the step's kicks only
  StepZones(const TestScene& s, long updatesPerRow, bool hold, const State* start = nullptr) {
    motion.begin(s.state.x, s.state.x + s.scene.dt * s.state.v);
    candidates.build(s.scene, motion.from(), motion.end(), 0.0, /*updates=*/true);
    zones.reset(s.scene.numParticles());
    zones.setUpdatesPerRow(updatesPerRow);
    zones.setHold(hold);
    if (start != nullptr) {
      kicks.setEnabled(false);
      State predicted = s.state;
      kicks.begin(s.scene, *start, predicted, s.scene.dt);
      zones.setSleepers(&kicks);
    }
  }
  StepZones(const StepZones&) = delete;
  StepZones& operator=(const StepZones&) = delete;
};

}  // namespace fosssim::testing
