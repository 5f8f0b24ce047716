#include "scene_builder.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/integrator.h"
#include "fosssim/io/scene_writer.h"

namespace fosssim::study {

SceneBuilder& SceneBuilder::duration(double seconds) {
  duration_ = seconds;
  return *this;
}

SceneBuilder& SceneBuilder::integrator(const std::string& type, double dt) {
  integrator_ = type;
  dt_ = dt;
  return *this;
}

SceneBuilder& SceneBuilder::collision(const CollisionChoice& choice) {
  collision_ = choice;
  return *this;
}

SceneBuilder& SceneBuilder::method(const Method& m, double dt) {
  integrator(m.integrator, dt);
  return collision(m.collision);
}

int SceneBuilder::particle(const Vec2& x, const Vec2& v, double mass, bool fixed, double radius) {
  particles_.push_back(Particle{x, v, mass, radius, fixed});
  return static_cast<int>(particles_.size()) - 1;
}

int SceneBuilder::edge(int i, int j, double radius) {
  edges_.push_back(Edge{i, j, radius});
  return static_cast<int>(edges_.size()) - 1;
}

SceneBuilder& SceneBuilder::halfplane(const Vec2& point, const Vec2& normal) {
  halfplanes_.push_back(HalfPlane{point, normal});
  return *this;
}

SceneBuilder& SceneBuilder::spring(int edge, double k, double l0, double b) {
  springs_.push_back(Spring{edge, k, l0, b});
  return *this;
}

SceneBuilder& SceneBuilder::gravity(const Vec2& g) {
  gravity_.push_back(g);
  return *this;
}

SceneBuilder& SceneBuilder::gravitational(int i, int j, double G) {
  gravitational_.push_back(Pair{i, j, G});
  return *this;
}

Status SceneBuilder::build(const std::string& name, SceneFile& out) const {
  auto fail = [&](const std::string& what) { return Status::error(name + ": " + what); };
  if (!findIntegrator(integrator_)) return fail("unknown integrator '" + integrator_ + "'");
  const int n = static_cast<int>(particles_.size());
  auto particleOk = [&](int i) { return i >= 0 && i < n; };
  for (const Edge& e : edges_)
    if (!particleOk(e.i) || !particleOk(e.j)) return fail("an edge joins a particle that does not exist");
  for (const Pair& p : gravitational_)
    if (!particleOk(p.i) || !particleOk(p.j))
      return fail("a gravitational force names a particle that does not exist");
  for (const Spring& s : springs_)
    if (s.edge < 0 || s.edge >= static_cast<int>(edges_.size()))
      return fail("a spring names an edge that does not exist");

  out = SceneFile{};
  out.path = name;
  Scene& scene = out.scene;
  scene.integrator = integrator_;
  scene.dt = dt_;
  scene.duration = duration_;
  // <collision>: as the loader reads it, with the table's defaults for what the choice leaves out;
  // "none" is no element at all (the default settings).
  if (collision_.type != "none") {
    const CollisionEntry* entry = findCollisionType(collision_.type);
    if (!entry) return fail("unknown collision type '" + collision_.type + "'");
    CollisionSettings& c = scene.collision;
    c.type = entry->type;
    c.cor = collision_.cor;
    if (collision_.maxIterations >= 0) c.maxIterations = collision_.maxIterations;
    c.penaltyK = collision_.k >= 0 ? collision_.k : entry->defaultK;
    c.penaltyThickness = collision_.thickness >= 0 ? collision_.thickness : entry->defaultThickness;
  }
  out.initial.x.resize(2 * n);
  out.initial.v.resize(2 * n);
  for (int i = 0; i < n; ++i) {
    const Particle& p = particles_[static_cast<size_t>(i)];
    addParticle(scene, p.mass, p.fixed, p.radius);
    out.initial.x.segment<2>(2 * i) = p.x;
    out.initial.v.segment<2>(2 * i) = p.v;
  }
  scene.edges = edges_;
  scene.halfplanes = halfplanes_;
  // Forces in the loader's (the reference's) summation order, whatever order they were added in.
  for (const Spring& s : springs_) {
    const Edge& e = edges_[static_cast<size_t>(s.edge)];
    scene.forces.push_back(std::make_unique<SpringForce>(e.i, e.j, s.k, s.l0, s.b));
  }
  for (const Vec2& g : gravity_) scene.forces.push_back(std::make_unique<SimpleGravityForce>(g));
  for (const Pair& p : gravitational_) scene.forces.push_back(std::make_unique<GravitationalForce>(p.i, p.j, p.G));
  finalizeScene(scene);  // the penalty force the collision type implies
  return Status::ok();  // no colours: the study draws none (the writer leaves them out)
}

Status SceneBuilder::xml(std::string& out) const {
  SceneFile file;
  if (Status s = build("scene", file); !s) return s;
  return sceneToXml(file, out);
}

}  // namespace fosssim::study
