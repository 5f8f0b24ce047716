// The scene writer: the loader's inverse. It writes what the loader reads, in the loader's terms
// (springs by edge index, the penalty force as collision settings), and checks first that the
// scene can be written that way, so that loading the text gives back the same scene.
#include "fosssim/io/scene_writer.h"

#include "xml_syntax.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace fosssim {

std::string xmlTextProblem(const std::string& text) {
  // XML carries no control character but tab and line ends, not even as a reference: the loader
  // refuses the file, so the text would not load back.
  for (const char c : text)
    if (const auto code = static_cast<unsigned char>(c); io::isForbiddenControl(code))
      return "holds the control character " + io::codePointName(code) +
             " (a scene file is XML text, which has none but tab and line ends)";
  // Nor bytes that are not UTF-8 (Latin-1 text): the loader refuses those too.
  if (io::InvalidUtf8 bad; io::findInvalidUtf8(text, bad)) return "holds " + bad.why + " (a scene file is UTF-8 text)";
  return "";
}

namespace {

/// Thrown inside the writer only; sceneToXml turns it into a Status.
struct WriteError {
  std::string message;
};

/// Attribute text with XML's special characters and line breaks as references, so that the
/// parser gives back the same string (a raw line break would be kept, but a tab or carriage
/// return would not survive every parser).
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += "&#9;"; break;
      default: out += c;
    }
  }
  return out;
}

/// One element on one line: <name a="1" b="2"/>.
class Element {
 public:
  Element(std::string& out, const char* name) : out_(out), name_(name) { out_ += std::string("  <") + name; }
  ~Element() { out_ += "/>\n"; }
  Element(const Element&) = delete;
  Element& operator=(const Element&) = delete;

  Element& number(const char* attribute, double value) {
    if (!std::isfinite(value))
      throw WriteError{std::string("<") + name_ + "> attribute '" + attribute + "' is " + formatNumber(value) +
                       " (a scene file holds finite numbers only)"};
    return text(attribute, formatNumber(value));
  }
  Element& integer(const char* attribute, long value) { return text(attribute, std::to_string(value)); }
  Element& text(const char* attribute, const std::string& value) {
    if (const std::string why = xmlTextProblem(value); !why.empty())
      throw WriteError{std::string("<") + name_ + "> attribute '" + attribute + "' " + why};
    out_ += std::string(" ") + attribute + "=\"" + escaped(value) + "\"";
    return *this;
  }
  Element& rgb(const Rgb& c) { return number("r", c.r).number("g", c.g).number("b", c.b); }

 private:
  std::string& out_;
  const char* name_;
};

