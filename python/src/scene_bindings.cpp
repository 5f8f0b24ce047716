// fosssim.Scene: load or build a scene, read it as arrays, write it as XML.
#include "arrays.h"
#include "bindings.h"
#include "py_scene.h"
#include "staged_output.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/io/scene_writer.h"

#include <nanobind/stl/array.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <climits>
#include <cmath>
#include <fstream>

namespace fosssim::py {
namespace {

using P = std::array<double, 2>;
Vec2 vec(const P& p) { return Vec2(p[0], p[1]); }

/// A force as a dict: its element name and parameters (springs name their particles).
nb::dict forceDict(const Force& f) {
  nb::dict d;
  d["type"] = std::string(f.keyword());
  if (auto* s = dynamic_cast<const SpringForce*>(&f)) {
    d["i"] = s->i(), d["j"] = s->j(), d["k"] = s->stiffness(), d["l0"] = s->restLength(), d["b"] = s->damping();
  } else if (auto* g = dynamic_cast<const SimpleGravityForce*>(&f)) {
    d["fx"] = g->acceleration().x(), d["fy"] = g->acceleration().y();
  } else if (auto* c = dynamic_cast<const ConstantForce*>(&f)) {
    d["fx"] = c->force().x(), d["fy"] = c->force().y();
  } else if (auto* gr = dynamic_cast<const GravitationalForce*>(&f)) {
    d["i"] = gr->i(), d["j"] = gr->j(), d["G"] = gr->G();
  } else if (auto* dr = dynamic_cast<const DragDampingForce*>(&f)) {
    d["b"] = dr->damping();
  } else if (auto* v = dynamic_cast<const VortexForce*>(&f)) {
    d["i"] = v->i(), d["j"] = v->j(), d["kbs"] = v->kbs(), d["kvc"] = v->kvc();
  } else if (auto* p = dynamic_cast<const PenaltyForce*>(&f)) {
    d["k"] = p->stiffness(), d["thickness"] = p->thickness();
  }
  return d;
}

/// Sets an initial state vector (2N: positions or velocities) from an (N, 2) array, refusing
/// non-finite values before anything is changed.
void setFinitePairs(VecX& target, const Input& a, const char* what) {
  const double* p = pairsOf(a, target.size() / 2, what);
  for (long k = 0; k < target.size(); ++k)
    if (!std::isfinite(p[k])) throw SceneError(std::string(what) + ": non-finite value");
  std::copy(p, p + target.size(), target.data());
}

}  // namespace

void bindScene(nb::module_& m) {
  nb::class_<PyScene>(m, "Scene", "A scene: particles, edges, half-planes, forces, integrator and collision handling.")
      .def(nb::init<>(), "An empty scene (add particles, then simulate).")
      .def_static("load", &PyScene::load, nb::arg("path"),
                  "Loads an XML scene file; raises SceneError with the located message on bad input.")
      .def_static("from_xml", &PyScene::fromXml, nb::arg("text"), nb::arg("name") = "<string>",
                  "Parses XML text; `name` stands for the file in messages.")
      .def("to_xml", &PyScene::toXml, "The scene as XML text that loads back to the same scene.")
      .def(
          "write",
          [](const PyScene& s, const std::string& path) {
            // Under the partial name, renamed when complete: a full disk does not cut the old file.
            StagedOutput out(path, "Scene.write");
            out.keepingPartial("the scene so far", [&] { check<FileError>(writeScene(out.writePath(), s.file)); });
            out.commit();
          },
          nb::arg("path"), "Writes the scene as an XML scene file (under NAME.partial.EXT, renamed when complete).")
      .def("copy", [](const PyScene& s) { return s.copy(); })
      .def_prop_ro("path", [](const PyScene& s) { return s.file.path; })
      .def_prop_ro(
          "warnings", [](const PyScene& s) { return s.file.warnings; },
          "Located messages about input the loader ignored.")
      .def_prop_rw(
          "description", [](const PyScene& s) { return s.file.description; },
          [](PyScene& s, const std::string& t) { PyScene::setText(s.file.description, t, "description"); })
      .def_prop_rw(
          "tag", [](const PyScene& s) { return s.file.tag; },
          [](PyScene& s, const std::string& t) { PyScene::setText(s.file.tag, t, "tag"); })
      .def_prop_ro("integrator", [](const PyScene& s) { return s.file.scene.integrator; })
      .def_prop_ro("dt", [](const PyScene& s) { return s.file.scene.dt; })
      .def("set_integrator", &PyScene::setIntegrator, nb::arg("type"), nb::arg("dt"))
      .def_prop_rw(
          "duration", [](const PyScene& s) { return s.file.scene.duration; }, &PyScene::setDuration)
      .def_prop_ro(
          "num_steps", [](const PyScene& s) { return s.file.scene.numSteps(); },
          "Steps of a full run: ceil(duration / dt).")
      .def_prop_ro("collision",
                   [](const PyScene& s) {
                     const CollisionSettings& c = s.file.scene.collision;
                     nb::dict d;
                     d["type"] = collisionKeyword(c.type), d["cor"] = c.cor, d["maxiters"] = c.maxIterations;
                     d["failsafe"] = std::string(c.failsafe == Failsafe::Rigid ? "rigid" : "projection");
                     d["k"] = c.penaltyK, d["thickness"] = c.penaltyThickness;
                     return d;
                   })
      .def(
          "set_collision",
          [](PyScene& s, const std::string& type, double cor, nb::object maxiters, const std::string& failsafe,
             std::optional<double> k, std::optional<double> thickness) {
            // Any integer (NumPy's too, through __index__; a float is a TypeError): one beyond C's int
            // (2**31) is out of range ("at most 10000"), not of the wrong type, as an int argument made it.
            nb::object index = nb::steal(PyNumber_Index(maxiters.ptr()));
            if (!index.is_valid()) throw nb::python_error();
            int overflow = 0;
            long long iterations = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
            if (iterations == -1 && PyErr_Occurred()) throw nb::python_error();
            if (overflow != 0) iterations = overflow > 0 ? LLONG_MAX : LLONG_MIN;
            s.setCollision(type, cor, iterations, failsafe, k, thickness);
          },
          // The stub's signature: maxiters is an int to the caller (an object here only to see its full value).
          nb::sig("def set_collision(self, type: str, cor: float = 1.0, maxiters: int = 10, "
                  "failsafe: str = 'projection', k: float | None = None, thickness: float | None = None) -> None"),
          nb::arg("type"), nb::arg("cor") = 1.0, nb::arg("maxiters") = 10, nb::arg("failsafe") = "projection",
          nb::arg("k") = nb::none(), nb::arg("thickness") = nb::none(),
          "Collision handling: none, simple, continuous-time, penalty or hybrid (k and thickness: the "
          "penalty force's, default the type's).")
      .def_prop_ro("num_particles", [](const PyScene& s) { return s.file.scene.numParticles(); })
      .def_prop_rw(
          "positions",
          [](const PyScene& s) { return copyArray(s.file.initial.x.data(), s.file.scene.numParticles(), 2); },
          [](PyScene& s, const Input& a) { setFinitePairs(s.file.initial.x, a, "positions"); },
          "Initial positions, (N, 2) (a copy; assign an array to change them).")
      .def_prop_rw(
          "velocities",
          [](const PyScene& s) { return copyArray(s.file.initial.v.data(), s.file.scene.numParticles(), 2); },
          [](PyScene& s, const Input& a) { setFinitePairs(s.file.initial.v, a, "velocities"); },
          "Initial velocities, (N, 2).")
      .def_prop_rw(
          "masses",
          [](const PyScene& s) {
            std::vector<double> m(s.file.scene.numParticles());
            for (size_t i = 0; i < m.size(); ++i) m[i] = s.file.scene.massOf(static_cast<int>(i));
            return copyArray(m.data(), m.size());
          },
          [](PyScene& s, const Input& a) {
            const int n = s.file.scene.numParticles();
            const double* p = valuesOf(a, n, "masses");
            for (int i = 0; i < n; ++i)
              if (!(std::isfinite(p[i]) && p[i] > 0 && std::isfinite(1.0 / p[i])))
                throw SceneError("masses: particle " + std::to_string(i) +
                                 "'s mass must be finite and > 0, with a finite reciprocal, got " + formatNumber(p[i]));
            for (int i = 0; i < n; ++i) s.file.scene.mass[2 * i] = s.file.scene.mass[2 * i + 1] = p[i];
          },
          "Particle masses, (N,).")
      .def_prop_ro("radii",
                   [](const PyScene& s) { return copyArray(s.file.scene.radius.data(), s.file.scene.radius.size()); })
      .def_prop_ro("fixed",
                   [](const PyScene& s) {
                     std::vector<bool> f;
                     for (char c : s.file.scene.fixed) f.push_back(c != 0);
                     return f;
                   })
      .def_prop_ro(
          "edges",
          [](const PyScene& s) {
            std::vector<std::tuple<int, int, double>> out;
            for (const Edge& e : s.file.scene.edges) out.emplace_back(e.i, e.j, e.radius);
            return out;
          },
          "(i, j, radius) per edge.")
      .def_prop_ro(
          "halfplanes",
          [](const PyScene& s) {
            std::vector<std::pair<P, P>> out;
            for (const HalfPlane& h : s.file.scene.halfplanes)
              out.push_back({P{h.point.x(), h.point.y()}, P{h.normal.x(), h.normal.y()}});
            return out;
          },
          "(point, normal) per half-plane.")
      .def_prop_ro(
          "forces",
          [](const PyScene& s) {
            nb::list out;
            for (const auto& f : s.file.scene.forces) out.append(forceDict(*f));
            return out;
          },
          "The forces in summation order, each a dict of its element name and parameters.")
      .def(
          "add_particle",
          [](PyScene& s, const P& x, const P& v, double mass, double radius, bool fixed) {
            return s.addParticle(vec(x), vec(v), mass, radius, fixed);
          },
          nb::arg("position"), nb::arg("velocity") = P{0, 0}, nb::arg("mass") = 1.0, nb::arg("radius") = 0.1,
          nb::arg("fixed") = false, "Adds a particle; returns its index.")
      .def("add_edge", &PyScene::addEdge, nb::arg("i"), nb::arg("j"), nb::arg("radius") = Edge{}.radius,
           "Adds a capsule between particles i and j; returns its index.")
      .def(
          "add_halfplane", [](PyScene& s, const P& p, const P& n) { return s.addHalfplane(vec(p), vec(n)); },
          nb::arg("point"), nb::arg("normal"), "Adds a half-plane (free side where (x - point) . normal > 0).")
      .def("add_spring", &PyScene::addSpring, nb::arg("edge"), nb::arg("k"), nb::arg("l0"), nb::arg("b") = 0.0)
      .def(
          "add_gravity", [](PyScene& s, const P& g) { s.addGravity(vec(g)); }, nb::arg("g") = P{0, -9.81})
      .def(
          "add_constant_force", [](PyScene& s, const P& f) { s.addConstantForce(vec(f)); }, nb::arg("f"))
      .def("add_gravitational_force", &PyScene::addGravitational, nb::arg("i"), nb::arg("j"), nb::arg("G"))
      .def(
          "add_drag",
          [](PyScene& s, double b) {
            if (!(std::isfinite(b) && b >= 0)) throw SceneError("add_drag: b must be finite and >= 0");
            s.addForce(std::make_unique<DragDampingForce>(b));
          },
          nb::arg("b"))
      .def("add_vortex_force", &PyScene::addVortex, nb::arg("i"), nb::arg("j"), nb::arg("kbs"), nb::arg("kvc"))
      .def(
          "set_viewport",
          [](PyScene& s, double cx, double cy, double size) {
            if (!(size > 0 && std::isfinite(size) && std::isfinite(cx) && std::isfinite(cy)))
              throw SceneError("set_viewport: finite centre and size > 0 needed");
            s.file.look.viewport = Viewport{cx, cy, size};
          },
          nb::arg("cx"), nb::arg("cy"), nb::arg("size"))
      .def("__repr__", [](const PyScene& s) {
        return "<fosssim.Scene " + (s.file.path.empty() ? std::string("(built)") : s.file.path) + ": " +
               std::to_string(s.file.scene.numParticles()) + " particles, " +
               std::to_string(s.file.scene.edges.size()) + " edges, " + std::to_string(s.file.scene.halfplanes.size()) +
               " half-planes, " + s.file.scene.integrator + ", collision " +
               collisionKeyword(s.file.scene.collision.type) + ">";
      });
}

}  // namespace fosssim::py
