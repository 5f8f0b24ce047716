// Internal header: the tuning of the default mode's failsafe (contact_zones.h) and of the
// resting-contact rule that impulses and zones share: how often a zone may be met again before it
// jams, the solves' budgets and tolerances, when particles count as held, touching or resting.
// Each constant says what it was measured against (docs/performance-history.md has the runs).
#pragma once

namespace fosssim {

/// Times a zone's contacts may come back in one step after it was solved for them (or its solve
/// ran out of budget) before the last resort: a zone whose own contacts keep approaching is a jam
/// (a wedge, a column being crushed). Against an obstacle the contact that comes back again welds
/// its own particles and locks them against its obstacles, or stops them (zone_stops.cpp); a zone
/// touching nothing moves rigidly for the rest of the step.
constexpr int kMaxZoneProjections = 8;

/// Times a zone's contacts may come back in one step after a solve that bounced them (its
/// restitution kept, so no energy gained) without counting toward kMaxZoneProjections: a ball
/// bouncing between two walls at the apex of a narrow wedge is not a jam, and comes back once
/// for each bounce. A particle alone against obstacles that bounces more often than that in a
/// step (a ball rattling between two walls a hair wider than it, faster than the step can follow)
/// jams, and keeps its bounce's speed for the next step (ContactZones::giveBackRattles).
constexpr int kMaxZoneBounces = 64;

/// Of those, the bounces a zone may take at the instant of its bounce before (whatever its
/// bounceLimit): a rattle moves on in time, and one that does not is a jam. A capsule pinned
/// between fixed disks bounced from one to the other at the step's first instant until a small
/// zone's kMaxZoneBouncesCap: 600 solves a step for 14 particles (a fuzzer's scene, 219 s under
/// the sanitizers).
constexpr int kMaxStalledBounces = kMaxZoneBounces;
/// A zone whose movable members' masses differ needs more: a light disk driven into a wall by a
/// heavy one (mass ratio M / m) bounces about pi sqrt(M / m) times before the heavy one turns
/// (Galperin's count of elastic collisions, exact in one dimension), each a comeback after a
/// solve that bounced. So a zone may take this many times pi sqrt(M / m) bounces when that is
/// more than kMaxZoneBounces (from a mass ratio of 26 on), up to kMaxZoneBouncesCap. Random fast
/// boxes at COR 1 with disks some 380 times lighter than a neighbour jammed at 64 and lost up to
/// 82% of their energy. Piles of alike masses keep 64.
constexpr double kBouncesPerGalperinCount = 4.0;
constexpr int kMaxZoneBouncesCap = 4096;
/// A zone of 2 to this many members (those whose cluster math::ContactProjector solves exactly,
/// kClusterBodies) may take kMaxZoneBouncesCap bounces whatever its masses. A disk rattling at
/// COR 1 between a wall and a disk the walls hold bounced every 0.0027 to 0.00023 of a step, up to
/// some 1,500 times, and at 64 bounces the jam took 37-72% of a fast box's energy (3 of 3,000
/// random boxes of 2-4 disks; in boxes of 5-8 disks most of the jams left once their clusters
/// were solved exactly). A zone of one particle keeps its limit: its rattle's outcome is given
/// back whole at the jam (rattlerOf). A bounce of a small zone costs an event and a small solve,
/// so the cap bounds such a zone's cost in a step; piles' zones are far larger. A rattle faster
/// still (every 2.5e-5 of a step: 40,000 bounces) passes the cap and jams.
constexpr int kSmallZoneMembers = 8;

/// A jammed contact's particles stop at rest, as obstacles, instead of being welded, when their
/// common velocity moves across their kick (the velocity change this step's forces gave them) by
/// at most this many kicks (ContactZones::stopsAtRest): the speed a jam takes from motion across
/// the forces is then at most a kick's, as a held particle's. What welding costs, against the
/// commit where every jam stopped (least user time of interleaved FOSSSim -d 0 runs): rain 1,000
/// 1.28-1.33 times, 2,500 1.35-1.38, 10^4 1.87; with the rule on the weld's speed instead of its
/// motion across the kick, 1.56 and 1.93 at 1,000 and 2,500; with 4 kicks, 1.23, 1.10 and 1.57.
constexpr double kJamRestKicks = 1.0;

/// The projection's tolerance, relative to the zone's largest speed (the solver's default): what
/// it leaves closing deepens the zone's slowest contacts over the rest of the step by about this
/// fraction of a step's motion, below the deepening --verify counts (kDepthTolerance, 1e-10 of
/// the lengths) for any motion per step up to the scene's size.
constexpr double kZoneProjectionTolerance = 1e-10;

/// Closing speeds inside one zone up to this fraction of the zone's largest rate are left over
/// by its projection (kZoneProjectionTolerance times a row norm of at most sqrt(3)), so that a
/// solved zone is not solved again for them.
constexpr double kZoneClosingFraction = 2e-10;

/// Gauss-Seidel updates one solve may spend per row it adds to the system (a zone's first solve
/// adds all its rows; a disk landing on a pile, a few). A resting pile jammed into a V (whose
/// answer is v = 0) contracts slowly under Gauss-Seidel; a solve that stops early keeps what it
/// reached (safe: no energy gained) and the contacts still closing come back as events, which
/// continue it from there: the cost follows what joins, not the size of the pile. Chosen on the
/// benchmark's piles and the flow tests, since contacts of one instant are solved together
/// (fosssim-bench --scenes pile-low-cor0.5 --sizes 2500 --steps 500; ms/step, steps with a rigid
/// zone; the V-pile test's least share of landed disks moving): 300: 33.4 ms, 0.0 %, 0.32;
/// 100: 14.6 ms, 0.4 %, 0.31; 60: 8.5 ms, 8.2 %, 0.05; 30: 6.2 ms, 19.6 %. Below 100 jammed zones
/// fall back to rigid motion in many steps and the flow suffers; above it the cost grows with
/// the budget for the same flow.
constexpr long kZoneUpdatesPerRow = 100;

/// A zone past the jam limit (kMaxZoneProjections) solves with this fraction of the budget per
/// row. Its contacts that still close then jam (welded, locked or stopped: zone_stops.cpp), so a
/// long solve buys little there: on the jammed piles measured (zones of 1,200-1,400 disks and
/// 3,300-3,700 rows, over-constrained), solves that end on their budget do 98% of the failsafe's
/// Gauss-Seidel updates, and those of zones past the limit 68%. Measured with the contacts a
/// budget-ended solve leaves not counted as jams (see ContactZones::requeried_), 1/10 against the
/// full budget: pile-rest 2,500 (200 steps) 6.8 -> 3.5 s, pile-low-cor0.5 2,500 (600 steps)
/// 23 -> 11 ms/step, rain 800-3,000 (400 steps) 2.8-5.3 -> 1.9-4.0 ms/step; the price: those
/// piles end 1-4% higher in energy (less settled within the step's budget). 1/100 gained little
/// more (3.1 s). (Figures of the session's changes together, what they cost included:
/// docs/performance-history.md.)
constexpr long kJammedBudgetDivisor = 10;

/// With holding on, a zone's first solve in a step solves with this fraction of the budget per
/// row. On a resting pile that solve rarely converges whatever its budget (its contacts change a
/// little every step); what a short one leaves is settled by holding the particles it has brought
/// to rest and by the solves of the contacts that come back. With 1/10, random zones gained
/// kinetic energy (ContactPhysicsRandom.KineticEnergyNeverGrows: a warm start the shorter solve
/// had not taken back); 1/5 keeps every test. Measured with the hold: docs/performance-history.md.
constexpr long kFirstSolveBudgetDivisor = 5;

/// With holding on, a zone against an obstacle halves its budget per row at each of its first
/// this many counts toward the jam limit in the step (a failed solve, a contact back after its
/// solve): a quarter of it from the second on, until the jammed budget (kJammedBudgetDivisor).
/// A zone whose solves keep failing is heading for a jam, and what a short solve leaves is
/// settled, as after the first solve, by the particles it holds and the contacts that come back.
/// On `chains` 1,000, 91% of the later solves of such zones ended on budgets of some 7,200
/// updates each. Measured (fosssim-bench --steps 400, one run each; ms/step with 0, 2 and 3
/// halvings): chains 1,000 4.25, 2.89, 2.84; chains 10^4 35.8, 26.6, 24.6; pile-low-cor0.5
/// 2,500 3.24, 2.51, 2.44; pile-rest 2,500 3.41, 3.10, 3.08; rain 10^4 8.38, 7.75, 7.59. The
/// price: chains 1,000 holds 38% of its particle-steps instead of 27% and jams 2.4% instead of
/// 1.0%; rain 10^4 has a rigid zone in 20% of its steps instead of 19% (22% with 3 halvings).
constexpr int kRepeatBudgetHalvings = 2;

/// A held particle (see the top of this file) has a speed of at most this fraction of its kick
/// after the budget-ended solve (below 1: its contacts took back part of the kick, so a particle
/// falling freely, whose solve left it its whole kick, is never held; 0.9 costs no more than 1,
/// pile-rest 2,500 2.9 against 3.3 ms/step) ...
constexpr double kHeldKickFraction = 0.9;

/// ... and had at most this fraction of its kick at the start of the step: a disk sliding on the
/// floor faster than that keeps its speed (in the oracle's v_pile a ball slides at a third of a
/// kick: without this bound the hold stopped it).
constexpr double kHeldStartFraction = 0.25;

/// A solve looks for new neighbours only around particles whose rate it changed by more than
/// this fraction of the zone's largest rate. Finding neighbours early only saves later events:
/// a pair missed here is still detected, as an event, if it comes into contact.
constexpr double kRegrowFraction = 1e-3;

/// Extra reach, as a fraction of a pair's radius sum, within which two zone neighbours count as
/// touching on top of the distance they could close in the rest of the step (absorbs rounding of
/// resting contacts, whose gaps are a few ulps of the radii).
constexpr double kTouchingSlack = 1e-6;

/// How far apart, as a fraction of their radius sum, two particles (or a particle and an edge or
/// a half-plane) may be at a solve's instant and still join its zone, however much they could
/// close in the rest of the step. A zone's rows forbid any approach, so a row for a wall a disk
/// is far from stops it there: two fast disks in a small box (five crossings a step) had rows to
/// all four walls and stopped dead. In a pile what a pair closes in a step is far below this,
/// and the zones are as they were.
constexpr double kZoneReach = 0.5;

/// A cluster that a zone's solve is about to leave unsettled on its budget is projected exactly
/// (ContactProjector::solveCluster's rescue) only if one of its bodies moves faster than this
/// many times the largest of their kicks this step (the velocity the step's forces gave them).
/// Without it, the small clusters of settling piles were solved exactly too, and not held where
/// a budget-ended solve had brought them to rest: pile-rest 1,000 made 18% more Gauss-Seidel
/// updates a step (5,812 against 4,941). At 8 kicks pile-low-cor0.5 1,000 still made 11% more
/// (9,369 against 8,416); at 32, 7,959, and pile-rest the same 4,941 as without the rescue. A
/// cluster wedged at 100 m/s, or any in a scene without forces, is far above it.
constexpr double kRescueKicks = 32.0;

/// Resting contact does not bounce: an impulse takes COR 0 (for a scene COR below 1) when its
/// contact closes no faster than this many times the step's kicks along its normal
/// (ContactZones::kicksAlong) and gained at least kRestingGainedShare of that closing in this
/// step (ContactZones::resting); so does a zone's row (its restitution target). Resting contact
/// closes at about one kick: a disk on the floor, or on a disk of a pile, in every step.
constexpr double kRestingBounceKicks = 2.0;
/// The share of a resting contact's closing speed that this step gave it (its kicks, and the
/// impulses before it that stopped what it rests on). Two disks in free fall close at the speed
/// they had before the step, whatever their kicks (which are equal): that is a hit, not a rest.
/// A disk on another in a pile, the lower stopped by its support in the step, gains one kick g h
/// and may keep up to three from an unfinished solve (closing at most 4 g h, kRestingBounceKicks
/// times its two sides' kicks) and still rest: g h >= share * 4 g h. A half, first tried, made a
/// settling pile's contacts with two kicks left over bounce (pile-low-cor0.5 2,500: 10% more
/// Gauss-Seidel updates).
constexpr double kRestingGainedShare = 0.25;
/// A contact that closed at the step's start no faster than this many of its kicks along the
/// normal rests whatever it gained: what a resolved contact keeps of an approach (rounding, a
/// plank's rotation turning its normal under a ball at rest on it) is not a hit.
constexpr double kRestingStartKicks = 0.01;

}  // namespace fosssim
