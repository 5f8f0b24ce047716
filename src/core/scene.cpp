// Scene helpers: step count, particle construction, finalisation, sums over the scene's forces.
#include "fosssim/core/scene.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"

#include <cmath>
#include <string>

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

Status checkSceneShape(const Scene& scene, const State* state) {
  const size_t n = scene.fixed.size();
  const auto count = [](size_t size) { return std::to_string(size); };
  if (scene.radius.size() != n || static_cast<size_t>(scene.mass.size()) != 2 * n)
    return Status::error("the scene's particle arrays disagree: " + count(n) + " fixed flags, " +
                         count(scene.radius.size()) + " radii and " + count(static_cast<size_t>(scene.mass.size())) +
                         " mass entries (2 per particle)");
  const auto outside = [&](int i) { return i < 0 || static_cast<size_t>(i) >= n; };
  for (size_t e = 0; e < scene.edges.size(); ++e)
    if (outside(scene.edges[e].i) || outside(scene.edges[e].j))
      return Status::error("edge " + count(e) + " joins particles " + std::to_string(scene.edges[e].i) + " and " +
                           std::to_string(scene.edges[e].j) + ", but the scene has " + count(n) + " particles");
  std::vector<std::pair<int, int>> pairs;
  for (size_t f = 0; f < scene.forces.size(); ++f) {
    pairs.clear();
    scene.forces[f]->couples(pairs);
    for (const auto& [i, j] : pairs)
      if (outside(i) || outside(j))
        return Status::error("force " + count(f) + " ('" + scene.forces[f]->keyword() + "') acts on particles " +
                             std::to_string(i) + " and " + std::to_string(j) + ", but the scene has " + count(n) +
                             " particles");
  }
  if (state && (static_cast<size_t>(state->x.size()) != 2 * n || static_cast<size_t>(state->v.size()) != 2 * n))
    return Status::error("the state has " + count(static_cast<size_t>(state->x.size())) + " position and " +
                         count(static_cast<size_t>(state->v.size())) + " velocity entries; the scene's " + count(n) +
                         " particles need " + count(2 * n) + " of each");
  return Status::ok();
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
