// Scene helpers: step count, particle construction, finalisation, sums over the scene's forces.
#include "fosssim/core/scene.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"

#include <cmath>

namespace fosssim {

long Scene::numSteps() const {
  // The reference computes ceil(duration / dt) in double precision; so do we, so that scenes whose
  // duration is not a multiple of dt (in binary) take the same number of steps.
  return static_cast<long>(std::ceil(duration / dt));
}

void addParticles(Scene& scene, const std::vector<ParticleSpec>& particles) {
  const Eigen::Index n = scene.mass.size();
  scene.mass.conservativeResize(n + 2 * static_cast<Eigen::Index>(particles.size()));
  Eigen::Index row = n;
  for (const ParticleSpec& p : particles) {
    scene.mass[row++] = p.mass;
    scene.mass[row++] = p.mass;
    scene.fixed.push_back(p.fixed ? 1 : 0);
    scene.radius.push_back(p.radius);
  }
}

void addParticle(Scene& scene, double mass, bool fixed, double radius) {
  addParticles(scene, {ParticleSpec{mass, fixed, radius}});
}

void finalizeScene(Scene& scene) {
  if (!collisionEntry(scene.collision.type).addsPenaltyForce) return;
  for (const auto& force : scene.forces)
    if (dynamic_cast<const PenaltyForce*>(force.get())) return;
  scene.forces.push_back(std::make_unique<PenaltyForce>(scene.collision.penaltyK, scene.collision.penaltyThickness));
}

void accumulateGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE, ForceContext& context) {
  for (const auto& force : scene.forces) force->addGradientWith(scene, x, v, gradE, context);
}

void accumulateGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE) {
  ForceContext context;
  accumulateGradient(scene, x, v, gradE, context);
}

double potentialEnergy(const Scene& scene, const VecX& x, const VecX& v, ForceContext& context) {
  double e = 0;
  for (const auto& force : scene.forces) e += force->energyWith(scene, x, v, context);
  return e;
}

double potentialEnergy(const Scene& scene, const VecX& x, const VecX& v) {
  ForceContext context;
  return potentialEnergy(scene, x, v, context);
}

double kineticEnergy(const Scene& scene, const VecX& v) {
  return 0.5 * v.dot(scene.mass.cwiseProduct(v));
}

}  // namespace fosssim
