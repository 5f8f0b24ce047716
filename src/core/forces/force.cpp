// Defaults of the Force interface: no potential, no Jacobian contributions, no use of the
// context; the context's storage.
#include "fosssim/core/force.h"

#include "core/forces/penalty_scratch.h"

namespace fosssim {

double Force::energy(const Scene&, const VecX&, const VecX&) const { return 0.0; }
double Force::energyWith(const Scene& scene, const VecX& x, const VecX& v, ForceContext&) const {
  return energy(scene, x, v);
}
void Force::addGradientWith(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE, ForceContext&) const {
  addGradient(scene, x, v, gradE);
}
void Force::addJacobianX(const Scene&, const VecX&, const VecX&, Triplets&) const {}
void Force::addJacobianV(const Scene&, const VecX&, const VecX&, Triplets&) const {}


ForceContext::ForceContext(bool allPairs, int threads) : allPairs_(allPairs), threads_(threads) {}
ForceContext::~ForceContext() = default;
ForceContext::ForceContext(ForceContext&&) noexcept = default;
ForceContext& ForceContext::operator=(ForceContext&&) noexcept = default;

PenaltyScratch& ForceContext::penaltyScratch() {
  if (!penalty_) penalty_ = std::make_unique<PenaltyScratch>();
  return *penalty_;
}

}  // namespace fosssim
