#include "timed_force.h"

#include <algorithm>
#include <chrono>

namespace fosssim::study {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point begin) {
  const double t = std::chrono::duration<double>(Clock::now() - begin).count() - clockOverhead();
  return std::max(0.0, t);
}

}  // namespace

double clockOverhead() {
  static const double overhead = [] {
    double best = 1.0;
    for (int k = 0; k < 2000; ++k) {
      const Clock::time_point a = Clock::now();
      best = std::min(best, std::chrono::duration<double>(Clock::now() - a).count());
    }
    return best;
  }();
  return overhead;
}

void TimedForce::addGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE) const {
  const Clock::time_point begin = Clock::now();
  inner_->addGradient(scene, x, v, gradE);
  into_->gradient += since(begin);
  ++into_->calls;
}

void TimedForce::addGradientWith(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE,
                                 ForceContext& context) const {
  const Clock::time_point begin = Clock::now();
  inner_->addGradientWith(scene, x, v, gradE, context);
  into_->gradient += since(begin);
  ++into_->calls;
}

void TimedForce::addJacobianX(const Scene& scene, const VecX& x, const VecX& v, Triplets& out) const {
  const Clock::time_point begin = Clock::now();
  inner_->addJacobianX(scene, x, v, out);
  into_->jacobian += since(begin);
  ++into_->jacobianCalls;
}

void TimedForce::addJacobianV(const Scene& scene, const VecX& x, const VecX& v, Triplets& out) const {
  const Clock::time_point begin = Clock::now();
  inner_->addJacobianV(scene, x, v, out);
  into_->jacobian += since(begin);
  ++into_->jacobianCalls;
}

}  // namespace fosssim::study
