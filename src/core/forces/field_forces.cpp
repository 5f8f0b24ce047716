// Forces that act on every particle alike: simple gravity, a constant force, drag damping.
// Their Jacobians with respect to x vanish; drag's Jacobian with respect to v is b I.
#include "fosssim/core/forces.h"

namespace fosssim {

double SimpleGravityForce::energy(const Scene& scene, const VecX& x, const VecX&) const {
  double e = 0;
  for (int i = 0; i < scene.numParticles(); ++i) e -= scene.massOf(i) * g_.dot(at(x, i));
  return e;
}

void SimpleGravityForce::addGradient(const Scene& scene, const VecX&, const VecX&, VecX& gradE) const {
  for (int i = 0; i < scene.numParticles(); ++i) at(gradE, i) -= scene.massOf(i) * g_;
}

double ConstantForce::energy(const Scene& scene, const VecX& x, const VecX&) const {
  double e = 0;
  for (int i = 0; i < scene.numParticles(); ++i) e -= f_.dot(at(x, i));
  return e;
}

void ConstantForce::addGradient(const Scene& scene, const VecX&, const VecX&, VecX& gradE) const {
  for (int i = 0; i < scene.numParticles(); ++i) at(gradE, i) -= f_;
}

void DragDampingForce::addGradient(const Scene&, const VecX&, const VecX& v, VecX& gradE) const {
  gradE += b_ * v;
}

void DragDampingForce::addJacobianV(const Scene&, const VecX&, const VecX& v, Triplets& out) const {
  for (Eigen::Index r = 0; r < v.size(); ++r) out.emplace_back(r, r, b_);
}

}  // namespace fosssim
