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
  /// budget (its rescue). Measured on random fast boxes at COR 1 (2 m, dt 0.03, disks at up to
  /// 100 m/s, tests/core/fast_box_test.cpp): with 4 bodies and 12 rows (all that the
  /// enumeration of 2^rows active sets, which the active-set solve replaced, could afford), 6 of
  /// 3,000 boxes of 2-4 disks lost energy, one in a cluster of 13 rows; of 600 boxes of 5-8
  /// disks, with 4 bodies and 16 rows, 125 did, most in zones of 5-8 disks whose solves ended on
  /// their budgets and then shortened their bounces. With 8 bodies and 24 rows, 18 of the 600;
  /// with 32 rows (8 disks in a box have up to 28 pairs and some walls) and small zones' bounces
  /// (kSmallZoneMembers), 4, all in jams of rattles. Piles' clusters are larger and their
  /// gathering stops at the limit: rain, chains and the piles at 1,000 and 2,500 made
  /// Gauss-Seidel updates within 7% of 4 bodies' (rain 1,000 7% fewer, pile-high-cor0 1,000 7%
  /// more), in times within this machine's noise.
  static constexpr int kClusterBodies = 8;
  static constexpr int kClusterRows = 32;
  /// The exact solve's feasibility slack there, relative as kAloneSlack is: what it accepts, not
  /// what it aims at (every row closing by more than math::kActiveSetJoin joins its active set).
  /// At 1e-12, random clusters of 8 bodies, 32 rows and masses 10^4 apart left rows violated by
  /// rounding beyond it, and their solves fell back on Gauss-Seidel, which ran out of budget.
  static constexpr double kClusterSlack = 1e-9;
  /// Only clusters whose heaviest body is at least this many times its lightest, except in the
  /// rescue: where masses are alike, Gauss-Seidel stalls only in tight geometry; solved exactly
  /// at every try, a settling pile's small clusters took another 20% of Gauss-Seidel updates to
  /// come to rest (pile-rest 2,500: 11,595 -> 13,863 a step). The rescue, at a budget's end,
  /// takes any masses, if the caller's RowSource allows it (the zones: fast clusters only).
  static constexpr double kClusterMassRatio = 10.0;
};

}  // namespace fosssim::math
