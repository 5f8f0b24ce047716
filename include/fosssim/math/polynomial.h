// Fixed-size real polynomial of degree <= 5, the currency of continuous collision detection.
//
// Coefficients are stored highest power first because that is how the reference simulator
// writes them into trajectory files; keeping the same order avoids a reversal at every log.
// Degree 5 is enough for every polynomial CCD builds (the particle-edge approach quintic).
#pragma once

#include <array>
#include <cfloat>
#include <cmath>
#include <initializer_list>

#include "fosssim/math/contract.h"

namespace fosssim::math {

struct Polynomial {
  static constexpr int kMaxCoeffs = 6;
  static constexpr int kMaxDegree = kMaxCoeffs - 1;

  /// c[0] multiplies t^(size-1), c[size-1] is the constant term. Entries past size are unused
  /// (and kept zero by the builders, so equal polynomials compare equal element-wise).
  std::array<double, kMaxCoeffs> c{};
  /// Number of coefficients; 0 is the zero polynomial. After fromHighestFirst, c[0] != 0.
  int size = 0;

  /// Builds from coefficients highest power first, dropping EXACT zero leading coefficients
  /// (the reference does this: a static pair gives shorter lists, all zeros gives size 0).
  /// -0.0 counts as zero. More than kMaxCoeffs significant coefficients is a programming error
  /// (FOSSSIM_ASSERT, in every build: no coefficient is ever dropped silently).
  static Polynomial fromHighestFirst(std::initializer_list<double> coeffs);
  static Polynomial fromHighestFirst(const double* coeffs, int count);
  /// The same, in place (no temporary to copy: the CCD builders write straight into a log).
  /// leadingCutoff > 0 also drops leading coefficients with |c| < leadingCutoff (the CCD
  /// builders pass kNegligibleLeadingCoefficient, see ccd.h); inner coefficients are kept.
  void assign(const double* coeffs, int count, double leadingCutoff = 0.0);
  void assign(std::initializer_list<double> coeffs, double leadingCutoff = 0.0) {
    assign(coeffs.begin(), static_cast<int>(coeffs.size()), leadingCutoff);
  }

  /// Value at t by Horner's rule. The zero polynomial evaluates to 0.
  double operator()(double t) const;

  /// Value and first derivative at t in one Horner pass (the Newton iteration's inner loop).
  void evaluate(double t, double* value, double* slope) const;

  /// Value at t together with a bound on the rounding error of that Horner evaluation:
  /// |computed - exact| <= *errorBound (for the stored coefficients), see kHornerErrorFactor.
  double evaluateWithErrorBound(double t, double* errorBound) const;

  /// size - 1; the zero polynomial has degree -1.
  int degree() const { return size - 1; }

  /// Coefficient of t^k (0 when k > degree).
  double coefficientOfPower(int k) const { return (k >= 0 && k < size) ? c[size - 1 - k] : 0.0; }

  /// p'. The leading coefficient deg*c[0] is nonzero whenever c[0] is, so no trimming is needed.
  Polynomial derivative() const;

  /// Sign (+1, -1, 0) of p on (0, eps) for small eps: the sign of the lowest-order nonzero
  /// coefficient (Taylor at 0 is read off the coefficients exactly). 0 for the zero polynomial.
  int signJustAfterZero() const;
};

/// Multiplier of eps * sum|c_k||t|^k bounding the rounding error of Horner's rule.
/// Classic bound (Higham, Accuracy and Stability, 5.1): |error| <= gamma_{2n} * sum|c_k||t|^k
/// with gamma_k = k*u/(1-k*u), u = eps/2. For n <= 5 that is about 5*eps; 8 leaves margin for
/// the error of computing the bound itself. Values within this bound are "numerically zero".
constexpr double kHornerErrorFactor = 8.0;

// The small members are defined here, inline: they run several times in every CCD query
// and a call across translation units cost more than their bodies.

inline void Polynomial::assign(const double* coeffs, int count, double leadingCutoff) {
  int first = 0;
  while (first < count && (coeffs[first] == 0.0 || std::fabs(coeffs[first]) < leadingCutoff)) ++first;
  const int n = count - first;
  FOSSSIM_ASSERT(n <= kMaxCoeffs);  // no coefficient is ever dropped
  size = n;
  for (int i = 0; i < kMaxCoeffs; ++i) c[i] = i < size ? coeffs[first + i] : 0.0;
}

inline Polynomial Polynomial::fromHighestFirst(const double* coeffs, int count) {
  Polynomial p;
  p.assign(coeffs, count);
  return p;
}

inline Polynomial Polynomial::fromHighestFirst(std::initializer_list<double> coeffs) {
  return fromHighestFirst(coeffs.begin(), static_cast<int>(coeffs.size()));
}

inline double Polynomial::operator()(double t) const {
  double v = 0.0;
  for (int i = 0; i < size; ++i) v = v * t + c[i];
  return v;
}

inline void Polynomial::evaluate(double t, double* value, double* slope) const {
  /// Horner on p and, interleaved, on p' (the derivative of the running Horner value).
  double v = 0.0;
  double d = 0.0;
  for (int i = 0; i < size; ++i) {
    d = d * t + v;
    v = v * t + c[i];
  }
  *value = v;
  *slope = d;
}

inline double Polynomial::evaluateWithErrorBound(double t, double* errorBound) const {
  const double at = t < 0.0 ? -t : t;
  double v = 0.0;
  double s = 0.0;  // sum |c_k| |t|^k, by Horner on absolute values
  for (int i = 0; i < size; ++i) {
    v = v * t + c[i];
    s = s * at + (c[i] < 0.0 ? -c[i] : c[i]);
  }
  *errorBound = kHornerErrorFactor * DBL_EPSILON * s;
  return v;
}

inline int Polynomial::signJustAfterZero() const {
  for (int i = size - 1; i >= 0; --i)
    if (c[i] != 0.0) return c[i] > 0.0 ? 1 : -1;
  return 0;
}

}  // namespace fosssim::math
