// Test helpers: polynomials from chosen roots.
#pragma once

#include <initializer_list>
#include <vector>

#include "fosssim/math/polynomial.h"

namespace fosssim::math::testing {

// s * prod (t - r_i) * prod ((t - c_j)^2 + d_j^2), expanded in double precision.
inline Polynomial expand(double s, const std::vector<double>& roots,
                         const std::vector<std::pair<double, double>>& complexPairs = {}) {
  double c[Polynomial::kMaxCoeffs + 2] = {s};
  int n = 1;
  auto multiply = [&](const double* f, int m) {  // c *= f (m coefficients, highest first)
    double out[Polynomial::kMaxCoeffs + 2] = {};
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) out[i + j] += c[i] * f[j];
    n += m - 1;
    for (int i = 0; i < n; ++i) c[i] = out[i];
  };
  for (double r : roots) {
    const double f[2] = {1.0, -r};
    multiply(f, 2);
  }
  for (const auto& [cc, d] : complexPairs) {
    const double f[3] = {1.0, -2.0 * cc, cc * cc + d * d};
    multiply(f, 3);
  }
  return Polynomial::fromHighestFirst(c, n);
}

inline Polynomial fromRoots(double s, std::initializer_list<double> roots) {
  return expand(s, std::vector<double>(roots));
}

}  // namespace fosssim::math::testing
