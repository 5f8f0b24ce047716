#include "continuous_detection.h"

#include <algorithm>

namespace fosssim {
namespace {

void append(const math::PairPolynomials& polys, PolynomialLog* log) {
  for (int k = 0; k < polys.count; ++k) log->add(polys.polys[k].c.data(), polys.polys[k].size);
}

/// Runs a CCD query, logging its polynomials when asked. Without a log nothing else is built:
/// the scratch PairPolynomials (four zeroed polynomials) would rival a particle-particle query.
template <class Input, class Detect>
bool query(const Input& in, math::Contact& contact, PolynomialLog* log, Detect&& detect) {
  if (!log || !log->enabled()) return detect(in, &contact, static_cast<math::PairPolynomials*>(nullptr));
  math::PairPolynomials polys;
  const bool hit = detect(in, &contact, &polys);
  append(polys, log);
  return hit;
}

}  // namespace

bool ContinuousDetector::particleParticle(const Scene& scene, const VecX& qs, const VecX& qe, int i, int j,
                                          Collision& hit, PolynomialLog* log) const {
  const math::PPInput in{at(qs, i), at(qe, i) - at(qs, i), scene.radius[i],
                         at(qs, j), at(qe, j) - at(qs, j), scene.radius[j]};
  math::Contact contact;
  const math::DetectionRules rules = rules_;
  if (!query(in, contact, log, [rules](auto& a, auto* c, auto* l) { return math::detectPP(a, c, l, rules); }))
    return false;
  hit = Collision{PairKind::ParticleParticle, i, j, contact.tau, contact.n, 0.0};
  return true;
}

bool ContinuousDetector::particleEdge(const Scene& scene, const VecX& qs, const VecX& qe, int i, int edge,
                                      Collision& hit, PolynomialLog* log) const {
  const Edge& e = scene.edges[edge];
  const math::PEInput in{at(qs, i),   at(qe, i) - at(qs, i),     scene.radius[i], at(qs, e.i),
                         at(qe, e.i) - at(qs, e.i), at(qs, e.j), at(qe, e.j) - at(qs, e.j), e.radius};
  math::Contact contact;
  const math::DetectionRules rules = rules_;
  if (!query(in, contact, log, [rules](auto& a, auto* c, auto* l) { return math::detectPE(a, c, l, rules); }))
    return false;
  // The response uses the closest point's parameter at the collision time, clamped to the edge.
  const double t = contact.tau;
  const double alpha =
      math::segmentParameterClamped(in.x1 + t * in.d1, in.x2 + t * in.d2, in.x3 + t * in.d3);
  hit = Collision{PairKind::ParticleEdge, i, edge, t, contact.n, alpha};
  return true;
}

bool ContinuousDetector::particleHalfPlane(const Scene& scene, const VecX& qs, const VecX& qe, int i, int plane,
                                           Collision& hit, PolynomialLog* log) const {
  const HalfPlane& h = scene.halfplanes[plane];
  const math::PHInput in{at(qs, i), at(qe, i) - at(qs, i), scene.radius[i], h.point, h.normal};
  math::Contact contact;
  const math::DetectionRules rules = rules_;
  if (!query(in, contact, log, [rules](auto& a, auto* c, auto* l) { return math::detectPH(a, c, l, rules); }))
    return false;
  hit = Collision{PairKind::ParticleHalfPlane, i, plane, contact.tau, contact.n, 0.0};
  return true;
}

}  // namespace fosssim
