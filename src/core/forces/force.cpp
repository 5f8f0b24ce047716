// Defaults of the Force interface: no potential, no Jacobian contributions.
#include "fosssim/core/force.h"

namespace fosssim {

double Force::energy(const Scene&, const VecX&, const VecX&) const { return 0.0; }
void Force::addJacobianX(const Scene&, const VecX&, const VecX&, Triplets&) const {}
void Force::addJacobianV(const Scene&, const VecX&, const VecX&, Triplets&) const {}

}  // namespace fosssim
