// Scene helpers: step count, particle construction, sums over the scene's forces.
#include "fosssim/core/scene.h"

#include <cmath>

namespace fosssim {

long Scene::numSteps() const {
  // The reference computes ceil(duration / dt) in double precision; so do we, so that scenes whose
  // duration is not a multiple of dt (in binary) take the same number of steps.
  return static_cast<long>(std::ceil(duration / dt));
}

bool Scene::allForcesHaveJacobians() const {
  for (const auto& f : forces)
    if (!f->hasJacobians()) return false;
  return true;
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

void accumulateGradient(const Scene& scene, const VecX& x, const VecX& v, VecX& gradE) {
  for (const auto& force : scene.forces) force->addGradient(scene, x, v, gradE);
}

double potentialEnergy(const Scene& scene, const VecX& x, const VecX& v) {
  double e = 0;
  for (const auto& force : scene.forces) e += force->energy(scene, x, v);
  return e;
}

double kineticEnergy(const Scene& scene, const VecX& v) {
  return 0.5 * v.dot(scene.mass.cwiseProduct(v));
}

}  // namespace fosssim
