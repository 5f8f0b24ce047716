// Helpers of the ContactProjector tests: bodies from a random zone, their velocities, a source of
// rows that keeps them and lets no budget-ended solve be rescued.
#pragma once

#include "fosssim/math/contact_projector.h"

#include <vector>

#include "random_zones.h"

namespace fosssim::math::testing {

inline void addBodies(ContactProjector& cp, const Zone& z) {
  cp.reset(static_cast<int>(z.v.size()));
  for (size_t b = 0; b < z.v.size(); ++b) cp.addBody(static_cast<int>(b), z.invMass[b], z.v[b]);
}
inline std::vector<Vec2> velocities(const ContactProjector& cp, size_t bodies) {
  std::vector<Vec2> v;
  for (size_t b = 0; b < bodies; ++b) v.push_back(cp.velocity(static_cast<int>(b)));
  return v;
}

/// Rows kept as they are, and no exact rescue at a budget's end (ContactProjector::solveCluster):
/// for tests of what a budget-ended Gauss-Seidel solve leaves, whatever the cluster's size.
class NoRescue final : public ContactProjector::RowSource {
 public:
  bool rowNow(int, ConstraintRow&) override { return false; }
  bool mayRescue(const int*, int) override { return false; }
};

}  // namespace fosssim::math::testing
