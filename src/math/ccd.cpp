#include "fosssim/math/ccd.h"

#include "staged_solve.h"

#include <initializer_list>

namespace fosssim::math {
namespace {

// Every CCD polynomial is stored through here: the reference's leading-coefficient cutoff.
inline void setTrimmed(Polynomial* out, std::initializer_list<double> coeffs) {
  out->assign(coeffs, kNegligibleLeadingCoefficient);
}

// The scalar products every PE polynomial is made of. With
//   e(t) = e0 + t De   (e0 = x3 - x2, De = d3 - d2: the edge vector)
//   w(t) = w0 + t Dw   (w0 = x1 - x2, Dw = d1 - d2: particle relative to endpoint 2)
// we have
//   G(t) = |e|^2 = a + 2b t + c t^2        a = e0.e0, b = e0.De, c = De.De
//   A(t) = w.e   = f + g t + h t^2          f = w0.e0, g = w0.De + Dw.e0, h = Dw.De
//   W(t) = |w|^2 = s + 2u t + d t^2         s = w0.w0, u = w0.Dw, d = Dw.Dw
// (letters a..h, d as in the spec's notation; the spec's "e" is our u = Dw.w0).
struct PEProducts {
  double a, b, c, f, g, h, s, u, d;
  explicit PEProducts(const PEInput& in) {
    const Vec2 e0 = in.x3 - in.x2;
    const Vec2 de = in.d3 - in.d2;
    const Vec2 w0 = in.x1 - in.x2;
    const Vec2 dw = in.d1 - in.d2;
    a = e0.dot(e0);
    b = e0.dot(de);
    c = de.dot(de);
    f = w0.dot(e0);
    g = w0.dot(de) + dw.dot(e0);
    h = dw.dot(de);
    s = w0.dot(w0);
    u = w0.dot(dw);
    d = dw.dot(dw);
  }
};

void peDistanceInto(const PEProducts& k, double radiusSum, Polynomial* out) {
  // R^2 G - G W + A^2, expanded power by power (R = rv + re):
  //   G W = as + (2au + 2bs) t + (ad + 4bu + cs) t^2 + (2bd + 2cu) t^3 + cd t^4
  //   A^2 = f^2 + 2fg t + (g^2 + 2fh) t^2 + 2gh t^3 + h^2 t^4
  const double r2 = radiusSum * radiusSum;
  setTrimmed(out, {
      k.h * k.h - k.c * k.d,
      2.0 * k.g * k.h - 2.0 * k.b * k.d - 2.0 * k.c * k.u,
      r2 * k.c - (k.a * k.d + 4.0 * k.b * k.u + k.c * k.s) + (k.g * k.g + 2.0 * k.f * k.h),
      2.0 * r2 * k.b - (2.0 * k.a * k.u + 2.0 * k.b * k.s) + 2.0 * k.f * k.g,
      r2 * k.a - k.a * k.s + k.f * k.f,
  });
}

void peApproachInto(const PEProducts& k, QuinticForm form, Polynomial* out) {
  // V = G Dw - A De and N = G (x2 - x1)(t) + A e(t) = -G w + A e, so
  //   V.N = -G^2 (w.Dw) + G A (Dw.e + De.w) - A^2 (De.e)
  //       = -G^2 (u + d t) + G A (g + 2h t) - A^2 (b + c t).
  // Written below in the spec's notation, term for term in the reference's order, so that
  // rounding matches it as closely as possible: p = b, q = c, e = u, i = -g, j = -h and
  // the products of G A = k + l t + m t^2 + n t^3 + o t^4.
  const double a = k.a, b = k.b, c = k.c, d = k.d, e = k.u, f = k.f, g = k.g, h = k.h;
  const double i = -g, j = -h, p = b, q = c;
  const double kk = a * f;
  const double l = a * g + 2.0 * b * f;
  const double m = a * h + 2.0 * b * g + c * f;
  const double n = c * g + 2.0 * b * h;
  const double o = c * h;
  // The single difference of the reference: its t^3 coefficient has f g q where the
  // expansion of -A^2 (b + c t) gives f h q (A^2's t^2 coefficient g^2 + 2fh times c).
  const double fxq = (form == QuinticForm::Exact ? h : g) * f * q;
  setTrimmed(out, {
      -h * h * q - c * c * d - 2.0 * o * j,
      -h * h * p - 2.0 * g * h * q - 4.0 * b * c * d - c * c * e - o * i - 2.0 * n * j,
      -2.0 * g * h * p - 2.0 * fxq - g * g * q - 2.0 * a * c * d - 4.0 * b * b * d - 4.0 * b * c * e -
          n * i - 2.0 * m * j,
      -2.0 * f * h * p - g * g * p - 2.0 * f * g * q - 4.0 * a * b * d - 2.0 * a * c * e -
          4.0 * b * b * e - m * i - 2.0 * l * j,
      -2.0 * f * g * p - f * f * q - a * a * d - 4.0 * a * b * e - l * i - 2.0 * kk * j,
      -f * f * p - a * a * e - kk * i,
  });
}

// Conservative swept-box test: true when the particle's swept disc (radius rv + re) and the
// edge's swept segment cannot meet. The box of a straight path is the box of its two ends;
// the edge's swept region lies inside the box of its four end positions. Any PE collision
// needs the particle within rv + re of a point of the edge, so separation of the inflated
// boxes (by a margin far above rounding) means no positive time for all three of the
// distance and alpha conditions, exactly what the polynomials would conclude.
bool sweptBoxesApart(const PEInput& in) {
  const Vec2 p0 = in.x1;
  const Vec2 p1 = in.x1 + in.d1;
  const Vec2 a0 = in.x2, a1 = in.x2 + in.d2, b0 = in.x3, b1 = in.x3 + in.d3;
  const Vec2 pMin = p0.cwiseMin(p1), pMax = p0.cwiseMax(p1);
  const Vec2 eMin = a0.cwiseMin(a1).cwiseMin(b0.cwiseMin(b1));
  const Vec2 eMax = a0.cwiseMax(a1).cwiseMax(b0.cwiseMax(b1));
  const double scale = pMax.cwiseAbs().maxCoeff() + pMin.cwiseAbs().maxCoeff() +
                       eMax.cwiseAbs().maxCoeff() + eMin.cwiseAbs().maxCoeff() + in.rv + in.re;
  const double reach = in.rv + in.re + kSweptBoxMargin * scale;
  return (pMin.array() > eMax.array() + reach).any() || (eMin.array() > pMax.array() + reach).any();
}

bool report(double tau, Contact* hit, Vec2 n) {
  if (!(tau <= 1.0)) return false;
  if (hit != nullptr) {
    hit->tau = tau;
    hit->n = n;
  }
  return true;
}

}  // namespace

// ---------------------------------------------------------------- builders
// Each polynomial has an in-place builder (detection writes straight into the caller's log:
// copying a freshly built Polynomial stalls on store forwarding, a cost of the order of a PP
// query's own arithmetic) and a value-returning public wrapper.

namespace {

void ppPositionInto(const PPInput& in, Polynomial* out) {
  // |x21 + t D21|^2 <= (r1+r2)^2  <=>  -|D21|^2 t^2 - 2 (D21.x21) t + (r1+r2)^2 - |x21|^2 >= 0
  const Vec2 x21 = in.x2 - in.x1;
  const Vec2 d21 = in.d2 - in.d1;
  const double rs = in.r1 + in.r2;
  setTrimmed(out, {-d21.squaredNorm(), -2.0 * d21.dot(x21), rs * rs - x21.squaredNorm()});
}

void ppApproachInto(const PPInput& in, Polynomial* out) {
  // Approaching while d/dt |x21(t)|^2 / 2 = D21.x21 + |D21|^2 t < 0; the reference writes the
  // negation with D12 = -D21.
  const Vec2 x21 = in.x2 - in.x1;
  const Vec2 d21 = in.d2 - in.d1;
  const Vec2 d12 = in.d1 - in.d2;
  setTrimmed(out, {-d21.squaredNorm(), d12.dot(x21)});
}

void peAlphaAboveZeroInto(const PEProducts& k, Polynomial* out) { setTrimmed(out, {k.h, k.g, k.f}); }

void peAlphaBelowOneInto(const PEInput& in, Polynomial* out) {
  // (x1 - x3)(t).(x2 - x3)(t) with both factors linear in t.
  const Vec2 u0 = in.x1 - in.x3, du = in.d1 - in.d3;
  const Vec2 v0 = in.x2 - in.x3, dv = in.d2 - in.d3;
  setTrimmed(out, {du.dot(dv), u0.dot(dv) + du.dot(v0), u0.dot(v0)});
}

void phDistanceInto(const PHInput& in, Polynomial* out) {
  // With P = (p - x1).m and D = d1.m, (p - x1(t)).m = P - D t, so
  // r^2|m|^2 - (P - D t)^2 = -D^2 t^2 + 2PD t + r^2|m|^2 - P^2.
  const double P = (in.p - in.x1).dot(in.m);
  const double D = in.d1.dot(in.m);
  setTrimmed(out, {-D * D, 2.0 * P * D, in.r * in.r * in.m.squaredNorm() - P * P});
}

void phApproachInto(const PHInput& in, Polynomial* out) {
  // Half of d/dt of the distance polynomial: moving towards the boundary.
  const double P = (in.p - in.x1).dot(in.m);
  const double D = in.d1.dot(in.m);
  setTrimmed(out, {-D * D, P * D});
}

}  // namespace

Polynomial ppPosition(const PPInput& in) {
  Polynomial p;
  ppPositionInto(in, &p);
  return p;
}

Polynomial ppApproach(const PPInput& in) {
  Polynomial p;
  ppApproachInto(in, &p);
  return p;
}

Polynomial peDistance(const PEInput& in) {
  Polynomial p;
  peDistanceInto(PEProducts(in), in.rv + in.re, &p);
  return p;
}

Polynomial peAlphaAboveZero(const PEInput& in) {
  Polynomial p;
  peAlphaAboveZeroInto(PEProducts(in), &p);
  return p;
}

Polynomial peAlphaBelowOne(const PEInput& in) {
  Polynomial p;
  peAlphaBelowOneInto(in, &p);
  return p;
}

Polynomial peApproach(const PEInput& in, QuinticForm form) {
  Polynomial p;
  peApproachInto(PEProducts(in), form, &p);
  return p;
}

Polynomial phDistance(const PHInput& in) {
  Polynomial p;
  phDistanceInto(in, &p);
  return p;
}

Polynomial phApproach(const PHInput& in) {
  Polynomial p;
  phApproachInto(in, &p);
  return p;
}

// ---------------------------------------------------------------- contact vectors

Vec2 ppContactVector(const PPInput& in, double tau) {
  return (in.x2 + tau * in.d2) - (in.x1 + tau * in.d1);
}

Vec2 peContactVector(const PEInput& in, double tau) {
  const Vec2 x1 = in.x1 + tau * in.d1;
  const Vec2 x2 = in.x2 + tau * in.d2;
  const Vec2 x3 = in.x3 + tau * in.d3;
  const double alpha = segmentParameterUnclamped(x1, x2, x3);
  return x2 + alpha * (x3 - x2) - x1;
}

Vec2 phContactVector(const PHInput& in, double tau) {
  return halfPlaneContactVector(in.x1 + tau * in.d1, in.p, in.m);
}

// ---------------------------------------------------------------- detection

// Each detector adds the polynomials to the staged solve cheapest first (the approach line
// of PP and PH; the alpha quadratics of PE before the quartic and the quintic). With a log,
// everything is built first, straight into the log, in the reference's order, and solved
// the same way. Without one, only what is needed is built, into locals (a zeroed scratch
// PairPolynomials would cost more than the PP solve itself).

bool detectPP(const PPInput& in, Contact* hit, PairPolynomials* log, const DetectionRules& rules) {
  StagedSolve solve(rules.intervals);  // holds pointers: finish() inside the scope of the polynomials
  double tau = kNever;
  if (log != nullptr) {
    log->count = 2;
    ppPositionInto(in, &log->polys[0]);
    ppApproachInto(in, &log->polys[1]);
    if (!solve.add(log->polys[1]) || !solve.add(log->polys[0])) return false;
    tau = solve.finish();
  } else {
    const Polynomial approach = ppApproach(in);
    if (!solve.add(approach)) return false;
    const Polynomial position = ppPosition(in);
    if (!solve.add(position)) return false;
    tau = solve.finish();
  }
  return report(tau, hit, tau <= 1.0 ? ppContactVector(in, tau) : Vec2::Zero());
}

bool detectPE(const PEInput& in, Contact* hit, PairPolynomials* log, const DetectionRules& rules) {
  StagedSolve solve(rules.intervals);  // holds pointers: finish() inside the scope of the polynomials
  const QuinticForm form = rules.quintic;
  double tau = kNever;
  if (log != nullptr) {  // all of them, whatever the outcome
    const PEProducts k(in);
    log->count = 4;
    peDistanceInto(k, in.rv + in.re, &log->polys[0]);
    peAlphaAboveZeroInto(k, &log->polys[1]);
    peAlphaBelowOneInto(in, &log->polys[2]);
    peApproachInto(k, form, &log->polys[3]);
    if (!solve.add(log->polys[1]) || !solve.add(log->polys[2]) || !solve.add(log->polys[0]) ||
        !solve.add(log->polys[3]))
      return false;
    tau = solve.finish();
  } else {
    if (sweptBoxesApart(in)) return false;
    const PEProducts k(in);
    Polynomial aboveZero;
    peAlphaAboveZeroInto(k, &aboveZero);
    if (!solve.add(aboveZero)) return false;
    const Polynomial belowOne = peAlphaBelowOne(in);
    if (!solve.add(belowOne)) return false;
    Polynomial distance;
    peDistanceInto(k, in.rv + in.re, &distance);
    if (!solve.add(distance)) return false;
    Polynomial approach;
    peApproachInto(k, form, &approach);
    if (!solve.add(approach)) return false;
    tau = solve.finish();
  }
  return report(tau, hit, tau <= 1.0 ? peContactVector(in, tau) : Vec2::Zero());
}

bool detectPH(const PHInput& in, Contact* hit, PairPolynomials* log, const DetectionRules& rules) {
  StagedSolve solve(rules.intervals);  // holds pointers: finish() inside the scope of the polynomials
  double tau = kNever;
  if (log != nullptr) {
    log->count = 2;
    phDistanceInto(in, &log->polys[0]);
    phApproachInto(in, &log->polys[1]);
    if (!solve.add(log->polys[1]) || !solve.add(log->polys[0])) return false;
    tau = solve.finish();
  } else {
    const Polynomial approach = phApproach(in);
    if (!solve.add(approach)) return false;
    const Polynomial distance = phDistance(in);
    if (!solve.add(distance)) return false;
    tau = solve.finish();
  }
  return report(tau, hit, tau <= 1.0 ? phContactVector(in, tau) : Vec2::Zero());
}

}  // namespace fosssim::math
