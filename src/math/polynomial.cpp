#include "fosssim/math/polynomial.h"

#include <cfloat>
#include <cmath>

namespace fosssim::math {

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

}  // namespace fosssim::math
