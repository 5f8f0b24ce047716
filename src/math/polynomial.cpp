#include "fosssim/math/polynomial.h"

#include <cassert>
#include <cfloat>
#include <cmath>

namespace fosssim::math {

Polynomial Polynomial::fromHighestFirst(const double* coeffs, int count) {
  Polynomial p;
  int first = 0;
  while (first < count && coeffs[first] == 0.0) ++first;  // exact zeros only, as the reference
  const int n = count - first;
  assert(n <= kMaxCoeffs && "Polynomial: more than kMaxCoeffs significant coefficients");
  p.size = n < kMaxCoeffs ? n : kMaxCoeffs;
  for (int i = 0; i < p.size; ++i) p.c[i] = coeffs[first + i];
  return p;
}

Polynomial Polynomial::fromHighestFirst(std::initializer_list<double> coeffs) {
  return fromHighestFirst(coeffs.begin(), static_cast<int>(coeffs.size()));
}

double Polynomial::operator()(double t) const {
  double v = 0.0;
  for (int i = 0; i < size; ++i) v = v * t + c[i];
  return v;
}

void Polynomial::evaluate(double t, double* value, double* slope) const {
  // Horner on p and, interleaved, on p' (the derivative of the running Horner value).
  double v = 0.0;
  double d = 0.0;
  for (int i = 0; i < size; ++i) {
    d = d * t + v;
    v = v * t + c[i];
  }
  *value = v;
  *slope = d;
}

double Polynomial::evaluateWithErrorBound(double t, double* errorBound) const {
  const double at = std::fabs(t);
  double v = 0.0;
  double s = 0.0;  // sum |c_k| |t|^k, by Horner on absolute values
  for (int i = 0; i < size; ++i) {
    v = v * t + c[i];
    s = s * at + std::fabs(c[i]);
  }
  *errorBound = kHornerErrorFactor * DBL_EPSILON * s;
  return v;
}

Polynomial Polynomial::derivative() const {
  Polynomial d;
  if (size <= 1) return d;
  d.size = size - 1;
  const int n = size - 1;  // degree
  for (int i = 0; i < d.size; ++i) d.c[i] = c[i] * static_cast<double>(n - i);
  return d;
}

int Polynomial::signJustAfterZero() const {
  for (int i = size - 1; i >= 0; --i) {
    if (c[i] > 0.0) return 1;
    if (c[i] < 0.0) return -1;
  }
  return 0;
}

}  // namespace fosssim::math
