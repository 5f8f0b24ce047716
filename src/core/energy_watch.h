// The energy watch: part of a step's verify phase. It stops a run whose total mechanical energy
// grows by orders of magnitude although nothing outside the scene does work on it: a stiff
// penalty contact or spring integrated with too large a time step (a ball leaving a k = 1e200
// contact at 5e195 m/s) would otherwise run on with finite but meaningless numbers.
//
// E = kinetic energy + the potentials of the forces that define one (Force::energy). Forces are
// of two sorts here: spring-like ones (Force::stiffness() > 0: springs, the collision penalty),
// whose potential k/2 (stretch)^2 is >= 0 and 0 at rest, and fields (gravity, constant forces,
// gravitation), whose potential is unbounded below and, for gravity, depends on the origin.
// The criterion:
//
//   gain(t) = KE(t) + sum_fields U_f(t) - E(0)   >   kBlowUpGrowth * scale(t)
//
//   scale(t) = KE(0) + sum_springlike U_f(0)               what the scene starts with
//            + max_{s<=t} sum_fields max(0, U_f(0) - U_f(s))  field potential released so far
//            + n(t) * min(sum_i |F_i dt|^2 / 2m_i, extent * sum_i |F_i|)   first-order drift
//            + kRoundingShare * (KE(0) + sum_f |U_f(0)|)      what rounding the sums can produce
//
// with F the fields' forces at the start and n(t) the steps taken. Why. In a conservative run
// KE(s) = KE(0) + sum_f (U_f(0) - U_f(s)): kinetic energy is bounded by what the scene starts
// with plus what the potentials release. A spring-like potential can release at most its start
// value; a field's release is followed step by step and never forgotten (a ball at the top of
// its bounce has released nothing right now). First-order steps add about one step's kinetic
// energy of the fields per step, whatever the motion: explicit Euler's fall from rest gains
// m g^2 dt^2 / 2 per step before it has released anything, and an elastic ball bouncing under
// gravity with continuous-time or hybrid handling gains about as much per step for ever (its
// energy grows linearly; after 3000 s it bounces 150 times its first height). That drift is
// linear in the number of steps; a blow-up grows exponentially and outruns it within a few
// dozen steps. Capped per step by the work the fields could do across the scene (extent =
// diagonal of the box around every disk at the start). The largest kinetic energy seen so far
// is deliberately *not* in the scale: in a blow-up the kinetic energy is the gain, and the ratio
// could never exceed 1.
// Scale-free: every term is an energy of the scene itself, so scaling mass, length and time
// scales gain and scale alike. Origin-free: only differences of field potentials enter (the
// rounding term uses |U_f(0)|, which is what the rounding of those sums depends on).
// Cheap: spring-like potentials are left out of E(t) after the start (the penalty force's would
// cost a near-pair search per step, as much as the force itself). They are >= 0, so the gain
// computed without them is a lower bound of the true gain: never a false alarm the full sum
// would not give, and a blow-up's energy passes through kinetic energy every half oscillation.
//
// Where it is off (E may then grow honestly): a force whose non-potential part can do positive
// work (Force::mayAddEnergy: the vortex force; drag and spring damping only remove energy), and a
// fixed particle with a velocity (it moves on at that velocity, a driven body doing external
// work through springs and contacts). Collision responses with COR in [0, 1] add no energy.
#pragma once

#include "fosssim/core/scene.h"
#include "fosssim/core/state.h"
#include "fosssim/core/status.h"

#include <string>
#include <vector>

namespace fosssim {

class EnergyWatch {
 public:
  /// Growth of E beyond its start, in multiples of the scale, that is called a blow-up: three
  /// orders of magnitude. Measured with this criterion: the honest scenes stay below 37 (the
  /// worst, the course's deliberately unstable explicit-Euler springs, conformance
  /// t1m2/SpringTests/test02explicit, over its 30 s; assets/ below 1 with and without --compat;
  /// the benchmark scenes at N = 1000 below 13, chains the most), a margin of 27. The tracker's
  /// spring pair in a stiff penalty layer (symplectic Euler, k = 1e6, on its way to 3200 m/s)
  /// is stopped at 8200 times, in the step that throws it from 500 to 3200 m/s; at 1e4 it would
  /// have run on. The study's explicit Euler on a spring (x7548 in 5 periods, docs/study.md) is
  /// a blow-up by this mark; the study turns the watch off (study/run.cpp).
  static constexpr double kBlowUpGrowth = 1e3;
  /// Relative rounding of an energy summed over many terms (1e-16 per term, up to 1e6 terms).
  static constexpr double kRoundingShare = 1e-10;

  explicit EnergyWatch(bool enabled = true) : wanted_(enabled) {}

  /// Checks the end state of one step, `start` being the state it began from. Takes its
  /// baseline at the first step of a run (a start state at step 0, or the first call), and fails
  /// there, naming the particle or force, if the start's energy is not finite (a speed of 1e160
  /// m/s: m |v|^2 / 2 overflows, and without a baseline nothing here could see the run go wrong).
  /// Fails with a message naming the fastest particle, the force whose energy changed most in
  /// this step and what to change; the caller adds step and time.
  /// `forces`: the caller's context for the forces' energies (a Simulator passes its own).
  Status check(const Scene& scene, const State& start, const State& end, ForceContext& forces);
  Status check(const Scene& scene, const State& start, const State& end) {
    ForceContext forces;
    return check(scene, start, end, forces);
  }

  /// False when off by choice or because the scene may gain energy honestly (see above).
  bool active() const { return active_; }
  /// The largest gain / scale seen in this run (0 when inactive): how close it came.
  double largestGrowth() const { return largestGrowth_; }

 private:
  /// Takes the baseline; fails when the start's energy is not finite (see check).
  Status begin(const Scene& scene, const State& start, ForceContext& forces);
  /// Per-force potentials (0 for forces without one) at x, v.
  void potentials(const Scene& scene, const VecX& x, const VecX& v, ForceContext& forces,
                  std::vector<double>& out) const;
  std::string explain(const Scene& scene, const State& start, const State& end, ForceContext& forces, double gain,
                      double scale) const;

  bool wanted_;            ///< the caller wants the watch (the constructor's `enabled`)
  bool started_ = false;   ///< a baseline was taken (begin ran)
  bool active_ = false;    ///< watching this run: wanted, the scene cannot gain energy honestly and E(0) is finite
  double energy0_ = 0;     ///< E(0)
  double baseScale_ = 0;   ///< the scale's terms fixed at the start
  double released_ = 0;    ///< the largest potential energy released so far
  double driftPerStep_ = 0;  ///< the first-order drift the fields may cause per step
  long steps_ = 0;         ///< steps checked since the baseline
  double largestGrowth_ = 0;  ///< the largest gain / scale seen in this run (largestGrowth())
  /// A force whose potential is followed step by step, and its value at the start.
  struct Tracked {
    int force;
    double start;
  };
  std::vector<Tracked> tracked_;  ///< the forces with a potential that are not spring-like
};

/// How run-time messages name the force scene.forces[index]: its keyword and its place among the
/// forces of that keyword, counted from 1 ("'springforce' #2": the second <springforce> of the
/// file, as forces of one kind keep the file's order). The energy watch and the step's
/// non-finite check both use it, so that their messages about one scene name the same element.
std::string forceOrdinal(const Scene& scene, int index);

}  // namespace fosssim
