// A force that times the force it wraps: the profile puts one around each of a scene's forces to
// split the integrator's time into force evaluation, Jacobians and the solve. The clock's own
// cost (calibrated once) is taken off every call, since forces such as gravity cost less than a
// clock read.
#pragma once

#include "fosssim/core/force.h"

#include <memory>

namespace fosssim::study {

struct ForceTime {
  double gradient = 0;   ///< seconds in addGradient (and energy: the runner's checks are not timed)
  double jacobian = 0;   ///< seconds in addJacobianX and addJacobianV
  long calls = 0;        ///< addGradient calls
  long jacobianCalls = 0; ///< addJacobianX and addJacobianV calls
};

class TimedForce final : public Force {
 public:
  TimedForce(std::unique_ptr<Force> inner, ForceTime* into) : inner_(std::move(inner)), into_(into) {}
  const char* keyword() const override { return inner_->keyword(); }
  double energy(const Scene& scene, const VecX& x, const VecX& v) const override {
    return inner_->energy(scene, x, v);
  }
  /// The caller's context goes through to the wrapped force: the penalty force searches its
  /// near pairs with the simulator's options and storage, exactly as it would unwrapped.
  double energyWith(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context) const override {
    return inner_->energyWith(scene, x, v, context);
  }
  void addGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE) const override;
  void addGradientWith(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE,
                       ForceContext& context) const override;
  void addJacobianX(const Scene& scene, const VecX& x, const VecX& v, Triplets& out) const override;
  void addJacobianV(const Scene& scene, const VecX& x, const VecX& v, Triplets& out) const override;
  bool hasJacobians() const override { return inner_->hasJacobians(); }
  bool hasPotential() const override { return inner_->hasPotential(); }
  bool mayAddEnergy() const override { return inner_->mayAddEnergy(); }
  double stiffness() const override { return inner_->stiffness(); }

 private:
  std::unique_ptr<Force> inner_;
  ForceTime* into_;
};

/// Seconds one pair of clock reads costs on this machine (the least of many tries).
double clockOverhead();

}  // namespace fosssim::study
