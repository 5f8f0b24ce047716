// Measured stability of a damped spring: u'' = -omega^2 u - 2 gamma u' (a unit mass on a spring of
// stiffness k = omega^2 with damping b = 2 gamma, along its own line). Unlike an undamped spring,
// where explicit Euler is never stable and the implicit methods always are, damping gives explicit
// and symplectic Euler real limits, which the study measures and compares with their closed forms.
//
// One step of either method is the linear map (u, v) -> A (u, v) with
//   explicit Euler:   A = [[1, h], [-w^2 h, 1 - 2 g h]]
//                     tr = 2 - 2 g h, det = 1 - 2 g h + w^2 h^2
//   symplectic Euler: A = [[1 - w^2 h^2, h (1 - 2 g h)], [-w^2 h, 1 - 2 g h]]
//                     tr = 2 - 2 g h - w^2 h^2, det = 1 - 2 g h
// Both eigenvalues lie inside the unit circle iff det < 1, 1 - tr + det > 0 and 1 + tr + det > 0
// (the Jury conditions of a real quadratic). Solved for h:
//   explicit Euler:   h < 2 g / w^2 (= b / k) when g <= w; h < 2 / (g + sqrt(g^2 - w^2)) when g > w
//                     (the third condition, 4 - 4 g h + w^2 h^2 > 0, binds first when overdamped)
//   symplectic Euler: h < 2 / (g + sqrt(g^2 + w^2)) = 2 (sqrt(g^2 + w^2) - g) / w^2
//                     (det < 1 and 1 - tr + det > 0 hold for every h > 0 below 1/g)
#pragma once

#include "fosssim/core/status.h"

#include <string>
#include <vector>

namespace fosssim::study {

/// The closed forms above; NaN for an integrator without a limit (or explicit Euler undamped).
double dampedStabilityLimit(const std::string& integrator, double omega, double gamma);

/// The probe's time steps: omega h on a geometric grid from 0.01 to 100, ratio 1.01 between
/// neighbours (the sweep's resolution).
std::vector<double> dampedGrid(double omega);

/// One probe: the spring released from a stretch of 1e-6 (of its rest length 1) and stepped by the
/// simulator. Its energy m v^2/2 + k u^2/2 is compared between the first and the last blocks of the
/// run (each block several periods long, so that their maxima see every phase): it grew iff the
/// state's largest eigenvalue has modulus above 1 (by more than 1 % over half the run: a neutral
/// mode, undamped symplectic Euler's, counts as stable). Stops early once the energy has grown
/// 1e5-fold (unstable) or decayed 1e12-fold (stable).
struct DampedProbe {
  bool stable = false;
  double growth = 0;  ///< log(energy of the last block / energy of the first) per step
  long steps = 0;
  std::string message;  ///< a failed step's message (counted unstable)
};
DampedProbe probeDamped(const std::string& integrator, double omega, double gamma, double dt, long steps);

/// The largest stable grid step, by bisection on the grid's index (stability holds below a limit
/// and fails above it, as the closed forms say). `index` is -1 when even the grid's smallest step
/// failed, and grid.size() - 1 with `capped` when its largest held.
struct DampedLimit {
  std::vector<double> grid;
  int index = -1;
  bool capped = false;
  int probes = 0;
  double largestStable() const;   ///< grid[index] (NaN if none)
  double smallestUnstable() const;  ///< grid[index + 1] (NaN if capped)
};
DampedLimit findDampedLimit(const std::string& integrator, double omega, double gamma, long steps);

}  // namespace fosssim::study
