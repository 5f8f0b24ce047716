#include "py_scene.h"

#include "errors.h"
#include "staged_output.h"
#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/integrator.h"
#include "fosssim/core/scene_values.h"
#include "fosssim/io/scene_writer.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace fosssim::py {
namespace {

std::string text(double v) { return formatNumber(v); }

void requireFinite(const char* what, double v) {
  if (!std::isfinite(v)) throw SceneError(std::string(what) + " must be finite, got " + text(v));
}

void requirePositive(const char* what, double v, bool allowZero = false) {
  requireFinite(what, v);
  if (v < 0 || (!allowZero && v == 0))
    throw SceneError(std::string(what) + " must be " + (allowZero ? ">= 0" : "> 0") + ", got " + text(v));
  // As the loader: a value that must be > 0 is divided by somewhere (1/m), so a subnormal one,
  // whose reciprocal overflows, is as unusable as 0.
  if (v > 0 && !std::isfinite(1.0 / v))
    throw SceneError(std::string(what) + " is too small: its reciprocal is not finite, got " + text(v));
}

/// As the loader's "number >= 0" attributes (no reciprocal is taken: 1e-320 is a fine value).
void requireNonNegative(const char* what, double v) {
  requireFinite(what, v);
  if (v < 0) throw SceneError(std::string(what) + " must be >= 0, got " + text(v));
}

/// duration / dt at most kMaxSteps, the loader's limit (fosssim/core/scene_values.h).
void requireSteps(const char* what, double duration, double dt) {
  if (dt <= 0) return;
  if (const std::string why = stepCountProblem(duration, dt); !why.empty())
    throw SceneError(std::string(what) + ": " + why);
}

/// The format's summation order of force kinds (see scene.h).
int rank(const Force& f) {
  const std::string k = f.keyword();
  const char* order[] = {"springforce", "simplegravity", "gravitationalforce", "constantforce",
                         "dragdamping", "vortexforce", "collision penalty"};
  for (int r = 0; r < 7; ++r)
    if (k == order[r]) return r;
  return 7;
}

}  // namespace

std::shared_ptr<PyScene> PyScene::load(const std::string& path) {
  checkPath(path, "Scene.load");
  auto s = std::make_shared<PyScene>();
  check<SceneError>(loadScene(path, s->file));
  return s;
}

std::shared_ptr<PyScene> PyScene::fromXml(const std::string& xml, const std::string& name) {
  auto s = std::make_shared<PyScene>();
  check<SceneError>(parseScene(xml, name, s->file));
  return s;
}

std::string PyScene::toXml() const {
  std::string xml;
  check<SceneError>(sceneToXml(file, xml));
  return xml;
}

std::shared_ptr<PyScene> PyScene::copy(const char* what) const {
  // The copy goes through the loader, whose message for this would name a <particle> element of
  // a file that was never there.
  if (file.scene.numParticles() == 0)
    throw SceneError(std::string(what) + ": the scene has no particles; add at least one with add_particle");
  auto s = fromXml(toXml(), file.path.empty() ? "<scene>" : file.path);
  s->file.path = file.path;
  s->file.warnings = file.warnings;
  return s;
}

void PyScene::checkParticle(int i, const char* what) const {
  if (i < 0 || i >= file.scene.numParticles())
    throw SceneError(std::string(what) + ": particle " + std::to_string(i) + " does not exist (the scene has " +
                     std::to_string(file.scene.numParticles()) + " particles)");
}

int PyScene::addParticle(const Vec2& x, const Vec2& v, double mass, double radius, bool fixed) {
  requirePositive("add_particle: mass", mass);
  requirePositive("add_particle: radius", radius);
  for (double c : {x.x(), x.y(), v.x(), v.y()}) requireFinite("add_particle: position and velocity", c);
  fosssim::addParticle(file.scene, mass, fixed, radius);
  file.look.particleColors.push_back(kDefaultParticleColor);
  return file.initial.addParticle(x, v);
}

int PyScene::addEdge(int i, int j, double radius) {
  checkParticle(i, "add_edge");
  checkParticle(j, "add_edge");
  if (i == j) throw SceneError("add_edge: an edge needs two different particles, got i = j = " + std::to_string(i));
  requirePositive("add_edge: radius", radius);
  file.scene.edges.push_back(Edge{i, j, radius});
  file.look.edgeColors.push_back(kDefaultEdgeColor);
  return static_cast<int>(file.scene.edges.size()) - 1;
}

int PyScene::addHalfplane(const Vec2& point, const Vec2& normal) {
  for (double c : {point.x(), point.y(), normal.x(), normal.y()}) requireFinite("add_halfplane: point and normal", c);
  if (normal.squaredNorm() == 0.0) throw SceneError("add_halfplane: the normal must not be zero");
  file.scene.halfplanes.push_back(HalfPlane{point, normal});
  file.look.halfplaneColors.push_back(kDefaultHalfplaneColor);
  return static_cast<int>(file.scene.halfplanes.size()) - 1;
}

void PyScene::addForce(std::unique_ptr<Force> force) {
  auto& forces = file.scene.forces;
  const int r = rank(*force);
  auto at = forces.begin();
  while (at != forces.end() && rank(**at) <= r) ++at;
  forces.insert(at, std::move(force));
}

