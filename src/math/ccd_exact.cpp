#include "fosssim/math/ccd_exact.h"

#include "staged_solve.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

namespace fosssim::math {
namespace {

// ---------------------------------------------------------------- normalisation

// Multiplication by 2^-e, e the frexp exponent of the pair's largest magnitude M (so M 2^-e
// lies in [1/2, 1)). A power of two changes only the exponent: exact unless a result falls
// into the subnormal range, where it could not have been represented relative to M anyway.
class PowerOfTwoScale {
 public:
  explicit PowerOfTwoScale(double largest) {
    std::uint64_t bits;
    std::memcpy(&bits, &largest, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    // Normal M = m 2^(biased-1023), m in [1, 2): frexp exponent e = biased - 1022, and 2^-e
    // has biased exponent 2045 - biased, a normal double when that lies in [1, 2046].
    if (biased >= 1 && biased <= 2044) {
      const std::uint64_t f = static_cast<std::uint64_t>(2045 - biased) << 52;
      std::memcpy(&first_, &f, sizeof first_);
    } else {  // subnormal or near-DBL_MAX M: 2^-e is not representable, use two halves
      int e = 0;
      std::frexp(largest, &e);
      first_ = std::ldexp(1.0, -e / 2);
      second_ = std::ldexp(1.0, -e - (-e / 2));
    }
  }
  double operator()(double v) const { return v * first_ * second_; }
  Vec2 operator()(const Vec2& v) const { return Vec2((*this)(v.x()), (*this)(v.y())); }

 private:
  double first_ = 1.0;
  double second_ = 1.0;
};

// Largest magnitude among the components and NaN-safe finiteness, accumulated value by value.
struct Magnitude {
  double largest = 0.0;
  double probe = 0.0;  // stays 0 iff every value was finite (inf*0 and NaN*0 are NaN)
  void add(double v) {
    const double a = std::fabs(v);
    largest = a > largest ? a : largest;
    probe += v * 0.0;
  }
  void add(const Vec2& v) {
    add(v.x());
    add(v.y());
  }
  bool finite() const { return probe == 0.0; }
};

// Unit vector along v, immune to overflow and underflow of |v|^2 (v is pre-scaled by a power
// of two). A zero (or non-finite) v gives the fallback's direction, else (1, 0).
Vec2 unitVector(const Vec2& v, const Vec2& fallback = Vec2::Zero()) {
  Magnitude m;
  m.add(v);
  if (m.largest == 0.0 || !m.finite()) return fallback.isZero() ? Vec2(1.0, 0.0) : unitVector(fallback);
  const Vec2 s = PowerOfTwoScale(m.largest)(v);
  return s / s.norm();
}

// ---------------------------------------------------------------- polynomials

// Stores coefficients (highest power first), dropping leading ones that are negligible
// relative to the largest (kRelativeNegligibleCoefficient, see ccd_exact.h). All zeros give
// the zero polynomial, which is never positive.
void setRelative(Polynomial* out, std::initializer_list<double> coeffs) {
  const double* c = coeffs.begin();
  const int n = static_cast<int>(coeffs.size());
  double largest = 0.0;
  for (int i = 0; i < n; ++i) largest = std::fabs(c[i]) > largest ? std::fabs(c[i]) : largest;
  const double cut = kRelativeNegligibleCoefficient * largest;
  int first = 0;
  while (first < n && std::fabs(c[first]) <= cut) ++first;
  out->assign(c + first, n - first);
}

// Where a disk pair overlaps and approaches, as a PositiveSet (the solver's right-neighbourhood
// sense). The other centre is at x + t D relative to particle 1 (all normalised), radius sum R.
// The conditions are those of ppPosition and ppApproach, R^2 - |x + tD|^2 > 0 and
// -(b + a t) > 0 with a = |D|^2, b = D.x, but solved in closed form: expanded, the constant
// R^2 - |x|^2 loses R entirely once R < 1e-8 |x| (a small fast disk would pass through).
//  * Approaching on [0, t*), t* = -b/a: needs b < 0 (b >= 0 never approaches after t = 0).
//  * Overlap between the roots t* -+ h of a t^2 + 2b t + |x|^2 - R^2, a h = sqrt(b^2 - a|x|^2
//    + aR^2) = sqrt(aR^2 - k^2), k = D x x (cross product), by Lagrange's identity
//    a|x|^2 - b^2 = k^2. So the pair overlaps iff |D| R > |k|, and the square root, taken as
//    sqrt((|D|R - |k|)(|D|R + |k|)), has no cancellation.
//  * Entry t_in = t* - h = (|x|^2 - R^2)/(-b + sqrt(aR^2 - k^2)) (product of the roots is
//    (|x|^2 - R^2)/a), with |x|^2 - R^2 = (|x| - R)(|x| + R) and no cancellation since -b > 0.
// Hit set: [max(0, t_in), t*) when that is non-empty and starts at or before 1.
PositiveSet diskSet(const Vec2& x, const Vec2& D, double R) {
  PositiveSet set;
  const double b = D.dot(x);
  if (!(b < 0.0)) return set;
  const double a = D.squaredNorm();
  const double sa = std::sqrt(a);
  const double k = std::fabs(D.x() * x.y() - D.y() * x.x());
  const double saR = sa * R;
  if (!(saR > k)) return set;  // passes at the radius sum or farther: a graze is no contact
  const double root = std::sqrt((saR - k) * (saR + k));
  const double nx = x.norm();
  const double c = (nx - R) * (nx + R);
  const double tIn = c <= 0.0 ? 0.0 : c / (root - b);
  const double tStar = -b / a;
  if (tIn <= 1.0 && tIn < tStar) set.append(tIn, tStar);
  return set;
}

// First time of diskSet, with an optional extra condition (a capsule cap's side), or kNever.
double diskTime(const Vec2& x, const Vec2& D, double R, const Polynomial* side) {
  PositiveSet sets[2];
  sets[0] = diskSet(x, D, R);
  if (sets[0].empty()) return kNever;
  if (side == nullptr) return sets[0].lo[0];
  sets[1] = positiveSet(*side, 1.0);
  return firstCommonTime(sets, 2, 1.0);
}

// The scalar products of the capsule interior, as PEProducts in ccd.cpp (same letters):
//   G = |e|^2 = a + 2b t + c t^2,  A = w.e = f + g t + h t^2,  W = |w|^2 = s + 2u t + d t^2
// with e(t) = e0 + t De the edge vector and w(t) = w0 + t Dw particle 1 relative to endpoint 2,
// and the cross product C = w x e = x0 + x1 t + x2 t^2.
struct Products {
  double a, b, c, f, g, h, s, u, d, x0, x1, x2;
  Products(const Vec2& e0, const Vec2& de, const Vec2& w0, const Vec2& dw)
      : a(e0.dot(e0)), b(e0.dot(de)), c(de.dot(de)), f(w0.dot(e0)), g(w0.dot(de) + dw.dot(e0)),
        h(dw.dot(de)), s(w0.dot(w0)), u(w0.dot(dw)), d(dw.dot(dw)), x0(cross(w0, e0)),
        x1(cross(w0, de) + cross(dw, e0)), x2(cross(dw, de)) {}
  static double cross(const Vec2& p, const Vec2& q) { return p.x() * q.y() - p.y() * q.x(); }
};

// Interior of the capsule: alpha in (0, 1), distance to the line below R, approaching it.
// The reference's four conditions with the exact quintic (derivations in ccd.cpp).
double interiorTime(const Products& k, const Polynomial& belowOne, double R) {
  StagedSolve solve;
  Polynomial aboveZero;  // w.e > 0
  setRelative(&aboveZero, {k.h, k.g, k.f});
  if (!solve.add(aboveZero)) return kNever;
  if (!solve.add(belowOne)) return kNever;  // (x1 - x3).(x2 - x3) > 0, built by the caller
  // R^2 G - G W + A^2 (|e|^2 times the squared-distance margin to the line), written with
  // Lagrange's identity G W - A^2 = |e|^2 |w|^2 - (w.e)^2 = (w x e)^2 = C^2. Expanded as the
  // reference does, G W and A^2 are each about |e|^2 |w|^2 and cancel down to C^2: R^2 G was lost
  // in their rounding once R fell below some 1e-8 of w, and a disk of radius 1e-8 crossed the
  // middle of an edge of length 2 unseen. C's coefficients are cross products, computed with no
  // cancellation, so R^2 G - C^2 keeps R down to the underflow of R^2.
  const double r2 = R * R;
  Polynomial distance;
  setRelative(&distance, {-k.x2 * k.x2, -2.0 * k.x1 * k.x2, r2 * k.c - (k.x1 * k.x1 + 2.0 * k.x0 * k.x2),
                          2.0 * r2 * k.b - 2.0 * k.x0 * k.x1, r2 * k.a - k.x0 * k.x0});
  if (!solve.add(distance)) return kNever;
  // V.N = -G^2 (u + d t) + G A (g + 2h t) - A^2 (b + c t), products of the quadratics,
  // lowest power first (gg, ga, aa: the coefficients of G^2, G A, A^2).
  const double g0 = k.a, g1 = 2.0 * k.b, g2 = k.c, a0 = k.f, a1 = k.g, a2 = k.h;
  const double gg[5] = {g0 * g0, 2 * g0 * g1, g1 * g1 + 2 * g0 * g2, 2 * g1 * g2, g2 * g2};
  const double ga[5] = {g0 * a0, g0 * a1 + g1 * a0, g0 * a2 + g1 * a1 + g2 * a0, g1 * a2 + g2 * a1, g2 * a2};
  const double aa[5] = {a0 * a0, 2 * a0 * a1, a1 * a1 + 2 * a0 * a2, 2 * a1 * a2, a2 * a2};
  double vn[6];
  for (int i = 0; i < 6; ++i) {
    const double lo = i < 5 ? -gg[i] * k.u + ga[i] * k.g - aa[i] * k.b : 0.0;
    const double hi = i > 0 ? -gg[i - 1] * k.d + ga[i - 1] * 2.0 * k.h - aa[i - 1] * k.c : 0.0;
    vn[i] = lo + hi;
  }
  Polynomial approach;
  setRelative(&approach, {vn[5], vn[4], vn[3], vn[2], vn[1], vn[0]});
  if (!solve.add(approach)) return kNever;
  return solve.finish();
}

// A cap's side condition (the closest point of the segment's line lies beyond that endpoint),
// a quadratic; nullptr when it is identically zero
// (a degenerate edge, or a particle moving exactly on the line through the endpoint
// perpendicular to the edge): then the endpoint is a closest point throughout.
const Polynomial* sideCondition(Polynomial* out, double c2, double c1, double c0) {
  setRelative(out, {c2, c1, c0});
  return out->size == 0 ? nullptr : out;
}

// Narrows [*lo, *hi) to where c1 t + c0 > 0 just after t (right-neighbourhood sense), the
// slope dropped as setRelative would; false when nothing of [0, 1] is left. Written out
// rather than through positiveSet: PH is three of these per query.
bool intersectLine(double c1, double c0, double* lo, double* hi) {
  const double big = std::fmax(std::fabs(c1), std::fabs(c0));
  if (std::fabs(c1) <= kRelativeNegligibleCoefficient * big) return c0 > 0.0;
  const double root = -c0 / c1;
  if (c1 > 0.0) {
    if (root > *lo) *lo = root;
  } else if (root < *hi) {
    *hi = root;
  }
  return *lo <= 1.0 && *lo < *hi;
}

CcdOutcome reportHit(double tau, const Vec2& toward, const Vec2& fallback, double alpha, ExactContact* hit) {
  if (!(tau <= 1.0)) return CcdOutcome::Miss;
  if (hit != nullptr) {
    hit->tau = tau;
    hit->normal = unitVector(toward, fallback);
    hit->alpha = alpha;
  }
  return CcdOutcome::Hit;
}

}  // namespace

CcdOutcome exactPP(const PPInput& in, ExactContact* hit) {
  // Relative quantities in the caller's units (the translation), then one exact scaling.
  const Vec2 x = in.x2 - in.x1;
  const Vec2 D = in.d2 - in.d1;
  const double R = in.r1 + in.r2;
  Magnitude m;
  m.add(x);
  m.add(D);
  m.add(R);
  if (!m.finite()) return CcdOutcome::Overflow;
  if (m.largest == 0.0) return CcdOutcome::Miss;  // coincident points of radius 0: no overlap
  const PowerOfTwoScale s(m.largest);
  const Vec2 xs = s(x), Ds = s(D);
  const double tau = diskTime(xs, Ds, s(R), nullptr);
  return reportHit(tau, xs + tau * Ds, -Ds, 0.0, hit);
}

CcdOutcome exactPE(const PEInput& in, ExactContact* hit) {
  // Positions relative to the moving endpoint 2 (differences only), and endpoint 3's.
  const Vec2 w0 = in.x1 - in.x2, dw = in.d1 - in.d2;  // particle 1 from endpoint 2
  const Vec2 e0 = in.x3 - in.x2, de = in.d3 - in.d2;  // the edge vector
  const Vec2 v0 = in.x1 - in.x3, dv = in.d1 - in.d3;  // particle 1 from endpoint 3
  const double R = in.rv + in.re;
  Magnitude m;
  m.add(w0);
  m.add(dw);
  m.add(e0);
  m.add(de);
  m.add(v0);
  m.add(dv);
  m.add(in.rv);
  m.add(in.re);
  if (!m.finite()) return CcdOutcome::Overflow;
  if (m.largest == 0.0) return CcdOutcome::Miss;
  const PowerOfTwoScale s(m.largest);
  const Vec2 w0s = s(w0), dws = s(dw), e0s = s(e0), des = s(de), v0s = s(v0), dvs = s(dv);
  const double Rs = s(R);

  // Swept boxes in the frame of endpoint 2 (relative motion stays linear): the particle's
  // path against the hull of 0, e0, e0 + De, which holds every point of the moving segment.
  // Apart by more than R plus a margin far above rounding (all magnitudes are <= 2 here),
  // the pair cannot come within R of the segment, caps included.
  const Vec2 p1 = w0s + dws, q1 = e0s + des;
  const double reach = Rs + kSweptBoxMargin;
  for (int i = 0; i < 2; ++i) {
    const double pLo = std::fmin(w0s[i], p1[i]), pHi = std::fmax(w0s[i], p1[i]);
    const double eLo = std::fmin(0.0, std::fmin(e0s[i], q1[i]));
    const double eHi = std::fmax(0.0, std::fmax(e0s[i], q1[i]));
    if (pLo > eHi + reach || eLo > pHi + reach) return CcdOutcome::Miss;
  }

  const Products k(e0s, des, w0s, dws);
  // B(t) = (x1 - x3).(x3 - x2) = (v0 + t dv).(e0 + t De): positive iff alpha > 1. Built from
  // v0 (small near endpoint 3) rather than as A - G, which cancels there.
  const double B2 = dvs.dot(des), B1 = v0s.dot(des) + dvs.dot(e0s), B0 = v0s.dot(e0s);
  Polynomial belowOne;  // alpha < 1: -B > 0 (the reference's (x1 - x3).(x2 - x3))
  setRelative(&belowOne, {-B2, -B1, -B0});
  double best = interiorTime(k, belowOne, Rs);
  int where = 0;  // 0 interior, 2 cap at endpoint 2, 3 cap at endpoint 3
  if (best > 0.0) {  // a cap can only win by being strictly earlier (ties go to the interior)
    // Cap at endpoint 2 while it is the closest point: alpha < 0, i.e. -(w.e) > 0.
    Polynomial side;
    const double t2 = diskTime(-w0s, -dws, Rs, sideCondition(&side, -k.h, -k.g, -k.f));
    if (t2 < best) best = t2, where = 2;
    // Cap at endpoint 3 while alpha > 1, i.e. B > 0.
    const double t3 = diskTime(-v0s, -dvs, Rs, sideCondition(&side, B2, B1, B0));
    if (t3 < best) best = t3, where = 3;
  }
  if (!(best <= 1.0)) return CcdOutcome::Miss;

  const double tau = best;
  const Vec2 w = w0s + tau * dws;  // particle 1 relative to endpoint 2 at tau
  const Vec2 e = e0s + tau * des;
  if (where == 2) return reportHit(tau, -w, -dws, 0.0, hit);
  if (where == 3) return reportHit(tau, -(v0s + tau * dvs), -dvs, 1.0, hit);
  const double ee = e.squaredNorm();
  double alpha = ee > 0.0 ? w.dot(e) / ee : 0.0;
  alpha = alpha < 0.0 ? 0.0 : (alpha > 1.0 ? 1.0 : alpha);
  // Fallback direction (centre exactly on the segment, only through rounding): the normal of
  // the edge on the side the particle came from.
  const Vec2 across(-e.y(), e.x());
  return reportHit(tau, alpha * e - w, across.dot(w0s) > 0.0 ? Vec2(-across) : across, alpha, hit);
}

CcdOutcome exactPH(const PHInput& in, ExactContact* hit) {
  // Unit normal first (its own power-of-two scaling keeps |m|^2 finite for any finite m).
  Magnitude mm;
  mm.add(in.m);
  if (!mm.finite() || mm.largest == 0.0) return CcdOutcome::Overflow;
  const Vec2 ms = PowerOfTwoScale(mm.largest)(in.m);
  const Vec2 n = ms / ms.norm();
  // Signed distance of the boundary from the centre along n, and the normal displacement:
  // (p - x1(t)).n = P - D t (the reference's phDistance, phApproach with unit m).
  const double P = (in.p - in.x1).dot(n);
  const double D = in.d1.dot(n);
  Magnitude m;
  m.add(P);
  m.add(D);
  m.add(in.r);
  if (!m.finite()) return CcdOutcome::Overflow;
  if (m.largest == 0.0) return CcdOutcome::Miss;
  const PowerOfTwoScale s(m.largest);
  const double Ps = s(P), Ds = s(D), rs = s(in.r);
  // ccd.h's r^2 - (P - Dt)^2 > 0 is, for r > 0, the product of two linear factors that are
  // both positive (their sum is 2r): solved as such, nothing cancels however small r is
  // against P. The approach condition PD - D^2 t = D (P - Dt) > 0 is linear already. Three
  // lines intersect in one interval, found here without the general solver.
  double lo = 0.0, hi = kNever;
  if (!(intersectLine(-Ds * Ds, Ps * Ds, &lo, &hi) && intersectLine(Ds, rs - Ps, &lo, &hi) &&
        intersectLine(-Ds, rs + Ps, &lo, &hi) && lo < hi))
    return CcdOutcome::Miss;
  return reportHit(lo, -n, -n, 0.0, hit);
}

}  // namespace fosssim::math
