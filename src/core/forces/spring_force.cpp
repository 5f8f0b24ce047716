// Damped spring along an edge.
//
// With r = x_j - x_i, l = |r|, n = r/l, P = I - n n^T (the projector orthogonal to n):
//   elastic:  E = k/2 (l - l0)^2,  dE/dx_j = k (l - l0) n = -dE/dx_i
//             d2E/dx_j2 = k (n n^T + (l - l0)/l P)  [since dn/dx_j = P/l]
//   damping:  "gradient" g_j = b (n . dv) n with dv = v_j - v_i, g_i = -g_j
//             dg_j/dx_j = b/l (n dv^T + (n . dv) I) P   [product rule on (n . dv) n]
//             dg_j/dv_j = b n n^T
// Each 2x2 block K enters the 4x4 pattern [[K, -K], [-K, K]] over (i, j).
#include "fosssim/core/forces.h"

namespace fosssim {
namespace {

void addPairBlocks(Triplets& out, int i, int j, const Mat2& K) {
  addBlock(out, i, i, K);
  addBlock(out, j, j, K);
  addBlock(out, i, j, -K);
  addBlock(out, j, i, -K);
}

}  // namespace

double SpringForce::energy(const Scene&, const VecX& x, const VecX&) const {
  const double l = (at(x, j_) - at(x, i_)).norm();
  return 0.5 * k_ * (l - l0_) * (l - l0_);
}

void SpringForce::addGradient(const Scene&, const VecX& x, const VecX& v, VecX& gradE) const {
  Vec2 n = at(x, j_) - at(x, i_);
  const double l = n.norm();
  n = divide(n, l);
  const Vec2 elastic = k_ * (l - l0_) * n;
  at(gradE, i_) -= elastic;
  at(gradE, j_) += elastic;
  if (b_ != 0.0) {
    const Vec2 damping = b_ * n.dot(at(v, j_) - at(v, i_)) * n;
    at(gradE, i_) -= damping;
    at(gradE, j_) += damping;
  }
}

void SpringForce::addJacobianX(const Scene&, const VecX& x, const VecX& v, Triplets& out) const {
  Vec2 n = at(x, j_) - at(x, i_);
  const double l = n.norm();
  n = divide(n, l);
  const Mat2 P = Mat2::Identity() - n * n.transpose();
  Mat2 K = k_ * (n * n.transpose() + (l - l0_) / l * P);
  if (b_ != 0.0) {
    const Vec2 dv = at(v, j_) - at(v, i_);
    K += b_ / l * (n * dv.transpose() + n.dot(dv) * Mat2::Identity()) * P;
  }
  addPairBlocks(out, i_, j_, K);
}

void SpringForce::addJacobianV(const Scene&, const VecX& x, const VecX&, Triplets& out) const {
  if (b_ == 0.0) return;
  const Vec2 n = normalize(at(x, j_) - at(x, i_));
  addPairBlocks(out, i_, j_, b_ * n * n.transpose());
}

}  // namespace fosssim