void PyScene::addGravity(const Vec2& g) {
  requireFinite("add_gravity: g[0]", g.x());
  requireFinite("add_gravity: g[1]", g.y());
  addForce(std::make_unique<SimpleGravityForce>(g));
}

void PyScene::addConstantForce(const Vec2& f) {
  requireFinite("add_constant_force: f[0]", f.x());
  requireFinite("add_constant_force: f[1]", f.y());
  addForce(std::make_unique<ConstantForce>(f));
}

void PyScene::addSpring(int edge, double k, double l0, double b) {
  if (edge < 0 || edge >= static_cast<int>(file.scene.edges.size()))
    throw SceneError("add_spring: edge " + std::to_string(edge) + " does not exist (the scene has " +
                     std::to_string(file.scene.edges.size()) + " edges)");
  requirePositive("add_spring: k", k, true);
  requirePositive("add_spring: l0", l0, true);
  requirePositive("add_spring: b", b, true);
  const Edge& e = file.scene.edges[edge];
  addForce(std::make_unique<SpringForce>(e.i, e.j, k, l0, b));
}

void PyScene::addGravitational(int i, int j, double G) {
  checkParticle(i, "add_gravitational_force");
  checkParticle(j, "add_gravitational_force");
  if (i == j) throw SceneError("add_gravitational_force: needs two different particles");
  requireFinite("add_gravitational_force: G", G);
  addForce(std::make_unique<GravitationalForce>(i, j, G));
}

void PyScene::addVortex(int i, int j, double kbs, double kvc) {
  checkParticle(i, "add_vortex_force");
  checkParticle(j, "add_vortex_force");
  if (i == j) throw SceneError("add_vortex_force: needs two different particles");
  requireFinite("add_vortex_force: kbs", kbs);
  requireFinite("add_vortex_force: kvc", kvc);
  addForce(std::make_unique<VortexForce>(i, j, kbs, kvc));
}

void PyScene::setCollision(const std::string& type, double cor, long long maxIterations, const std::string& failsafe,
                           std::optional<double> k, std::optional<double> thickness) {
  const CollisionEntry* entry = findCollisionType(type);
  if (!entry) {
    std::string valid;
    for (const auto& e : collisionTable()) valid += (valid.empty() ? "" : ", ") + std::string(e.keyword);
    throw SceneError("set_collision: unknown collision type \"" + type + "\" (valid: " + valid + ")");
  }
  requireFinite("set_collision: cor", cor);
  if (cor < 0 || cor > 1) throw SceneError("set_collision: cor must lie in [0, 1], got " + text(cor));
  // The loader's limit (fosssim/core/scene_values.h): more passes per step only make a jammed pile slower.
  if (maxIterations > kMaxCollisionIterations) {
    // LLONG_MAX: the binding's stand-in for a Python int beyond long long.
    const std::string got = maxIterations == LLONG_MAX ? "an integer beyond 2**63" : std::to_string(maxIterations);
    throw SceneError("set_collision: maxiters must be at most " + std::to_string(kMaxCollisionIterations) + ", got " +
                     got + ": " + kMaxCollisionIterationsReason);
  }
  // Given, as the loader's k="-1": refused, not taken for "the default" (None is the default).
  if (k) requireNonNegative("set_collision: k", *k);
  if (thickness) requireNonNegative("set_collision: thickness", *thickness);
  if (failsafe != "projection" && failsafe != "rigid")
    throw SceneError("set_collision: unknown failsafe \"" + failsafe + "\" (valid: projection, rigid)");
  CollisionSettings& c = file.scene.collision;
  c.type = entry->type;
  c.cor = cor;
  c.maxIterations = static_cast<int>(std::max<long long>(maxIterations, -1));  // <= 0: none, as the loader's
  c.failsafe = failsafe == "rigid" ? Failsafe::Rigid : Failsafe::Projection;
  c.penaltyK = k.value_or(entry->defaultK);
  c.penaltyThickness = thickness.value_or(entry->defaultThickness);
  auto& forces = file.scene.forces;
  for (auto it = forces.begin(); it != forces.end();)
    it = dynamic_cast<PenaltyForce*>(it->get()) ? forces.erase(it) : it + 1;
  if (entry->addsPenaltyForce) forces.push_back(std::make_unique<PenaltyForce>(c.penaltyK, c.penaltyThickness));
}

void PyScene::setIntegrator(const std::string& type, double dt) {
  if (!findIntegrator(type)) {
    std::string valid;
    for (const auto& e : integratorTable()) valid += (valid.empty() ? "" : ", ") + std::string(e.keyword);
    throw SceneError("set_integrator: unknown integrator \"" + type + "\" (valid: " + valid + ")");
  }
  requirePositive("set_integrator: dt", dt);
  requireSteps("set_integrator", file.scene.duration, dt);
  file.scene.integrator = type;
  file.scene.dt = dt;
}

void PyScene::setText(std::string& into, const std::string& text, const char* what) {
  // The writer's rule, checked here rather than when the scene is next written (copy(), Simulator).
  if (const std::string why = xmlTextProblem(text); !why.empty()) throw SceneError(std::string(what) + ": " + why);
  into = text;
}

void PyScene::setDuration(double duration) {
  requirePositive("duration", duration, true);
  requireSteps("duration", duration, file.scene.dt);
  file.scene.duration = duration;
}

}  // namespace fosssim::py
