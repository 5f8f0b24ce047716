// The loader's second half: what can only be checked with the whole file read (indices may name
// elements that come later, the step count needs both <duration> and <integrator>), and the
// assembly of the Scene, State and Appearance.
#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/integrator.h"
#include "scene_elements.h"
#include "fosssim/io/spelling.h"

#include <algorithm>
#include <cmath>

namespace fosssim::io {
namespace {

/// Reports an index beyond the count; false then (and for an index already reported).
bool checkIndex(SceneMessages& messages, const IndexRef& ref, size_t count, const char* what) {
  if (ref.value < 0) return false;
  if (ref.value < static_cast<long>(count)) return true;
  messages.error(ref.line, ref.where + ": " + what + " " + std::to_string(ref.value) + " does not exist (the scene has " +
                               std::to_string(count) + " " + what + (count == 1 ? "" : "s") + ")");
  return false;
}

/// " (<durration> on line 2 is ignored: a misspelling?)" when an unknown element was near `name`.
std::string misspeltHint(const Builder& b, const char* name) {
  for (const auto& [unknown, line] : b.unknownElements)
    if (!closestName(unknown, {name}).empty())
      return " (<" + unknown + "> on line " + std::to_string(line) + " is ignored: a misspelling?)";
  return "";
}

void checkRequired(Builder& b, const std::string& file) {
  for (const ElementSpec& e : elementTable()) {
    if (!e.required) continue;
    const std::string name = e.name;
    const bool present = name == "integrator" ? b.sawIntegrator : name == "duration" ? b.sawDuration : !b.particles.empty();
    if (present) continue;
    std::string form;
    for (const AttributeSpec& a : e.attributes)
      if (a.required()) form += " " + std::string(a.name) + "=...";
    const std::string what = name == "particle" ? "no <particle> elements (at least one is required)"
                                                : "no <" + name + form + "> element (required)";
    b.messages.error(0, file + ": the scene has " + what + misspeltHint(b, e.name));
  }
}

/// Trails keep ceil(duration / dt) positions, at most one per step of the run: a longer trail
/// holds the same positions, so its duration is cut to the run's. Their sum is bounded.
void checkPaths(Builder& b) {
  const Scene& scene = b.out.scene;
  const double runPoints = static_cast<double>(scene.numSteps()) + 1;
  double total = 0;
  for (auto& p : b.paths) {
    const double points = std::min(std::ceil(p.value.duration / scene.dt), runPoints);
    p.value.duration = std::min(p.value.duration, runPoints * scene.dt);
    total += std::max(points, 1.0);
    if (total > kMaxTrailPoints) {
      b.messages.error(p.ref.line, p.ref.where.substr(0, p.ref.where.rfind(" attribute")) +
                                       " attribute 'duration': the trails would keep more than " + shortNumber(kMaxTrailPoints) +
                                       " positions in all (ceil(duration / dt) each, at most one per step of the "
                                       "run: 16 bytes each); shorten the durations or use fewer <particlepath> elements");
      return;
    }
  }
}

/// A spring whose edge joins two particles that start at one point, one of them free: its
/// direction (r / |r|, with r = 0) and so its force are undefined at the start, whatever l0 (the
/// force divides by the length), and the run stopped at step 1 without the spring's line. Both
/// fixed, it moves nothing and is left alone. States reached later are the run's to check.
void checkSpringEnds(Builder& b) {
  for (const SpringSpec& s : b.springs) {
    const Edge& e = b.out.scene.edges[s.edge.value];
    const Vec2 xi(b.positions[2 * e.i], b.positions[2 * e.i + 1]), xj(b.positions[2 * e.j], b.positions[2 * e.j + 1]);
    if (xi != xj || (b.particles[e.i].fixed && b.particles[e.j].fixed)) continue;
    b.messages.error(s.edge.line, s.edge.where + ": edge " + std::to_string(s.edge.value) + " joins particles " +
                                      std::to_string(e.i) + " and " + std::to_string(e.j) + ", which both start at (" +
                                      shortNumber(xi.x()) + ", " + shortNumber(xi.y()) +
                                      "): the spring's direction, and so its force, is undefined there" +
                                      (s.l0 == 0 ? " (even with l0 = 0: the force divides by the length)" : "") +
                                      "; move one of them apart");
  }
}

}  // namespace

void assemble(Builder& b, const std::string& file) {
  SceneFile& out = b.out;
  Scene& scene = out.scene;
  SceneMessages& messages = b.messages;
  checkRequired(b, file);
  const bool timed = b.integratorOk && b.durationOk;
  const std::string tooLong = timed ? stepCountProblem(scene.duration, scene.dt) : "";
  if (!tooLong.empty()) messages.error(b.integratorLine, b.integratorWhere + ": " + tooLong);
  if (timed && tooLong.empty()) checkPaths(b);

  const size_t n = b.particles.size(), edges = scene.edges.size(), planes = scene.halfplanes.size();
  for (const auto& [i, j] : b.edgeEnds) checkIndex(messages, i, n, "particle"), checkIndex(messages, j, n, "particle");
  for (const SpringSpec& s : b.springs) checkIndex(messages, s.edge, edges, "edge");
  for (const auto* list : {&b.gravitational, &b.vortex})
    for (const PairForceSpec& f : *list) checkIndex(messages, f.i, n, "particle"), checkIndex(messages, f.j, n, "particle");
  for (const auto& c : b.particleColors) checkIndex(messages, c.ref, n, "particle");
  for (const auto& c : b.edgeColors) checkIndex(messages, c.ref, edges, "edge");
  for (const auto& c : b.halfplaneColors) checkIndex(messages, c.ref, planes, "half-plane");
  for (const auto& p : b.paths) checkIndex(messages, p.ref, n, "particle");
  if (messages.errors() > 0) return;  // nothing below may meet a placeholder
  checkSpringEnds(b);
  if (messages.errors() > 0) return;

  addParticles(scene, b.particles);
  out.initial.x = Eigen::Map<const VecX>(b.positions.data(), static_cast<Eigen::Index>(b.positions.size()));
  out.initial.v = Eigen::Map<const VecX>(b.velocities.data(), static_cast<Eigen::Index>(b.velocities.size()));

  // Forces in the reference's summation order.
  for (const SpringSpec& s : b.springs) {
    const Edge& e = scene.edges[s.edge.value];
    scene.forces.push_back(std::make_unique<SpringForce>(e.i, e.j, s.k, s.l0, s.b));
  }
  for (auto& f : b.gravity) scene.forces.push_back(std::move(f));
  for (const PairForceSpec& f : b.gravitational)
    scene.forces.push_back(std::make_unique<GravitationalForce>(f.i.value, f.j.value, f.a));
  for (auto& f : b.constant) scene.forces.push_back(std::move(f));
  for (auto& f : b.drag) scene.forces.push_back(std::move(f));
  for (const PairForceSpec& f : b.vortex)
    scene.forces.push_back(std::make_unique<VortexForce>(f.i.value, f.j.value, f.a, f.b));
  finalizeScene(scene);  // the penalty force that the collision type implies

  // Appearance: defaults, then the file's colours.
  Appearance& look = out.look;
  look.particleColors.assign(n, kDefaultParticleColor);
  look.edgeColors.assign(edges, kDefaultEdgeColor);
  look.halfplaneColors.assign(planes, kDefaultHalfplaneColor);
  for (const auto& c : b.particleColors) look.particleColors[c.ref.value] = c.value;
  for (const auto& c : b.edgeColors) look.edgeColors[c.ref.value] = c.value;
  for (const auto& c : b.halfplaneColors) look.halfplaneColors[c.ref.value] = c.value;
  for (auto& p : b.paths) {
    p.value.particle = p.ref.value;
    look.paths.push_back(p.value);
  }

  const IntegratorEntry* integrator = findIntegrator(scene.integrator);
  if (integrator->implicit)
    for (const auto& f : scene.forces)
      if (!f->hasJacobians())
        messages.warn(b.integratorLine, std::string("no Jacobian: ") + f->keyword(),
                      std::string("forces without a Jacobian: ") + f->keyword(),
                      b.integratorWhere + ": " + f->keyword() +
                          " provides no Jacobian; the implicit integrator treats it explicitly");
}

}  // namespace fosssim::io
