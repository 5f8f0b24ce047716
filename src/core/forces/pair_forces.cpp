// Forces between two given particles: Newtonian gravitation and the vortex force.
//
// Gravitation, with r = x_j - x_i, l = |r|, n = r/l:
//   E = -G m_i m_j / l,  dE/dx_j = G m_i m_j r / l^3 = -dE/dx_i
//   d2E/dx_j2 = G m_i m_j (I - 3 n n^T) / l^3   [d(r/l^3) = (I/l^3 - 3 r r^T/l^5) dr]
#include "fosssim/core/forces.h"

namespace fosssim {

double GravitationalForce::energy(const Scene& scene, const VecX& x, const VecX&) const {
  const double l = (at(x, j_) - at(x, i_)).norm();
  return -G_ * scene.massOf(i_) * scene.massOf(j_) / l;
}

void GravitationalForce::addGradient(const Scene& scene, const VecX& x, const VecX&, VecX& gradE) const {
  Vec2 n = at(x, j_) - at(x, i_);
  const double l = n.norm();
  n = divide(n, l);
  n *= G_ * scene.massOf(i_) * scene.massOf(j_) / (l * l);
  at(gradE, i_) -= n;
  at(gradE, j_) += n;
}

void GravitationalForce::addJacobianX(const Scene& scene, const VecX& x, const VecX&, Triplets& out) const {
  const Vec2 r = at(x, j_) - at(x, i_);
  const double l = r.norm();
  const Vec2 n = divide(r, l);
  const Mat2 K = G_ * scene.massOf(i_) * scene.massOf(j_) / (l * l * l) *
                 (Mat2::Identity() - 3.0 * n * n.transpose());
  addBlock(out, i_, i_, K);
  addBlock(out, j_, j_, K);
  addBlock(out, i_, j_, -K);
  addBlock(out, j_, i_, -K);
}

void VortexForce::addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const {
  const Vec2 r = at(x, j_) - at(x, i_);
  const double l = r.norm();
  const Vec2 rhat = divide(r, l);
  const Vec2 perp(-rhat.y(), rhat.x());
  const Vec2 forceOnJ = kvc_ * divide(kbs_ * perp - (at(v, j_) - at(v, i_)), l * l);
  at(gradE, i_) += forceOnJ;
  at(gradE, j_) -= forceOnJ;
}

}  // namespace fosssim
