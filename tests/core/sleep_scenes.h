// Scenes of the sleeping tests (sleep_test.cpp, sleep_wake_test.cpp): disks on a floor under
// gravity, and a pair of them tied by a spring (an island).
#pragma once

#include "contact_physics.h"

#include "fosssim/core/forces.h"

#include <string>
#include <utility>
#include <vector>

namespace fosssim::testing {

inline constexpr double kG = 9.81;
inline constexpr double kR = 0.1;  // every disk's radius

/// Disks of radius kR on the floor y = 0 under gravity (symplectic Euler, dt 0.01), each at
/// (x, kR) with horizontal velocity vx. COR 0 by default (resting contact does not bounce at any
/// COR below 1: resting_contact_test.cpp).
inline TestScene floorScene(const std::string& type, const std::vector<std::pair<double, double>>& disks,
                            double cor = 0.0) {
  TestScene s = contactScene(type, cor);
  addFloorAndGravity(s, kG);
  for (const auto& [x, vx] : disks) addBody(s, 1.0, Vec2(x, kR), Vec2(vx, 0), kR);
  return s;
}

/// An island: disks 0 and 1 on the floor at x = 0 and 0.5 (disk 1 sliding at vx1), tied by a
/// spring of stiffness k at its rest length; then the disks `more` (x, vx), as floorScene's.
inline TestScene springPair(const std::string& type, const std::vector<std::pair<double, double>>& more = {},
                     double k = 10.0, double vx1 = 0.0) {
  std::vector<std::pair<double, double>> disks = {{0.0, 0.0}, {0.5, vx1}};
  disks.insert(disks.end(), more.begin(), more.end());
  TestScene s = floorScene(type, disks);
  s.scene.forces.push_back(std::make_unique<SpringForce>(0, 1, k, 0.5, 0.0));
  return s;
}

}  // namespace fosssim::testing
