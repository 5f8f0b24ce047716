// The polynomial interval solver: the first time t >= 0 at which several polynomials are all
// strictly positive.
//
// Semantics (those of the reference simulator, which roots every polynomial with
// Jenkins-Traub and tests the sign between consecutive roots): the set S where all
// polynomials are > 0 is a union of open intervals; the answer is inf(S intersected with
// [0, inf)), reported when it is <= tMax, else kNever. Consequences:
//  * a root touching 0 counts: p(0) = 0 and p > 0 just after gives t = 0;
//  * a double root touching zero from above excludes one instant only (it never delays the
//    answer); touching from below (a tangent graze) is never positive;
//  * the zero polynomial is never positive; a positive constant always is;
//  * a positive interval that begins exactly at tMax is a hit at tMax (the infimum tMax
//    is <= tMax). The solver looks just past tMax for this, through the Taylor expansion.
//
// Under IntervalRule::Reference (--compat) the reference's own rule is followed instead (see
// IntervalRule below): it differs exactly where a root lies at, or within rounding of, the end
// of the step or where two polynomials' positive stretches only touch.
//
// Work is arranged for the CCD hot path: a polynomial is reduced once to its PositiveSet
// (at most a few intervals inside [0, tMax]); the sets are then intersected by a chase that
// costs nothing next to root finding. Callers who build polynomials one at a time can stop
// as soon as one set is empty (see detect* in ccd.h), with the same answer as the full solve.
#pragma once

#include <limits>

#include "fosssim/math/polynomial.h"

namespace fosssim::math {

/// "No positive time in [0, tMax]".
inline constexpr double kNever = std::numeric_limits<double>::infinity();

/// How roots become the answer.
enum class IntervalRule {
  /// FOSSSim's own (the default): the semantics of the file comment, with roots computed as
  /// accurately as doubles allow, and a root whose polynomial is numerically zero at tMax moved
  /// onto tMax (snapRootToEnd), so that a contact at the very end of a step is always inside it.
  Exact,
  /// The course reference's (ContinuousTimeUtilities, --compat). Each polynomial's roots are
  /// those rpoly computes; for degree 1 and 2 FOSSSim computes them with rpoly's own closed forms
  /// (referenceRealRoots), never snapped; for degree >= 3 (particle-edge) with FOSSSim's root
  /// finder, since rpoly's iterations are not reproduced. Between consecutive roots (and beyond
  /// the first and last) the sign is read at one point (the midpoint, r0 - 1, r_last + 1); the
  /// positive pieces are CLOSED intervals [r_i, r_i+1], intersected as closed intervals, so two
  /// stretches that only touch at t meet at t. The answer is the first t >= 0 of the
  /// intersection, among intervals ending after 0; a hit when it is <= tMax. So a root computed
  /// an ulp past tMax is a miss (the reference responds in the next step), and a root computed
  /// at or before tMax a hit.
  Reference,
};

/// Where one polynomial is positive, in the "right-neighbourhood" sense: t belongs to the
/// set iff p > 0 on (t, t + eps) for some eps > 0. Stored as disjoint ascending half-open
/// intervals [lo, hi) with 0 <= lo <= tMax; hi = kNever (or any value > tMax) when the
/// positivity continues past tMax. Isolated zeros inside a positive stretch (touching roots)
/// do not split it: they never change an infimum.
/// Under IntervalRule::Reference the intervals are closed, [lo, hi], with hi > 0 (intervals of
/// the reference ending at or before 0 never give an answer) and lo clamped up to 0.
struct PositiveSet {
  /// A degree-5 polynomial changes sign at most 5 times: at most 3 positive stretches.
  /// One extra slot absorbs numerically-zero polynomials whose snapped roots split more.
  static constexpr int kMaxIntervals = 4;
  /// Only [0, count) is meaningful; the rest is deliberately left uninitialised (the sets
  /// live on the stack of every CCD query, where zeroing them would rival the query's arithmetic).
  double lo[kMaxIntervals];
  double hi[kMaxIntervals];
  int count = 0;

  bool empty() const { return count == 0; }
  /// Adds [a, b) at the end, merging with the last interval when they touch.
  void append(double a, double b);
};

/// The positive set of p restricted to starts in [0, tMax] (tMax > 0). Non-finite
/// coefficients give the empty set (a NaN state must not cause a collision response).
PositiveSet positiveSet(const Polynomial& p, double tMax = 1.0, IntervalRule rule = IntervalRule::Exact);

/// p > 0 just after t = 0 (exact, from the coefficients) and all coefficients finite. When
/// this holds for every polynomial of a query the answer is 0 without any root finding.
inline bool positiveJustAfterZero(const Polynomial& p) {
  if (p.signJustAfterZero() <= 0) return false;
  double probe = 0.0;  // NaN iff some coefficient is infinite or NaN (inf*0 and NaN*0 are NaN)
  for (int i = 0; i < p.size; ++i) probe += p.c[i] * 0.0;
  return probe == 0.0;
}

/// inf of the common positive set, or kNever: the smallest t in [0, tMax] contained in every
/// set. count = 0 returns 0 (no condition at all holds everywhere). The rule must be the one the
/// sets were built with (it says whether their intervals are half-open or closed).
double firstCommonTime(const PositiveSet* sets, int count, double tMax = 1.0,
                       IntervalRule rule = IntervalRule::Exact);

/// At most this many polynomials per query (the solver keeps fixed-size scratch storage).
constexpr int kMaxSolverPolynomials = 8;

/// The whole solve: the first t in [0, tMax] at which all polys[0..count) are > 0 (see the
/// file comment), or kNever. Cheap exits first: all positive just after 0 gives 0 at once
/// (Exact only: the reference's computed roots decide even then); any empty positive set gives
/// kNever without rooting the others.
double firstPositiveTime(const Polynomial* polys, int count, double tMax = 1.0,
                         IntervalRule rule = IntervalRule::Exact);

}  // namespace fosssim::math
