#include "fosssim/math/interval_solver.h"

#include <cmath>

#include "fosssim/math/contract.h"
#include "fosssim/math/real_roots.h"
#include "staged_solve.h"

namespace fosssim::math {
namespace {

bool allFinite(const Polynomial& p) {
  for (int i = 0; i < p.size; ++i)
    if (!std::isfinite(p.c[i])) return false;
  return true;
}

inline int signOf(double v) { return (v > 0.0) - (v < 0.0); }

// Sign of p on (x, x + eps) when p(x) is numerically zero: the first derivative that is not
// numerically zero decides (Taylor expansion at x).
int signJustAfterRoot(const Polynomial& p, double x) {
  Polynomial d = p.derivative();
  while (d.size > 0) {
    const double v = evaluateSnapped(d, x);
    if (v != 0.0) return signOf(v);
    d = d.derivative();
  }
  return 0;
}

void linearSet(const Polynomial& p, double tMax, PositiveSet* set) {
  double r = -p.c[1] / p.c[0];
  snapRootToEnd(p, tMax, &r, 1);
  if (p.c[0] > 0.0) {  // positive on (r, inf)
    if (r <= tMax) set->append(r > 0.0 ? r : 0.0, kNever);
  } else if (r > 0.0) {  // positive on (-inf, r)
    set->append(0.0, r);
  }
}

void quadraticSet(const Polynomial& p, double tMax, PositiveSet* set) {
  double r[2];
  const int k = quadraticRoots(p.c[0], p.c[1], p.c[2], r);
  const bool upward = p.c[0] > 0.0;
  snapRootToEnd(p, tMax, r, k);
  if (k < 2) {  // no real root or a touching one: the sign of a everywhere (but one instant)
    if (upward) set->append(0.0, kNever);
    return;
  }
  if (upward) {  // positive outside [r0, r1]
    if (r[0] > 0.0) set->append(0.0, r[0]);
    if (r[1] <= tMax) set->append(r[1] > 0.0 ? r[1] : 0.0, kNever);
  } else if (r[1] > 0.0 && r[0] <= tMax) {  // positive inside (r0, r1)
    set->append(r[0] > 0.0 ? r[0] : 0.0, r[1]);
  }
}

// Degree >= 3: root in [0, tMax], then the sign of each piece between consecutive roots.
void generalSet(const Polynomial& p, double tMax, PositiveSet* set) {
  double roots[kMaxRoots];
  const int n = realRootsInInterval(p, tMax, roots);
  double start = 0.0;
  int lastSign = p.signJustAfterZero();  // exact, from the coefficients
  bool first = true;
  for (int i = 0; i <= n; ++i) {
    const double end = (i < n) ? roots[i] : tMax;
    if (end <= start) continue;  // a root at 0, or the root at tMax closing the list
    // The first piece's sign is read exactly at 0; the others at their midpoints, which lie
    // as far as possible from the roots that bound them.
    lastSign = first ? lastSign : signOf(p(0.5 * (start + end)));
    first = false;
    if (lastSign > 0) set->append(start, end);
    start = end;
  }
  const bool rootAtEnd = n > 0 && roots[n - 1] == tMax;
  const int signAfter = rootAtEnd ? signJustAfterRoot(p, tMax) : lastSign;
  if (signAfter > 0) set->append(tMax, kNever);
}

// ---- IntervalRule::Reference

// Adds the reference's closed interval [a, b] in the form the chase needs: intervals ending at or
// before 0 are dropped (the reference skips them when it looks for the first time >= 0, and an
// intersection with one of them ends at or before 0 too), starts are clamped up to 0 (the start
// of an intersection is the largest start, and the answer its maximum with 0), and intervals
// starting after tMax are dropped (whatever they add to the intersection starts after tMax).
// Appended in ascending order of a, touching or overlapping intervals merge, as the reference's
// consolidation does.
void appendClosed(double a, double b, double tMax, PositiveSet* set) {
  if (!(b > 0.0) || a > tMax) return;
  set->append(a > 0.0 ? a : 0.0, b);
}

// Degree 0 to 2, exactly as the reference: its roots (referenceRealRoots), then the sign of each
// piece read at one point by Horner's rule (Polynomial::operator() evaluates in the same order).
void referenceLowDegreeSet(const Polynomial& p, double tMax, PositiveSet* set) {
  double r[2];
  const int n = p.degree() >= 1 ? referenceRealRoots(p, r) : 0;
  if (n == 0) {  // a constant, or no real root: all or nothing, as p(0) says
    if (p(0.0) > 0.0) appendClosed(-kNever, kNever, tMax, set);
    return;
  }
  // In ascending order of start: (-inf, r0], then [r_i, r_i+1], then [r_last, inf).
  if (p(r[0] - 1.0) > 0.0) appendClosed(-kNever, r[0], tMax, set);
  if (n == 2 && p(0.5 * (r[0] + r[1])) > 0.0) appendClosed(r[0], r[1], tMax, set);
  if (p(r[n - 1] + 1.0) > 0.0) appendClosed(r[n - 1], kNever, tMax, set);
}

}  // namespace

void PositiveSet::append(double a, double b) {
  if (count > 0 && hi[count - 1] >= a) {  // touching or overlapping: extend
    if (b > hi[count - 1]) hi[count - 1] = b;
    return;
  }
  // Capacity: see kMaxIntervals. Never dropped silently: a fifth stretch is a bug.
  FOSSSIM_ASSERT(count < kMaxIntervals);
  lo[count] = a;
  hi[count] = b;
  ++count;
}

PositiveSet positiveSet(const Polynomial& p, double tMax, IntervalRule rule) {
  PositiveSet set;
  if (p.size == 0 || !allFinite(p)) return set;
  if (rule == IntervalRule::Reference && p.degree() <= 2) {
    referenceLowDegreeSet(p, tMax, &set);
    return set;
  }
  // Degree >= 3 under the Reference rule: FOSSSim's pieces between its own roots in [0, tMax]
  // have the signs the reference reads, and are read as closed by firstCommonTime. The roots
  // themselves are FOSSSim's (a root at tMax snapped as in the Exact rule), not rpoly's: a
  // particle-edge contact exactly at the end of a step may still be decided differently.
  switch (p.degree()) {
    case 0:
      if (p.c[0] > 0.0) set.append(0.0, kNever);
      break;
    case 1:
      linearSet(p, tMax, &set);
      break;
    case 2:
      quadraticSet(p, tMax, &set);
      break;
    default:
      generalSet(p, tMax, &set);
      break;
  }
  return set;
}

double firstCommonTime(const PositiveSet* sets, int count, double tMax, IntervalRule rule) {
  // Chase: t only grows, and never past a point of the intersection. At a fixed point every
  // set contains t, so t is the infimum of the intersection. Half-open [lo, hi) no longer
  // contains t once hi <= t; the reference's closed [lo, hi] still does at hi == t (touching
  // stretches meet: its overlap test is b.s <= a.e && a.s <= b.e).
  const bool closed = rule == IntervalRule::Reference;
  double t = 0.0;
  FOSSSIM_ASSERT(count <= kMaxSolverPolynomials);
  int cursor[kMaxSolverPolynomials] = {};
  for (bool moved = true; moved;) {
    moved = false;
    for (int i = 0; i < count; ++i) {
      const PositiveSet& s = sets[i];
      int& k = cursor[i];
      while (k < s.count && (closed ? s.hi[k] < t : s.hi[k] <= t)) ++k;
      if (k == s.count) return kNever;
      if (s.lo[k] > t) {
        t = s.lo[k];
        moved = true;
      }
    }
  }
  return t <= tMax ? t : kNever;
}

// The staged solve (staged_solve.h, what CCD uses) with every polynomial at once: one
// implementation of the rules for both.
double firstPositiveTime(const Polynomial* polys, int count, double tMax, IntervalRule rule) {
  FOSSSIM_ASSERT(count <= kMaxSolverPolynomials);
  // Cheapest (lowest degree) first, so an empty set is usually found before any iteration.
  // (The answer does not depend on the order: it is the infimum of the sets' intersection.)
  int order[kMaxSolverPolynomials];
  for (int i = 0; i < count; ++i) {
    int j = i;
    for (; j > 0 && polys[order[j - 1]].size > polys[i].size; --j) order[j] = order[j - 1];
    order[j] = i;
  }
  StagedSolve solve(rule, tMax);
  for (int i = 0; i < count; ++i)
    if (!solve.add(polys[order[i]])) return kNever;
  return solve.finish();
}

}  // namespace fosssim::math