bool sameRgb(const Rgb& a, const Rgb& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

/// The loader's summation order of force kinds (scene.h): its rank for each force.
int forceRank(const Force& f) {
  if (dynamic_cast<const SpringForce*>(&f)) return 0;
  if (dynamic_cast<const SimpleGravityForce*>(&f)) return 1;
  if (dynamic_cast<const GravitationalForce*>(&f)) return 2;
  if (dynamic_cast<const ConstantForce*>(&f)) return 3;
  if (dynamic_cast<const DragDampingForce*>(&f)) return 4;
  if (dynamic_cast<const VortexForce*>(&f)) return 5;
  if (dynamic_cast<const PenaltyForce*>(&f)) return 6;
  return -1;
}

/// The first edge from i to j (the loader builds a spring on edge e from e.i to e.j).
int edgeJoining(const Scene& scene, int i, int j) {
  for (size_t e = 0; e < scene.edges.size(); ++e)
    if (scene.edges[e].i == i && scene.edges[e].j == j) return static_cast<int>(e);
  return -1;
}

void writeForce(std::string& out, const Scene& scene, const Force& force, size_t index) {
  if (const auto* s = dynamic_cast<const SpringForce*>(&force)) {
    const int e = edgeJoining(scene, s->i(), s->j());
    if (e < 0)
      throw WriteError{"force " + std::to_string(index) + " (springforce between particles " + std::to_string(s->i()) +
                       " and " + std::to_string(s->j()) + "): no edge from " + std::to_string(s->i()) + " to " +
                       std::to_string(s->j()) + " (a scene file's spring acts along an edge)"};
    Element(out, "springforce").integer("edge", e).number("k", s->stiffness()).number("l0", s->restLength())
        .number("b", s->damping());
  } else if (const auto* g = dynamic_cast<const SimpleGravityForce*>(&force)) {
    Element(out, "simplegravity").number("fx", g->acceleration().x()).number("fy", g->acceleration().y());
  } else if (const auto* gr = dynamic_cast<const GravitationalForce*>(&force)) {
    Element(out, "gravitationalforce").integer("i", gr->i()).integer("j", gr->j()).number("G", gr->G());
  } else if (const auto* c = dynamic_cast<const ConstantForce*>(&force)) {
    Element(out, "constantforce").number("fx", c->force().x()).number("fy", c->force().y());
  } else if (const auto* d = dynamic_cast<const DragDampingForce*>(&force)) {
    Element(out, "dragdamping").number("b", d->damping());
  } else if (const auto* v = dynamic_cast<const VortexForce*>(&force)) {
    Element(out, "vortexforce")
        .integer("i", v->i())
        .integer("j", v->j())
        .number("kbs", v->kbs())
        .number("kvc", v->kvc());
  }
  // The penalty force is written as the collision settings (checkForces).
}

/// The forces must be ones the format has, in its order, with the penalty force exactly the one
/// the collision settings make.
void checkForces(const Scene& scene) {
  const CollisionEntry& entry = collisionEntry(scene.collision.type);
  int previous = 0, penalties = 0;
  for (size_t k = 0; k < scene.forces.size(); ++k) {
    const Force& f = *scene.forces[k];
    const int rank = forceRank(f);
    const std::string which = "force " + std::to_string(k) + " (" + f.keyword() + ")";
    if (rank < 0) throw WriteError{which + ": the scene file format has no element for it"};
    if (rank < previous)
      throw WriteError{which + ": out of the format's order (springs, simple gravity, gravitational, constant, "
                               "drag, vortex, penalty); the loader would sum the forces in another order"};
    previous = rank;
    if (const auto* p = dynamic_cast<const PenaltyForce*>(&f)) {
      ++penalties;
      if (!entry.addsPenaltyForce)
        throw WriteError{which + ": collision type \"" + entry.keyword + "\" has no penalty force"};
      if (p->stiffness() != scene.collision.penaltyK || p->thickness() != scene.collision.penaltyThickness)
        throw WriteError{which + ": k = " + formatNumber(p->stiffness()) +
                         ", thickness = " + formatNumber(p->thickness()) +
                         " differ from the collision settings' k = " + formatNumber(scene.collision.penaltyK) +
                         ", thickness = " + formatNumber(scene.collision.penaltyThickness)};
    }
  }
  if (entry.addsPenaltyForce && penalties != 1)
    throw WriteError{"collision type \"" + std::string(entry.keyword) +
                     "\" needs exactly one penalty force, the scene has " + std::to_string(penalties)};
}

void writeScene(std::string& out, const SceneFile& file) {
  const Scene& scene = file.scene;
  const State& initial = file.initial;
  const int n = scene.numParticles();
  if (initial.x.size() != 2 * n || initial.v.size() != 2 * n || scene.mass.size() != 2 * n ||
      static_cast<int>(scene.fixed.size()) != n)
    throw WriteError{"the initial state or the masses do not have 2 entries per particle (" + std::to_string(n) +
                     " particles)"};
  checkForces(scene);

  out += "<scene>\n";
  if (!file.description.empty()) Element(out, "description").text("text", file.description);
  if (!file.tag.empty()) Element(out, "scenetag").text("tag", file.tag);
  Element(out, "duration").number("time", scene.duration);
  Element(out, "integrator").text("type", scene.integrator).number("dt", scene.dt);
  const CollisionSettings& c = scene.collision;
  Element(out, "collision")
      .text("type", collisionKeyword(c.type))
      .number("COR", c.cor)
      .integer("maxiters", c.maxIterations)
      .text("failsafe", c.failsafe == Failsafe::Rigid ? "rigid" : "projection")
      .number("k", c.penaltyK)
      .number("thickness", c.penaltyThickness);

  const Appearance& look = file.look;
  if (look.maxSimFreq != Appearance{}.maxSimFreq) Element(out, "maxsimfreq").number("max", look.maxSimFreq);
  if (look.viewport)
    Element(out, "viewport").number("cx", look.viewport->cx).number("cy", look.viewport->cy)
        .number("size", look.viewport->size);
  if (!sameRgb(look.background, Appearance{}.background)) Element(out, "backgroundcolor").rgb(look.background);

  for (int i = 0; i < n; ++i)
    Element(out, "particle")
        .number("m", scene.massOf(i))
        .number("px", initial.x[2 * i])
        .number("py", initial.x[2 * i + 1])
        .number("vx", initial.v[2 * i])
        .number("vy", initial.v[2 * i + 1])
        .integer("fixed", scene.isFixed(i) ? 1 : 0)
        .number("radius", scene.radius[i]);
  for (const Edge& e : scene.edges) Element(out, "edge").integer("i", e.i).integer("j", e.j).number("radius", e.radius);
  for (const HalfPlane& h : scene.halfplanes)
    Element(out, "halfplane").number("px", h.point.x()).number("py", h.point.y()).number("nx", h.normal.x())
        .number("ny", h.normal.y());
  for (size_t k = 0; k < scene.forces.size(); ++k) writeForce(out, scene, *scene.forces[k], k);

  // Colours that differ from the defaults the loader fills in.
  for (size_t i = 0; i < look.particleColors.size(); ++i)
    if (!sameRgb(look.particleColors[i], kDefaultParticleColor))
      Element(out, "particlecolor").integer("i", static_cast<long>(i)).rgb(look.particleColors[i]);
  for (size_t i = 0; i < look.edgeColors.size(); ++i)
    if (!sameRgb(look.edgeColors[i], kDefaultEdgeColor))
      Element(out, "edgecolor").integer("i", static_cast<long>(i)).rgb(look.edgeColors[i]);
  for (size_t i = 0; i < look.halfplaneColors.size(); ++i)
    if (!sameRgb(look.halfplaneColors[i], kDefaultHalfplaneColor))
      Element(out, "halfplanecolor").integer("i", static_cast<long>(i)).rgb(look.halfplaneColors[i]);
  for (const ParticlePath& p : look.paths)
    Element(out, "particlepath").integer("i", p.particle).number("duration", p.duration).rgb(p.color);
  out += "</scene>\n";
}

}  // namespace

std::string formatNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  // Without a format argument to_chars gives the shortest text that reads back to the same value.
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

Status sceneToXml(const SceneFile& file, std::string& out) {
  out.clear();
  try {
    writeScene(out, file);
  } catch (const WriteError& e) {
    out.clear();
    return Status::error("cannot write the scene: " + e.message);
  }
  return Status::ok();
}

Status writeScene(const std::string& path, const SceneFile& file) {
  std::string text;
  if (Status s = sceneToXml(file, text); !s) return Status::error(path + ": " + s.message());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) return Status::error(path + ": cannot create the scene file (" + std::strerror(errno) + ")");
  out << text;
  out.close();
  if (!out) return Status::error(path + ": cannot write the scene file (" + std::strerror(errno) + ")");
  return Status::ok();
}

}  // namespace fosssim
