// Real roots of a Polynomial inside [0, tMax], without ever computing complex roots.
//
// Strategy (cheapest first):
//  * degree 1 and 2 in closed form (the quadratic with the cancellation-free formula);
//  * degree >= 3: the Bernstein coefficients of p on [0, tMax] bound the number of roots in
//    the open interval by their sign variations (Descartes' rule in the Bernstein basis).
//    0 variations: no interior root; 1 variation: exactly one simple root, bracketed by
//    [0, tMax]; otherwise recurse: the roots of p' split [0, tMax] into pieces on which p is
//    monotone, each holding at most one root, found by a safeguarded Newton iteration.
// Values within the rounding-error bound of Horner's rule count as zero (see
// kHornerErrorFactor in polynomial.h): that is how a double root (tangent graze), whose
// extremum computes to +-1e-17 instead of 0, is recognised as touching rather than crossing.
#pragma once

#include <cfloat>
#include <cmath>

#include "fosssim/math/polynomial.h"

namespace fosssim::math {

/// Capacity for root lists: a degree-5 polynomial has at most 5 roots; one slot of slack
/// because snapping near-zero values to zero can, for numerically-zero polynomials, report a
/// touching root next to a crossing one.
constexpr int kMaxRoots = Polynomial::kMaxDegree + 1;

/// Stop the Newton iteration when the step is below this many ulps of the iterate: the next
/// step would only change the last bit, so the root is at full double precision.
constexpr double kRootStepUlps = 2.0;

/// Absolute floor of the Newton stopping step, as a fraction of tMax: roots within 1e-18*tMax
/// of each other are the same time for any simulation purpose, and the floor keeps roots at or
/// next to 0 from needing a thousand halvings to reach denormals.
constexpr double kRootAbsoluteTolerance = 1e-18;

/// Safety cap for the bracketed iteration; bisection alone needs at most ~64 steps on [0,1]
/// in double precision, so this is never reached in practice.
constexpr int kMaxRootIterations = 200;

/// Roots of a*t^2 + b*t + c (a != 0), ascending. Returns 0, 1 (a double root: the
/// discriminant is within its rounding error of 0) or 2. Uses q = -(b + sign(b)sqrt(D))/2,
/// roots q/a and c/q, which never subtracts nearly equal numbers.
int quadraticRoots(double a, double b, double c, double roots[2]);

/// When p(tMax) is numerically zero, moves the root closest to tMax onto tMax exactly (the
/// closed forms for degrees 1 and 2 may land an ulp away, which would decide whether a root
/// exactly at the end of the step is inside it; degree >= 3 roots come out snapped already).
void snapRootToEnd(const Polynomial& p, double tMax, double* roots, int count);

/// Sorted, distinct real roots of p in the closed interval [0, tMax] (tMax > 0). Roots of
/// even multiplicity (touching points) are included. Returns the count. The zero polynomial
/// and nonzero constants have no isolated roots: 0 is returned.
int realRootsInInterval(const Polynomial& p, double tMax, double roots[kMaxRoots]);

/// The unique root of p in (lo, hi), given fLo = p(lo) and fHi = p(hi) nonzero with opposite
/// signs. Safeguarded Newton: a Newton step that leaves the bracket or fails to halve the
/// step of two iterations ago is replaced by bisection, so convergence is guaranteed and
/// quadratic near a simple root.
double bracketedRoot(const Polynomial& p, double lo, double hi, double fLo, double fHi);

/// p(t) with values inside the Horner rounding-error bound snapped to exactly 0.
double evaluateSnapped(const Polynomial& p, double t);

/// Bernstein coefficients of p on [0, tMax] (degree n: n+1 values, b[0] = p(0),
/// b[n] ~ p(tMax)). Returns n. p must be nonzero.
int bernsteinCoefficients(const Polynomial& p, double tMax, double b[Polynomial::kMaxCoeffs]);

/// Number of sign changes in b[0..count-1], exact zeros skipped.
int signVariations(const double* b, int count);

// ---- The reference simulator's roots of degree 1 and 2 (IntervalRule::Reference, --compat)
//
// The course's reference roots every polynomial with Jenkins-Traub (TOMS 493 `rpoly`, in its
// common C++ port) and keeps the roots whose imaginary part is below
// kReferenceImaginaryTolerance. For degree 1 and 2 rpoly does not iterate: it strips roots at 0
// (p ends in exact zeros), then takes -p1/p0 for a line, and for a quadratic its `Quad` formula,
// which differs from quadraticRoots above in rounding: with B = b/2 it forms the scaled
// discriminant E = B*(B/|c|) -+ a (when |B| < |c|) or 1 - (a/B)*(c/B) (otherwise), takes the
// root of larger modulus as (-B -+ D)/a with D = sqrt|E| * sqrt|c| or sqrt|E| * |B|, and the
// other as (c/large)/a. A root at the very end of a step (tracker: two disks meeting exactly at
// t = 1) comes out a few ulps on either side of 1 depending on these roundings, and decides in
// which step the reference responds; so under --compat FOSSSim computes them operation for
// operation (rounded as written, without fused multiply-adds, as on the x86-64 builds).
// Replaying every particle-particle and particle-half-plane pair of the conformance suite's
// continuous-time logs (51100 pairs, 64 collisions) through this emulation reproduces every
// recorded collision and its time bit for bit.

/// Imaginary parts with magnitude below this make a root real (the reference's eps).
constexpr double kReferenceImaginaryTolerance = 1e-8;

/// The real roots of p (degree 1 or 2, finite coefficients) as the reference computes them,
/// ascending, duplicates kept (a complex pair with a tiny imaginary part gives its real part
/// twice). Returns the count, 0 to 2. When every root is at 0 (p = a t^k) the port reports
/// failure and the reference sees no roots at all: 0 is returned then too.
int referenceRealRoots(const Polynomial& p, double roots[2]);

// ---- inline definitions (these run in every PP and PH query)

inline int quadraticRoots(double a, double b, double c, double roots[2]) {
  const double disc = b * b - 4.0 * a * c;
  /// The discriminant is computed from products of size b^2 and 4|ac|; below its rounding
  /// error it carries no sign information, and the vertex value -D/(4a) is numerically zero:
  /// a double root (the same rule as evaluateSnapped applies to higher degrees).
  const double discError = kHornerErrorFactor * DBL_EPSILON * (b * b + 4.0 * std::fabs(a * c));
  if (std::fabs(disc) <= discError) {
    roots[0] = -b / (2.0 * a);
    return 1;
  }
  if (disc < 0.0) return 0;
  const double s = std::sqrt(disc);
  const double q = -0.5 * (b + (b >= 0.0 ? s : -s));  // |q| >= s/2 > 0, no cancellation
  double r1 = q / a;
  double r2 = c / q;
  if (r1 > r2) {
    const double tmp = r1;
    r1 = r2;
    r2 = tmp;
  }
  roots[0] = r1;
  roots[1] = r2;
  return 2;
}

inline void snapRootToEnd(const Polynomial& p, double tMax, double* roots, int count) {
  if (count == 0 || evaluateSnapped(p, tMax) != 0.0) return;
  int best = 0;
  for (int i = 1; i < count; ++i)
    if (std::fabs(roots[i] - tMax) < std::fabs(roots[best] - tMax)) best = i;
  roots[best] = tMax;
}

inline double evaluateSnapped(const Polynomial& p, double t) {
  double bound = 0.0;
  const double v = p.evaluateWithErrorBound(t, &bound);
  return std::fabs(v) <= bound ? 0.0 : v;
}

}  // namespace fosssim::math
