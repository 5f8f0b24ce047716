// Internal header: the default mode's failsafe, impact zones resolved at an instant of the step.
//
// When impulses cannot settle a cluster of contacts (a particle took its quota of impulse
// events in this step: a resting pile, a ball wedged in a corner), the cluster becomes a zone at
// the current event time T: the particles of the contact and, transitively, every particle that
// could touch one of them before the step ends. The zone's velocities are then replaced by the
// closest ones, in the kinetic-energy norm, under which no contact of the zone approaches
// (math::ZoneProjector, Harmon, Vouga, Tamstorf and Grinspun 2008): contacts stop closing,
// tangential motion is kept, and kinetic energy can only fall. Later contacts of a zone's
// particles in the same step join the zone and it is solved again at their time.
//
// Last resort, after kMaxZoneProjections solves of one zone in a step (or at once with
// failsafe="rigid", or when the projection does not converge): the zone moves rigidly, with its
// centre-of-mass velocity and the angular velocity of its momentum (the M-orthogonal projection
// onto rigid motions, so again no energy is gained), or stops if it holds a fixed particle or
// touches a half-plane. Contacts inside a rigid zone are then exempt (the course's rule).
#pragma once

#include "pair_candidates.h"
#include "step_motion.h"

#include "fosssim/core/scene.h"
#include "fosssim/core/status.h"
#include "fosssim/core/step_stats.h"
#include "fosssim/math/zone_projection.h"

#include <vector>

namespace fosssim {

/// Solves of one zone in one step without new contacts since the last solve, before it moves
/// rigidly instead: a zone still meeting its own contacts after this many is a jam (a wedge, a
/// column being crushed) that a rigid motion settles for the rest of the step. Solves for new
/// contacts (newcomers landing on a pile) do not count: they are bounded by the pairs.
constexpr int kMaxZoneProjections = 8;
/// All solves of one zone in one step, new contacts or not: bounds the cost of a zone that keeps
/// meeting newcomers one at a time (each solve costs the whole zone).
constexpr int kMaxZoneSolves = 64;

/// The projection's tolerance, relative to the zone's largest speed: tighter than the solver's
/// default, because what it leaves closing deepens the zone's slowest contacts over the rest of
/// the step, and verification counts deepening beyond kDepthTolerance (1e-12) of the lengths.
/// Gauss-Seidel converges linearly, so this costs about 30% more sweeps than 1e-10.
constexpr double kZoneProjectionTolerance = 1e-13;

/// Closing speeds inside one zone up to this fraction of the zone's largest rate are left over
/// by its projection (kZoneProjectionTolerance times a row norm of at most sqrt(3)), so that a
/// solved zone is not solved again for them.
constexpr double kZoneClosingFraction = 2e-13;

/// Extra reach, as a fraction of a pair's radius sum, within which two zone neighbours count as
/// touching on top of the distance they could close in the rest of the step (absorbs rounding of
/// resting contacts, whose gaps are a few ulps of the radii).
constexpr double kTouchingSlack = 1e-6;

class ContactZones {
 public:
  /// No zones; storage for n particles.
  void reset(int n);

  /// Puts pair `key` (met at time T) and every particle that could touch its particles in the
  /// rest of the step (transitively) into one zone, whose contacts it records; returns the zone.
  int absorb(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, uint64_t key, double T);

  /// Solves zone `zone` at time T, growing it while its new velocities bring more pairs near:
  /// writes its particles' new rates into `motion`, their velocity changes into v (2N), and
  /// appends the particles whose rate changed to `changed` (perhaps more than once).
  void resolve(const Scene& scene, StepMotion& motion, PairCandidates& candidates, int zone, double T,
               double h, VecX& v, std::vector<int>& changed, StepStats& stats);

  /// The zone of particle p, or -1.
  int zoneOf(int p) const { return parent_.empty() || parent_[p] < 0 ? -1 : root(p); }
  bool isRigid(int zone) const { return rigid_[zone] != 0; }
  /// Adds the zones (count, particles, largest, rigid ones) to the statistics.
  void sizes(StepStats& stats) const;
  /// The largest rate (displacement per step) among the zone's particles after its last solve:
  /// the scale of what its projection leaves closing (math::kProjectionTolerance of it).
  double rateScale(int zone) const { return rateScale_[root(zone)]; }
  void setRigidOnly(bool rigid) { rigidOnly_ = rigid; }

 private:
  int root(int p) const {
    while (parent_[p] != p) p = parent_[p];
    return p;
  }
  int join(int p);              ///< adds movable particle p to the zones (alone), returns its root
  int unite(int a, int b);      ///< merges two zones, returns the new root
  void addContact(int zone, uint64_t key);
  int take(const Scene& scene, int p, int zone);  ///< movable p joins `zone` (or a new one)
  int grow(const Scene& scene, const StepMotion& motion, const PairCandidates& candidates, int zone, double T);
  size_t uniqueContacts(int zone);
  void solve(const Scene& scene, StepMotion& motion, int zone, double T, double h, VecX& v,
             std::vector<int>& changed, StepStats& stats);
  bool near(const Scene& scene, const StepMotion& motion, uint64_t key, double T) const;
  void project(const Scene& scene, const StepMotion& motion, int zone, double T, bool& converged);
  /// Appends the contact's row with its normal at position(p); returns the normal (zero: none).
  template <class Position>
  Vec2 addRow(const Scene& scene, uint64_t key, Position&& position);
  void moveRigidly(const Scene& scene, const StepMotion& motion, int zone, double T, double h);

  bool rigidOnly_ = false;
  std::vector<int> parent_;                ///< N: union-find parent, -1 when in no zone
  std::vector<std::vector<int>> members_;  ///< per root: its particles
  std::vector<std::vector<uint64_t>> contacts_;  ///< per root: its contacts' pair keys
  std::vector<int> projections_;           ///< per root: solves without new contacts in this step
  std::vector<int> solves_;                ///< per root: all solves in this step
  std::vector<size_t> solvedContacts_;     ///< per root: contacts at its last solve
  std::vector<char> rigid_;                ///< per root: moving rigidly for the rest of the step
  std::vector<double> rateScale_;          ///< per root: see rateScale()
  std::vector<int> roots_;                 ///< every particle that has been a root this step
  std::vector<int> queue_;
  std::vector<uint64_t> keys_;
  // Projection scratch: bodies are the zone's particles, then fixed particles its contacts touch.
  std::vector<int> slot_;                  ///< N: body index of a particle in the current solve, -1
  std::vector<int> bodies_;
  std::vector<double> inverseMass_;
  std::vector<Vec2> velocity_;
  std::vector<math::ConstraintRow> rows_;
  math::ZoneProjector projector_;
};

}  // namespace fosssim
