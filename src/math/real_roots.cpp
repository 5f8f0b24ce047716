#include "fosssim/math/real_roots.h"

#include <cfloat>
#include <cmath>

namespace fosssim::math {
namespace {

constexpr double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

// Power basis -> Bernstein basis of degree n on [0,1]: with p(t) = sum_k a_k t^k,
// t^k = sum_{j>=k} [C(j,k)/C(n,k)] B_{j,n}(t), hence b_j = sum_{k<=j} C(j,k)/C(n,k) a_k.
struct BernsteinTable {
  double w[Polynomial::kMaxCoeffs][Polynomial::kMaxCoeffs][Polynomial::kMaxCoeffs]{};
  constexpr BernsteinTable() {
    for (int n = 0; n < Polynomial::kMaxCoeffs; ++n)
      for (int j = 0; j <= n; ++j)
        for (int k = 0; k <= j; ++k) w[n][j][k] = binomial(j, k) / binomial(n, k);
  }
};
constexpr BernsteinTable kBernstein{};

// Appends r to the ascending list unless it repeats the last entry (a root met both as a
// zero breakpoint and as a bracket end must be reported once).
inline void pushRoot(double r, double* roots, int* count) {
  if (*count > 0 && roots[*count - 1] >= r) return;
  if (*count < kMaxRoots) roots[(*count)++] = r;
}

}  // namespace

int bernsteinCoefficients(const Polynomial& p, double tMax, double b[Polynomial::kMaxCoeffs]) {
  const int n = p.degree();
  double a[Polynomial::kMaxCoeffs];
  double scale = 1.0;  // substitute t = tMax*s so that s runs over [0,1]
  for (int k = 0; k <= n; ++k) {
    a[k] = p.c[n - k] * scale;
    scale *= tMax;
  }
  const auto& w = kBernstein.w[n];
  for (int j = 0; j <= n; ++j) {
    double s = 0.0;
    for (int k = 0; k <= j; ++k) s += w[j][k] * a[k];
    b[j] = s;
  }
  return n;
}

int signVariations(const double* b, int count) {
  int variations = 0;
  int last = 0;
  for (int i = 0; i < count; ++i) {
    const int s = (b[i] > 0.0) - (b[i] < 0.0);
    if (s == 0) continue;
    if (last != 0 && s != last) ++variations;
    last = s;
  }
  return variations;
}

double bracketedRoot(const Polynomial& p, double lo, double hi, double fLo, double fHi) {
  const bool loNegative = fLo < 0.0;
  const double absTol = kRootAbsoluteTolerance * (hi > 1.0 ? hi : 1.0);
  // Start from the secant (false position) point: exact for lines, close for gentle curves.
  double x = lo + (hi - lo) * (fLo / (fLo - fHi));
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  double stepBeforeLast = hi - lo;
  double lastStep = stepBeforeLast;
  for (int it = 0; it < kMaxRootIterations; ++it) {
    double f = 0.0;
    double df = 0.0;
    p.evaluate(x, &f, &df);
    if (f == 0.0) return x;
    if ((f < 0.0) == loNegative) {
      lo = x;
    } else {
      hi = x;
    }
    double next = 0.0;
    const double newton = (df != 0.0) ? f / df : 0.0;
    const double candidate = x - newton;
    // rtsafe's rule: take the Newton step only if it stays strictly inside the bracket and
    // is less than half the step before last (otherwise convergence is not fast enough).
    if (df != 0.0 && candidate > lo && candidate < hi &&
        std::fabs(newton) <= 0.5 * std::fabs(stepBeforeLast)) {
      stepBeforeLast = lastStep;
      lastStep = newton;
      next = candidate;
    } else {
      stepBeforeLast = lastStep;
      lastStep = 0.5 * (hi - lo);
      next = lo + lastStep;
      if (next <= lo || next >= hi) return x;  // bracket is two adjacent doubles
    }
    if (std::fabs(next - x) <= kRootStepUlps * DBL_EPSILON * std::fabs(next) + absTol) return next;
    x = next;
  }
  return x;
}

int realRootsInInterval(const Polynomial& p, double tMax, double roots[kMaxRoots]) {
  const int n = p.degree();
  int count = 0;
  if (n <= 0) return 0;
  if (n == 1) {
    double r = -p.c[1] / p.c[0];
    snapRootToEnd(p, tMax, &r, 1);
    if (r >= 0.0 && r <= tMax) roots[count++] = r;
    return count;
  }
  if (n == 2) {
    double r[2];
    const int k = quadraticRoots(p.c[0], p.c[1], p.c[2], r);
    snapRootToEnd(p, tMax, r, k);
    for (int i = 0; i < k; ++i)
      if (r[i] >= 0.0 && r[i] <= tMax) pushRoot(r[i], roots, &count);
    return count;
  }

  const double f0 = p.c[n];  // p(0), exact
  const double fT = evaluateSnapped(p, tMax);
  double b[Polynomial::kMaxCoeffs];
  bernsteinCoefficients(p, tMax, b);
  const int variations = signVariations(b, n + 1);
  if (variations == 0) {  // no root inside (0, tMax); only the ends can be roots
    if (f0 == 0.0) pushRoot(0.0, roots, &count);
    if (fT == 0.0) pushRoot(tMax, roots, &count);
    return count;
  }
  if (variations == 1 && f0 != 0.0 && fT != 0.0 && ((f0 < 0.0) != (fT < 0.0))) {
    roots[count++] = bracketedRoot(p, 0.0, tMax, f0, fT);  // exactly one simple root
    return count;
  }

  // General case: p is monotone between consecutive critical points.
  double crit[kMaxRoots];
  const int nCrit = realRootsInInterval(p.derivative(), tMax, crit);
  double at[kMaxRoots + 2];
  double val[kMaxRoots + 2];
  int nb = 0;
  at[nb] = 0.0;
  val[nb++] = f0;
  for (int i = 0; i < nCrit; ++i) {
    if (crit[i] <= at[nb - 1] || crit[i] >= tMax) continue;  // ends are already breakpoints
    at[nb] = crit[i];
    val[nb++] = evaluateSnapped(p, crit[i]);
  }
  at[nb] = tMax;
  val[nb++] = fT;
  for (int k = 0; k < nb; ++k) {
    if (val[k] == 0.0) pushRoot(at[k], roots, &count);
    if (k + 1 < nb && val[k] != 0.0 && val[k + 1] != 0.0 && ((val[k] < 0.0) != (val[k + 1] < 0.0)))
      pushRoot(bracketedRoot(p, at[k], at[k + 1], val[k], val[k + 1]), roots, &count);
  }
  return count;
}

int referenceRealRoots(const Polynomial& p, double roots[2]) {
  // rpoly first divides out roots at 0: trailing exact zeros (at most one can remain with a
  // nonzero root beside it, since p has degree <= 2 and a nonzero leading coefficient).
  int n = p.degree();
  int count = 0;
  while (n > 0 && p.c[n] == 0.0) {
    roots[count++] = 0.0;
    --n;
  }
  if (n < 1) return 0;  // only roots at 0: the port returns failure, and no root is used
  if (n == 1) {
    roots[count++] = -p.c[1] / p.c[0];
  } else {
    // Quad(a, b1, c); c != 0 here (zero roots are gone), a != 0 (leading coefficient).
    const double a = p.c[0], c = p.c[2];
    const double b = p.c[1] / 2.0;
    double e = 0.0;
    double d = 0.0;
    if (std::fabs(b) < std::fabs(c)) {
      e = b * (b / std::fabs(c)) - (c < 0.0 ? -a : a);
      d = std::sqrt(std::fabs(e)) * std::sqrt(std::fabs(c));
    } else {
      e = 1.0 - (a / b) * (c / b);
      d = std::sqrt(std::fabs(e)) * std::fabs(b);
    }
    if (e < 0.0) {  // complex pair -B/a +- i|D/a|: real only when the imaginary part is tiny
      if (std::fabs(d / a) < kReferenceImaginaryTolerance) {
        roots[count++] = -b / a;
        roots[count++] = -b / a;
      }
    } else {
      if (b >= 0.0) d = -d;
      const double large = (-b + d) / a;
      roots[count++] = (large != 0.0) ? (c / large) / a : 0.0;
      roots[count++] = large;
    }
  }
  if (count == 2 && roots[0] > roots[1]) {
    const double tmp = roots[0];
    roots[0] = roots[1];
    roots[1] = tmp;
  }
  return count;
}

}  // namespace fosssim::math
