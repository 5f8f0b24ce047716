// Collision robustness: a small fast disk thrown straight at a thin fixed edge, and what became of
// it. The disk (radius 0.02) and the edge (radius 0.01) overlap only while the disk's centre is
// within 0.03 of the edge's line, so a step that moves it further than 0.06 can skip the contact.
#pragma once

#include "run.h"
#include "scene_builder.h"

namespace fosssim::study {

enum class EdgeOutcome {
  Bounced,    ///< on its own side of the edge at the end, moving away, not overlapping
  Tunnelled,  ///< passed through: on the far side at the end
  Stuck,      ///< overlapping the edge at the end, or stopped on its own side
  Unstable,   ///< the run failed or blew up
};

/// "bounced", "tunnelled", "stuck", "unstable".
const char* edgeOutcomeName(EdgeOutcome outcome);

struct EdgeThrow {
  EdgeOutcome outcome = EdgeOutcome::Unstable;
  RunResult run;
  double startHeight = 0;  ///< the disk's start above the edge's line [m]
};

/// The scene: edge from (-1, 0) to (1, 0) between fixed particles, the disk at (0, h) moving down at
/// `speed`, h = 0.03 + max(0.1, 5.37 speed dt) (an offset that does not land on the edge exactly);
/// the duration lets free flight end as far below the edge as it started above.
SceneBuilder edgeThrowScene(const Method& method, double speed, double dt, double* startHeight = nullptr);

EdgeThrow throwAtEdge(const Method& method, double speed, double dt);

}  // namespace fosssim::study
