// Continuous collision detection for particle-particle (PP), particle-edge (PE) and
// particle-half-plane (PH) pairs over one step.
//
// Time is normalised to the step: x(t) = x_start + t*D, t in [0, 1], D the whole step's
// displacement (q_end - q_start). A pair collides when the first t >= 0 at which all of its
// polynomials are > 0 is <= 1 (firstPositiveTime in interval_solver.h). The polynomials are
// built in the reference simulator's order and form (spec section 4) because they are
// written into trajectory files and graded coefficient by coefficient.
#pragma once

#include <array>

#include "fosssim/math/geometry.h"
#include "fosssim/math/interval_solver.h"
#include "fosssim/math/polynomial.h"

namespace fosssim::math {

/// Particle 1 (start x1, displacement d1, radius r1) against particle 2.
struct PPInput {
  Vec2 x1, d1;
  double r1 = 0.0;
  Vec2 x2, d2;
  double r2 = 0.0;
};

/// Particle 1 (radius rv) against the edge from particle 2 to particle 3 (edge radius re).
struct PEInput {
  Vec2 x1, d1;
  double rv = 0.0;
  Vec2 x2, d2, x3, d3;
  double re = 0.0;
};

/// Particle 1 (radius r) against the half-plane through p with raw (unnormalised) normal m.
struct PHInput {
  Vec2 x1, d1;
  double r = 0.0;
  Vec2 p, m;
};

/// Which PE approach quintic to build. Exact is V.N expanded correctly; Reference reproduces
/// the reference simulator's coefficients, whose t^3 term uses f*g*q where the expansion has
/// f*h*q (spec section 4). The choice affects detection too, not only the log: to reproduce
/// the reference's collisions, detect with the polynomial it solved.
enum class QuinticForm { Exact, Reference };

/// Everything detection does differently to reproduce the reference simulator (--compat): the
/// PE quintic it builds and the rule by which roots become a collision time (IntervalRule in
/// interval_solver.h). The default is FOSSSim's own; reference() is what --compat selects.
struct DetectionRules {
  QuinticForm quintic = QuinticForm::Exact;
  IntervalRule intervals = IntervalRule::Exact;
  static constexpr DetectionRules reference() { return {QuinticForm::Reference, IntervalRule::Reference}; }
};

/// Leading coefficients smaller than this in magnitude are dropped from every CCD polynomial,
/// for building, solving and logging alike. This is what the reference simulator does, and it
/// is NOT what spec section 4 says ("exact zero leading coefficients are dropped"): among the
/// 3.7 million polynomials logged in the conformance suite's continuous-time and hybrid
/// references, the smallest leading coefficient is 1.000005e-12, in a dense distribution
/// that stops there; and the PE quintics whose expected leading terms lie below 1e-12 are
/// logged shorter. An absolute cutoff (it depends on the scene's units); whether exactly
/// 1e-12 itself is kept cannot be told from the data (taken: |c| < 1e-12 is dropped).
constexpr double kNegligibleLeadingCoefficient = 1e-12;

// ---- Polynomial builders, one per polynomial, highest power first, leading coefficients
// below kNegligibleLeadingCoefficient (and exact zeros) dropped. A pair's list is, in order:
//   PP: ppPosition, ppApproach
//   PE: peDistance, peAlphaAboveZero, peAlphaBelowOne, peApproach
//   PH: phDistance, phApproach
Polynomial ppPosition(const PPInput& in);   // (r1+r2)^2 - |x2(t) - x1(t)|^2
Polynomial ppApproach(const PPInput& in);   // -(d/dt |x21|^2)/2 = -|D21|^2 t + D12.x21
Polynomial peDistance(const PEInput& in);   // |e|^2 (rv+re)^2 - |e|^2 |w|^2 + (w.e)^2
Polynomial peAlphaAboveZero(const PEInput& in);  // w.e
Polynomial peAlphaBelowOne(const PEInput& in);   // (x1 - x3).(x2 - x3)
Polynomial peApproach(const PEInput& in, QuinticForm form = QuinticForm::Exact);  // V.N
Polynomial phDistance(const PHInput& in);   // r^2 |m|^2 - ((p - x1(t)).m)^2
Polynomial phApproach(const PHInput& in);   // -(D1.m)^2 t + ((p - x1).m)(D1.m)

/// The polynomials of one pair, in the order above (count 2 for PP and PH, 4 for PE).
struct PairPolynomials {
  std::array<Polynomial, 4> polys;
  int count = 0;
};

/// A detected collision: the time tau in [0, 1] and the contact vector at tau (unnormalised):
///   PP: x2(tau) - x1(tau)
///   PE: x2(tau) + alpha e(tau) - x1(tau), alpha = (w.e)/(e.e) at tau, NOT clamped
///   PH: ((p - x1(tau)).m / m.m) m
struct Contact {
  double tau = kNever;
  Vec2 n = Vec2::Zero();
};

/// Detection. Returns true on a collision and then fills *hit (if not null).
/// log == nullptr: fast path, with early exits as soon as one condition is never met in the
///   step (for PE also a swept bounding-box test before any polynomial is built).
/// log != nullptr: *log is OVERWRITTEN with all the pair's polynomials, in order, whatever
///   the outcome (the caller appends them to the step's log). The answer is the same as on
///   the fast path: the early exits only skip work whose result they already know.
/// rules: see DetectionRules (the quintic form only concerns PE).
bool detectPP(const PPInput& in, Contact* hit, PairPolynomials* log = nullptr, const DetectionRules& rules = {});
bool detectPE(const PEInput& in, Contact* hit, PairPolynomials* log = nullptr, const DetectionRules& rules = {});
bool detectPH(const PHInput& in, Contact* hit, PairPolynomials* log = nullptr, const DetectionRules& rules = {});

/// Contact vectors at a given time (also what detect* report at tau).
Vec2 ppContactVector(const PPInput& in, double tau);
Vec2 peContactVector(const PEInput& in, double tau);
Vec2 phContactVector(const PHInput& in, double tau);

/// Relative margin of the PE swept-box rejection: boxes are inflated by this fraction of the
/// pair's size (coordinates, displacements, radii) on top of rv + re, so that the test only
/// fires when the pair is apart by far more than rounding could ever bridge; whatever it
/// rejects, the polynomials would have rejected too.
constexpr double kSweptBoxMargin = 1e-6;

}  // namespace fosssim::math
