// Robustness by energy: many random shots of a small disk (radius 0.02, unit mass) at thin fixed
// edges (radius 0.01), each judged by where the disk ends and what became of its energy. The
// targets are the places contact handling gets wrong: an edge's face, an edge's end cap, the
// joint of two edges at an angle, and a narrow slot between two parallel edges (many bounces).
// Speeds, time steps, angles, offsets and COR are drawn from a fixed seed, so every method meets
// the same shots, in the default mode and with --compat.
#pragma once

#include "run.h"
#include "scene_builder.h"

#include "fosssim/core/status.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fosssim::study {

enum class ShotTarget { EdgeFace, EdgeEnd, Joint, Slot };
/// "edge face", "edge end", "joint", "slot".
const char* shotTargetName(ShotTarget target);

struct Shot {
  ShotTarget target = ShotTarget::EdgeFace;
  double speed = 1;   ///< [m/s]
  double dt = 0.01;   ///< [s]
  double angle = 0;   ///< direction of motion [rad] (slot: from the slot's axis)
  double offset = 0;  ///< aim: along the face, beside the end cap or the joint [m]; slot: free half-width
  double jointAngle = 0;  ///< joint: the second edge's rise [rad]
  double cor = 1;
};

/// The i-th shot at `target` (the same for every method and mode).
Shot randomShot(ShotTarget target, int i);

/// Shortest distance from the disk's centre to any edge's segment, less the disk and edge radii:
/// negative when they overlap.
double shotClearance(const Shot& shot, const Vec2& centre);

/// The scene: the fixed edges, the disk starting 0.3 m plus three steps of flight before its aim
/// point, for long enough to leave as far after a bounce (slot: six crossings of the slot).
SceneBuilder shotScene(const Shot& shot, const Method& method);

enum class ShotOutcome {
  Bounced,     ///< on its own side, clear of the edges, energy within COR's bounds (0.1 % leeway)
  Gained,      ///< mechanical energy above its start by more than 0.1 %
  Lost,        ///< below COR's lower bound (e^2 per contact; slot: the kinetic energy along it) by 0.1 %
  Tunnelled,   ///< its centre crossed an edge, or it flew on as if no edge were there
  Overlapped,  ///< ends overlapping an edge
  Froze,       ///< ends at rest (kinetic energy below 1e-6 of its start)
  Unstable,    ///< the run failed or blew up
};
/// "bounced", "gained energy", "lost energy", "tunnelled", "overlapped", "froze", "unstable".
const char* shotOutcomeName(ShotOutcome outcome);

struct ShotResult {
  ShotOutcome outcome = ShotOutcome::Unstable;
  double energyRatio = 0;           ///< E_end / E_0 (kinetic + the forces' potential)
  double lowBound = 0, highBound = 1;  ///< COR's bounds on that ratio
  double clearance = 0;             ///< shotClearance at the end
  RunResult run;
};

ShotResult fireShot(const Shot& shot, const Method& method, bool compat);

/// The methods the shots compare: simple, continuous-time, hybrid (defaults), hybrid k = 0,
/// penalty k = 1e4.
std::vector<Method> shotMethods();

}  // namespace fosssim::study
