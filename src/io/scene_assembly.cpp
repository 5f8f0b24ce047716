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
#include <limits>
#include <string>

namespace fosssim::io {
namespace {

/// Reports an index beyond the count; false then (and for an index already reported).
bool checkIndex(SceneMessages& messages, const IndexRef& ref, size_t count, const char* what) {
  if (ref.value < 0) return false;
  if (ref.value < static_cast<long>(count)) return true;
  messages.error(ref.line, ref.where + ": " + what + " " + std::to_string(ref.value) +
                               " does not exist (the scene has " + std::to_string(count) + " " + what +
                               (count == 1 ? "" : "s") + ")");
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
    const bool present = name == "integrator" ? b.sawIntegrator
                         : name == "duration" ? b.sawDuration
                                              : !b.particles.empty();
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
      b.messages.error(p.ref.line,
                       p.ref.where.substr(0, p.ref.where.rfind(" attribute")) +
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

/// omega dt above which an explicit integrator's step of a spring-like force is unstable:
/// symplectic Euler's limit for an oscillator (explicit Euler's energy grows at any omega dt, by
/// a factor 1 + (omega dt)^2 a step: five times past this mark).
constexpr double kStableOmegaDt = 2.0;

// A spring-like force of stiffness k on a reduced mass mu oscillates at omega = sqrt(k / mu);
// under an explicit integrator with omega dt past kStableOmegaDt the run blows up within a few
// steps, and the energy watch stops only growth of three orders of magnitude. A disk of 1e-6 kg
// resting in hybrid's default penalty layer (k = 10) has omega dt = 32 at dt = 0.01 and left at
// 1e4 m/s in its first step. So the loader warns, naming the stiffest force and what to change.
// A spring's reduced mass is its two particles' (one's, if the other is fixed); the penalty
// layer's is the lightest movable particle's, as against a wall (a lower bound of its stiffest
// pair's omega, so never a warning for a pair a scene does not have). Implicit integrators are
// stable at any omega dt for the forces they treat implicitly; the penalty force has no Jacobian
// and is explicit under any integrator.
void warnStiffForces(const Scene& scene, const IntegratorEntry& integrator, const Builder& b, SceneMessages& messages) {
  if (!(scene.dt > 0)) return;
  double lightest = std::numeric_limits<double>::infinity();
  for (int p = 0; p < scene.numParticles(); ++p)
    if (!scene.isFixed(p)) lightest = std::min(lightest, scene.massOf(p));
  double worst = 0.0;
  std::string what;
  bool implicitHelps = false;  // the worst force has a Jacobian: an implicit integrator is stable
  for (size_t f = 0; f < scene.forces.size(); ++f) {
    const Force& force = *scene.forces[f];
    const double k = force.stiffness();
    if (!(k > 0.0) || (integrator.implicit && force.hasJacobians())) continue;
    double mu = lightest;
    std::string who = std::string(force.keyword()) + " on the lightest particle, against an obstacle (mass";
    if (const auto* pair = dynamic_cast<const PairForce*>(&force)) {
      const int i = pair->i(), j = pair->j();
      if (scene.isFixed(i) && scene.isFixed(j)) continue;
      const double mi = scene.massOf(i), mj = scene.massOf(j);
      mu = scene.isFixed(i) ? mj : scene.isFixed(j) ? mi : mi * mj / (mi + mj);
      who = std::string(force.keyword()) + " between particles " + std::to_string(i) + " and " + std::to_string(j) +
            " (reduced mass";
    }
    const double omegaDt = std::sqrt(k / mu) * scene.dt;
    if (!(omegaDt > worst)) continue;
    worst = omegaDt;
    what = who + " " + shortNumber(mu) + ", k = " + shortNumber(k) + ")";
    implicitHelps = force.hasJacobians();
  }
  if (!(worst > kStableOmegaDt)) return;
  messages.warn(b.integratorLine, "stiff force", "stiff forces",
                b.integratorWhere + ": " + what + " oscillates at omega dt = " + shortNumber(worst) + " with dt = " +
                    shortNumber(scene.dt) + "; " + scene.integrator + " is unstable above " +
                    shortNumber(kStableOmegaDt) + " and the run will likely blow up: use dt below " +
                    shortNumber(kStableOmegaDt * scene.dt / worst) + ", a smaller k or a heavier particle" +
                    (implicitHelps ? ", or implicit-euler" : ""));
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
    for (const PairForceSpec& f : *list)
      checkIndex(messages, f.i, n, "particle"), checkIndex(messages, f.j, n, "particle");
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
  warnStiffForces(scene, *integrator, b, messages);
  if (integrator->implicit)
    for (const auto& f : scene.forces)
      if (!f->hasJacobians())
        messages.warn(b.integratorLine, std::string("no Jacobian: ") + f->keyword(),
                      std::string("forces without a Jacobian: ") + f->keyword(),
                      b.integratorWhere + ": " + f->keyword() +
                          " provides no Jacobian; the implicit integrator treats it explicitly");
}

}  // namespace fosssim::io
