#pragma once
// The limits of ContactProjector's exact solves (solveAlone: one body against obstacles;
// solveCluster: a few bodies of very different masses), where Gauss-Seidel would stall: which
// rows qualify, when they are tried, and the slack their answers are checked with. A base of
// ContactProjector, so that they read as ContactProjector::kAloneRows and so on.

namespace fosssim::math {

struct ExactSolveLimits {
  /// A body whose rows move no other body (a disk against walls, fixed particles or sleepers)
  /// has them solved at once, exactly, when it has at most this many: its velocity projected
  /// onto the polygon they allow (solveAlone, in the .cpp). More rows: Gauss-Seidel, as any.
  static constexpr int kAloneRows = 8;
  /// That projection's feasibility slack: a row counts as satisfied at G_k v >= -this |G_k| V, V
  /// the largest speed among the body's unconstrained velocity and its obstacles' (rounding of
  /// the projection's own products is ~1e-16 relative).
  static constexpr double kAloneSlack = 1e-12;
  /// Two rows whose normals are closer to parallel than this (|sin| of their angle) make no
  /// corner for solveAlone: where their lines meet is lost to rounding.
  static constexpr double kAloneParallel = 1e-9;
  /// solveAlone is tried for a row at this many Gauss-Seidel updates since the last takeChanged
  /// (and at twice, four times... as many): rows that Gauss-Seidel settles leave it alone, those
  /// it keeps coming back to (a disk in a narrow wedge: hundreds) meet it soon. Looking at a
  /// body's rows at every update cost rain 1,000 a sixth more instructions (cachegrind); from the
  /// 4th update, the exact solves changed how piles settle (pile-rest 1,000 +9% instructions);
  /// from the 32nd, rain, chains, pile-rest and pile-high-cor0.5 at 1,000 changed by -1.5% to
  /// +4.3%, as any change of their trajectories does.
  static constexpr int kAloneAfterUpdates = 32;
  /// Up to this many movable bodies (none locked to an axis) whose rows, at most kClusterRows,
  /// move no other body are projected exactly together, as solveAlone does for one
  /// (solveCluster, contact_projector_cluster.cpp): bodies of very different masses squeezed
  /// together stall Gauss-Seidel. Tried as rarely, and once when a solve is about to end on its
  /// budget (its rescue). Four bodies: two light disks wedged in a corner by two heavy ones.
  /// Sixteen rows: four disks in a box have up to six pairs and two walls each; a 13-row cluster
  /// of four disks outgrew the enumeration's 12 (2^12 systems, which that solver could afford)
  /// and jammed. With the active-set solve, 16 rows, and up to 8 bodies and 24 rows alike, left
  /// rain, chains and the piles at 1,000 and 2,500 within 1% of their Gauss-Seidel updates.
  static constexpr int kClusterBodies = 4;
  static constexpr int kClusterRows = 16;
  /// The exact solve's feasibility slack there, relative as kAloneSlack is: set for the
  /// enumeration it replaced, where nearly parallel rows of several bodies left no active set
  /// feasible to 1e-12 after their systems' rounding (one random cluster in eight). The active
  /// set's own rows end tight to rounding (it refines them); the slack decides which others it
  /// takes as satisfied, and Gauss-Seidel settles those to the solve's tolerance.
  static constexpr double kClusterSlack = 1e-9;
  /// Only clusters whose heaviest body is at least this many times its lightest, except in the
  /// rescue: where masses are alike, Gauss-Seidel stalls only in tight geometry; solved exactly
  /// at every try, a settling pile's small clusters took another 20% of Gauss-Seidel updates to
  /// come to rest (pile-rest 2,500: 11,595 -> 13,863 a step). The rescue, at a budget's end,
  /// takes any masses, if the caller's RowSource allows it (the zones: fast clusters only).
  static constexpr double kClusterMassRatio = 10.0;
};

}  // namespace fosssim::math
