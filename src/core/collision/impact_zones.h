// Internal header: rigid impact zones, the hybrid handler's failsafe.
//
// A zone is a set of particles that move as one rigid body for the rest of the step: the
// particles of every collision that impulses could not resolve, merged whenever two zones share
// a particle. A zone touched by a half-plane collision, or holding a fixed particle, cannot move
// at all. Zones only ever grow, so "the zone set changed" is detected as it happens: a particle
// joins, two zones merge, or a zone gains the immovable mark.
#pragma once

#include "continuous_detection.h"

#include <vector>

namespace fosssim {

class ImpactZones {
 public:
  /// Empties the zones and sizes the per-particle storage for n particles.
  void reset(int n);
  /// Adds a collision's particles as a zone (merging); returns true if the zone set changed.
  bool add(const Scene& scene, const Collision& c);
  /// Moves every zone rigidly: from `start` positions along the mean of the motion to the
  /// positions in x (translation of the centre of mass, rotation by the angular displacement
  /// L/I), writing the zone particles' new positions into x and appending those that changed (bit
  /// for bit) to `changed`. Immovable zones stay at `start`. Other particles untouched.
  void moveRigidly(const Scene& scene, const VecX& start, VecX& x, std::vector<int>& changed);
  /// The particles in some zone (ascending up to the last moveRigidly, then in joining order).
  const std::vector<int>& members() const { return members_; }
  /// Number of zones and the size of the largest.
  void sizes(int& zones, int& largest);
  /// The zone (its representative particle) holding particle p, or -1.
  int zoneOf(int p) const;

 private:
  int find(int p);
  bool unite(int a, int b);
  bool touch(int p);

  std::vector<int> parent_;      ///< N: union-find parent, -1 for particles in no zone
  std::vector<char> immovable_;  ///< N: per root, the zone holds a fixed particle or met a half-plane
  std::vector<int> members_;     ///< particles in some zone
  size_t sorted_ = 0;            ///< members_[0, sorted_) is ascending (moveRigidly sorts)
  std::vector<int> slot_;        ///< N: per root, index of its accumulator (scratch)
  struct Accumulator {           ///< per zone, sums for its rigid motion
    double mass = 0, inertia = 0, angular = 0;  ///< M, I about the centre, and L of the displacements (see the .cpp)
    /// Sums, then c and Dc: the start centre of mass and the mean displacement (see the .cpp).
    Vec2 centre = Vec2::Zero(), shift = Vec2::Zero();
    bool immovable = false;      ///< holds a fixed particle or met a half-plane: it stays at the start
    int root = -1;               ///< the zone's root particle
    double cos = 1, sin = 0;     ///< of the rotation angle
    Vec2 base = Vec2::Zero();    ///< centre + shift
  };
  std::vector<Accumulator> accumulators_;  ///< moveRigidly's scratch: one per zone, indexed by slot_[root]
  std::vector<int> memberZone_;  ///< scratch: per member (in members_ order), its accumulator
};

}  // namespace fosssim
