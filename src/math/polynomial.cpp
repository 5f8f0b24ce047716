#include "fosssim/math/polynomial.h"

namespace fosssim::math {

Polynomial Polynomial::derivative() const {
  Polynomial d;
  if (size <= 1) return d;
  d.size = size - 1;
  const int n = size - 1;  // degree
  for (int i = 0; i < d.size; ++i) d.c[i] = c[i] * static_cast<double>(n - i);
  return d;
}

}  // namespace fosssim::math
