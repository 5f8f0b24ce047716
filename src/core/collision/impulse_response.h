// Internal header: the reference's impulse responses, written with inverse masses.
//
// The reference writes them with masses and treats fixed particles as infinitely heavy; e.g. for
// particle-edge, D1 = 1 + (1-a)^2 m1/m2 + a^2 m1/m3. Factoring out m1 gives D1 = m1 W with
//   W = w1 + (1-a)^2 w2 + a^2 w3,   w = 1/m, and w = 0 for a fixed particle,
// and likewise D2 = m2 W, D3 = m3 W. So the velocity changes are
//   dv1 = +N w1/W n,  dv2 = -(1-a) N w2/W n,  dv3 = -a N w3/W n,
// with N = 2c (v_edge - v1) . n (c = (1 + COR)/2). This is the same formula without inf/inf or
// 0*inf (which the mass form meets when several particles are fixed). Particle-particle is the
// case a = 0 with particle 2 as the edge's first endpoint; particle-half-plane has w_other = 0:
// dv1 = -2c (v1 . n) n.
#pragma once

#include "continuous_detection.h"
#include "fosssim/core/scene.h"

namespace fosssim {

/// Velocity changes of at most three particles.
struct VelocityChange {
  int count = 0;
  int particle[3] = {0, 0, 0};
  Vec2 dv[3] = {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  void add(int p, const Vec2& change) {
    particle[count] = p;
    dv[count] = change;
    ++count;
  }
};

inline double inverseMass(const Scene& scene, int i) {
  return scene.isFixed(i) ? 0.0 : 1.0 / scene.massOf(i);
}

/// Particles i and j with velocities vi, vj, contact vector n from i to j; w(p) is particle p's
/// inverse mass (0: it does not move).
template <class InverseMass>
VelocityChange particleParticleImpulse(InverseMass&& w, int i, int j, const Vec2& n, double cor, const Vec2& vi,
                                       const Vec2& vj) {
  VelocityChange out;
  const double wi = w(i), wj = w(j), sum = wi + wj;
  if (sum == 0.0) return out;
  const Vec2 nhat = normalize(n);
  const double N = (1.0 + cor) * (vj - vi).dot(nhat);
  if (wi != 0.0) out.add(i, N * wi / sum * nhat);
  if (wj != 0.0) out.add(j, -N * wj / sum * nhat);
  return out;
}

/// Particle i (velocity v1) against edge e (endpoint velocities v2, v3) at parameter alpha in
/// [0, 1], contact vector n from the particle to the edge; w as above.
template <class InverseMass>
VelocityChange particleEdgeImpulse(InverseMass&& w, int i, const Edge& e, double alpha, const Vec2& n, double cor,
                                   const Vec2& v1, const Vec2& v2, const Vec2& v3) {
  VelocityChange out;
  const double w1 = w(i), w2 = w(e.i), w3 = w(e.j);
  const double a = alpha, b = 1.0 - alpha;
  const double W = w1 + b * b * w2 + a * a * w3;
  if (W == 0.0) return out;
  const Vec2 nhat = normalize(n);
  const double N = (1.0 + cor) * (v2 + a * (v3 - v2) - v1).dot(nhat);
  if (w1 != 0.0) out.add(i, N * w1 / W * nhat);
  if (w2 != 0.0) out.add(e.i, -b * N * w2 / W * nhat);
  if (w3 != 0.0) out.add(e.j, -a * N * w3 / W * nhat);
  return out;
}

/// Particle i (velocity v1, inverse mass w1) against a half-plane, contact vector n toward the
/// boundary.
inline VelocityChange particleHalfPlaneImpulse(double w1, int i, const Vec2& n, double cor, const Vec2& v1) {
  VelocityChange out;
  if (w1 == 0.0) return out;
  const Vec2 nhat = normalize(n);
  out.add(i, -(1.0 + cor) * v1.dot(nhat) * nhat);
  return out;
}

/// The same with the scene's masses (fixed particles do not move).
inline VelocityChange particleParticleResponse(const Scene& scene, int i, int j, const Vec2& n, double cor,
                                               const Vec2& vi, const Vec2& vj) {
  return particleParticleImpulse([&](int p) { return inverseMass(scene, p); }, i, j, n, cor, vi, vj);
}
inline VelocityChange particleEdgeResponse(const Scene& scene, int i, const Edge& e, double alpha, const Vec2& n,
                                           double cor, const Vec2& v1, const Vec2& v2, const Vec2& v3) {
  return particleEdgeImpulse([&](int p) { return inverseMass(scene, p); }, i, e, alpha, n, cor, v1, v2, v3);
}
inline VelocityChange particleHalfPlaneResponse(const Scene& scene, int i, const Vec2& n, double cor,
                                                const Vec2& v1) {
  return particleHalfPlaneImpulse(inverseMass(scene, i), i, n, cor, v1);
}

}  // namespace fosssim

namespace fosssim {

/// The response to a continuous-time collision, with each particle's velocity taken as its mean
/// velocity over the step, d = (qe - qs)/h (the reference's choice).
inline VelocityChange collisionResponse(const Scene& scene, const Collision& c, double cor, const VecX& qs,
                                        const VecX& qe, double h) {
  auto d = [&](int p) -> Vec2 { return divide(at(qe, p) - at(qs, p), h); };
  switch (c.kind) {
    case PairKind::ParticleParticle:
      return particleParticleResponse(scene, c.i, c.j, c.n, cor, d(c.i), d(c.j));
    case PairKind::ParticleEdge: {
      const Edge& e = scene.edges[c.j];
      return particleEdgeResponse(scene, c.i, e, c.alpha, c.n, cor, d(c.i), d(e.i), d(e.j));
    }
    case PairKind::ParticleHalfPlane:
      return particleHalfPlaneResponse(scene, c.i, c.n, cor, d(c.i));
  }
  return {};
}

/// Applies velocity changes to a state; a velocity change dv also moves the particle by h dv
/// (the step's end position is the start position plus h times the final velocity).
inline void applyWithDisplacement(const VelocityChange& change, double h, VecX& x, VecX& v) {
  for (int k = 0; k < change.count; ++k) {
    at(v, change.particle[k]) += change.dv[k];
    at(x, change.particle[k]) += h * change.dv[k];
  }
}

}  // namespace fosssim
