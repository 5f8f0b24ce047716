// The force interface. Forces follow the reference's convention of "gradient of the potential":
// each adds dE/dx = -F to a gradient vector, also forces that have no potential (damping, vortex),
// so that F = -sum of gradients. Jacobians are likewise of -F: dE2/dx2 (the Hessian) and -dF/dv.
#pragma once

#include "fosssim/core/types.h"

#include <memory>
#include <utility>
#include <vector>

namespace fosssim {

struct Scene;
struct PenaltyScratch;

/// What evaluating forces may use besides the scene and the state: how near pairs are searched
/// (the same choices as HandlerOptions::allPairs and threads; the results are identical for
/// every choice) and storage reused from call to call. A Simulator owns one and passes it to its
/// integrator, so simulators share nothing and may step on different threads. A default context
/// searches with the broad phase on the calling thread.
class ForceContext {
 public:
  explicit ForceContext(bool allPairs = false, int threads = 1);
  ~ForceContext();
  ForceContext(ForceContext&&) noexcept;
  ForceContext& operator=(ForceContext&&) noexcept;
  ForceContext(const ForceContext&) = delete;
  ForceContext& operator=(const ForceContext&) = delete;

  bool allPairs() const { return allPairs_; }
  int threads() const { return threads_; }
  /// The penalty force's near-pair search and lists (src/core/forces/penalty_scratch.h),
  /// created at first use.
  PenaltyScratch& penaltyScratch();

  /// Particles whose force this evaluation nobody reads (size N, 1 for such a particle), or
  /// null: all are read. A Simulator sets it around its integrator's step to the particles
  /// asleep at the step's start, which the step puts back where they rest whatever was
  /// predicted, and to the fixed particles, whose force an explicit step zeroes. A force may then
  /// leave out what acts on those particles only (the penalty force: pairs whose particles all
  /// rest); every other particle's force stays bit for bit. The implicit integrators hold such
  /// particles where they are, as fixed ones, and leave them out of their linear system
  /// (src/core/integrators/implicit_system.h).
  void setResting(const std::vector<char>* resting) { resting_ = resting; }
  const std::vector<char>* resting() const { return resting_; }

 private:
  bool allPairs_;  ///< every pair is a near-pair candidate, without the broad phase (HandlerOptions::allPairs)
  int threads_;    ///< threads for the pair search and per-particle passes (HandlerOptions::threads; 1: the caller's)
  /// See setResting: per particle (size N), 1 for a particle whose force nobody reads; null: none.
  const std::vector<char>* resting_ = nullptr;
  std::unique_ptr<PenaltyScratch> penalty_;  ///< see penaltyScratch(); null until first use
};

class Force {
 public:
  virtual ~Force() = default;

  /// The XML element that creates this force (for messages and reports).
  virtual const char* keyword() const = 0;

  /// Potential energy at (x, v); 0 for forces that have none (see hasPotential()).
  virtual double energy(const Scene& scene, const VecX& x, const VecX& v) const;

  /// Adds -F(x, v) to gradE (size 2N).
  virtual void addGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE) const = 0;

  /// energy() and addGradient() with the caller's context. Forces that search for near pairs
  /// (the penalty force) override these and use the context's options and storage; for every
  /// other force they are energy() and addGradient(). The scene's sums (accumulateGradient,
  /// potentialEnergy) and the integrators call these.
  virtual double energyWith(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context) const;
  virtual void addGradientWith(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE,
                               ForceContext& context) const;

  /// Adds -dF/dx at (x, v) as 2N x 2N triplets (nothing when hasJacobians() is false).
  virtual void addJacobianX(const Scene& scene, const VecX& x, const VecX& v, Triplets& out) const;

  /// Adds -dF/dv at (x, v) as 2N x 2N triplets.
  virtual void addJacobianV(const Scene& scene, const VecX& x, const VecX& v, Triplets& out) const;

  /// False for forces whose Jacobians are not provided (vortex, penalty): implicit integrators
  /// then treat them explicitly, and the loader warns.
  virtual bool hasJacobians() const { return true; }

  /// True when energy() is a potential whose gradient is addGradient (conservative forces).
  virtual bool hasPotential() const { return false; }

  /// True when the force on each particle depends on that particle's own position and velocity
  /// alone (gravity, a constant force, drag), or acts between particles only at contact range
  /// (the penalty layer, for which a sleeper is an obstacle as it is for contacts): holding one
  /// particle still then changes no force on another particle at a distance, which is what lets
  /// a resting particle sleep alone (src/core/collision/sleepers.h). False for springs and pair
  /// forces, whose particles sleep only together (couples).
  virtual bool actsAlone() const { return false; }

  /// Appends the pairs of particles whose motion this force ties together at a distance (a
  /// spring's two ends, a gravitational pair): such particles sleep only together, as one island
  /// (src/core/collision/sleepers.h). Returns false for a force whose couplings it cannot list
  /// (then nothing sleeps); a force that actsAlone() lists none.
  virtual bool couples(std::vector<std::pair<int, int>>& pairs) const {
    (void)pairs;
    return actsAlone();
  }

  /// True when the part of the force that energy() does not account for can do positive work,
  /// so that the total mechanical energy may grow honestly (the energy watch then stays off).
  /// By default a force without a potential may; drag and spring damping with b >= 0 only remove
  /// energy and say so.
  virtual bool mayAddEnergy() const { return !hasPotential(); }

  /// The stiffness k of a spring-like force (spring, penalty), 0 for other forces. A spring-like
  /// force's energy() is k/2 (stretch)^2 >= 0; the energy watch relies on that (and names k in
  /// its advice on blow-ups).
  virtual double stiffness() const { return 0.0; }
};

}  // namespace fosssim
