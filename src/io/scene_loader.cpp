// The XML scene loader. One table maps every element of the format to the function that reads
// it; the loader walks the document once, then resolves cross references (indices may name
// elements that come later in the file), then assembles the Scene.
#include "fosssim/io/scene_file.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/integrator.h"
#include "input_path.h"
#include "xml_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>

namespace fosssim {
namespace {

using io::ElementReader;
using io::LoadError;

/// An index read from the file, checked once the counts are known.
struct IndexRef {
  int value;
  std::string where;  ///< "file:line: <element> attribute 'i'"
};

struct SpringSpec {
  IndexRef edge;
  double k, l0, b;
};

/// A force between two particles: gravitational (a = G) or vortex (a = kbs, b = kvc).
struct PairForceSpec {
  IndexRef i, j;
  double a = 0, b = 0;
};

template <class T>
struct Indexed {  // something that refers to a particle, edge or half-plane by index
  IndexRef ref;
  T value;
};

/// Everything read so far, before cross references are resolved.
struct Builder {
  explicit Builder(SceneFile& file) : out(file) {}
  SceneFile& out;
  std::vector<ParticleSpec> particles;
  std::vector<double> positions, velocities;  // 2 per particle
  std::vector<std::pair<IndexRef, IndexRef>> edgeEnds;
  std::vector<SpringSpec> springs;
  std::vector<std::unique_ptr<Force>> gravity, constant, drag;
  std::vector<PairForceSpec> gravitational, vortex;
  std::vector<Indexed<Rgb>> particleColors, edgeColors, halfplaneColors;
  std::vector<Indexed<ParticlePath>> paths;
  bool hasDuration = false, hasIntegrator = false;
  std::string integratorWhere;
  std::string collisionWhere;
};

Vec2 readVec(ElementReader& r, const char* a, const char* b) { return Vec2(r.number(a), r.number(b)); }

Rgb readRgb(ElementReader& r) { return Rgb{r.channel("r"), r.channel("g"), r.channel("b")}; }

IndexRef readIndex(ElementReader& r, const char* name) { return IndexRef{r.index(name), r.where(name)}; }

// --- one function per element --------------------------------------------------------------------

void readSimtype(ElementReader& r, Builder&) {
  const std::string type = r.text("type", "particle-system");
  if (type != "particle-system")
    r.fail("type", "simulation type \"" + type + "\" is not supported (valid: particle-system)");
}

void readDescription(ElementReader& r, Builder& b) { b.out.description = r.text("text"); }

void readSceneTag(ElementReader& r, Builder& b) { b.out.tag = r.text("tag"); }

void readDuration(ElementReader& r, Builder& b) {
  b.out.scene.duration = r.positive("time", /*allowZero=*/true);
  b.hasDuration = true;
}

void readIntegrator(ElementReader& r, Builder& b) {
  const std::string type = r.text("type");
  if (!findIntegrator(type)) {
    std::string valid;
    for (const auto& e : integratorTable()) valid += (valid.empty() ? "" : ", ") + std::string(e.keyword);
    r.fail("type", "unknown integrator \"" + type + "\" (valid: " + valid + ")");
  }
  b.out.scene.integrator = type;
  b.out.scene.dt = r.positive("dt");
  b.hasIntegrator = true;
  b.integratorWhere = r.where();
}

void readMaxSimFreq(ElementReader& r, Builder& b) { b.out.look.maxSimFreq = r.positive("max"); }

void readViewport(ElementReader& r, Builder& b) {
  b.out.look.viewport = Viewport{r.number("cx"), r.number("cy"), r.positive("size")};
}

void readBackground(ElementReader& r, Builder& b) { b.out.look.background = readRgb(r); }

void readParticle(ElementReader& r, Builder& b) {
  ParticleSpec p;
  p.mass = r.positive("m");
  const Vec2 x = readVec(r, "px", "py"), v = readVec(r, "vx", "vy");
  p.fixed = r.boolean("fixed");
  p.radius = r.positive("radius", 0.1);
  b.particles.push_back(p);
  b.positions.insert(b.positions.end(), {x.x(), x.y()});
  b.velocities.insert(b.velocities.end(), {v.x(), v.y()});
}

void readEdge(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i"), j = readIndex(r, "j");
  if (i.value == j.value) r.fail("j", "an edge needs two different particles, got i = j = " + std::to_string(i.value));
  b.out.scene.edges.push_back(Edge{i.value, j.value, r.positive("radius", Edge{}.radius)});
  b.edgeEnds.emplace_back(std::move(i), std::move(j));
}

void readHalfplane(ElementReader& r, Builder& b) {
  HalfPlane h{readVec(r, "px", "py"), readVec(r, "nx", "ny")};
  if (h.normal.squaredNorm() == 0.0) r.fail("nx", "the half-plane normal (nx, ny) must not be zero");
  b.out.scene.halfplanes.push_back(h);
}

void readSpring(ElementReader& r, Builder& b) {
  IndexRef edge = readIndex(r, "edge");
  const double k = r.positive("k", true), l0 = r.positive("l0", true), damping = r.positive("b", 0.0, true);
  b.springs.push_back(SpringSpec{std::move(edge), k, l0, damping});
}

void readSimpleGravity(ElementReader& r, Builder& b) {
  b.gravity.push_back(std::make_unique<SimpleGravityForce>(readVec(r, "fx", "fy")));
}

void readConstantForce(ElementReader& r, Builder& b) {
  b.constant.push_back(std::make_unique<ConstantForce>(readVec(r, "fx", "fy")));
}

void readDragDamping(ElementReader& r, Builder& b) {
  b.drag.push_back(std::make_unique<DragDampingForce>(r.positive("b", true)));
}

PairForceSpec readPairEnds(ElementReader& r) {
  PairForceSpec spec{readIndex(r, "i"), readIndex(r, "j")};
  if (spec.i.value == spec.j.value)
    r.fail("j", "the force needs two different particles, got i = j = " + std::to_string(spec.i.value));
  return spec;
}

void readGravitational(ElementReader& r, Builder& b) {
  PairForceSpec spec = readPairEnds(r);
  spec.a = r.number("G");
  b.gravitational.push_back(std::move(spec));
}

void readVortex(ElementReader& r, Builder& b) {
  PairForceSpec spec = readPairEnds(r);
  spec.a = r.number("kbs");
  spec.b = r.number("kvc");
  b.vortex.push_back(std::move(spec));
}

void readCollision(ElementReader& r, Builder& b) {
  CollisionSettings& c = b.out.scene.collision;
  c.type = r.text("type");
  const CollisionEntry* entry = findCollisionType(c.type);
  if (!entry) {
    std::string valid;
    for (const auto& e : collisionTable()) valid += (valid.empty() ? "" : ", ") + std::string(e.keyword);
    r.fail("type", "unknown collision type \"" + c.type + "\" (valid: " + valid + ")");
  }
  c.cor = r.number("COR", 1.0);
  if (c.cor < 0 || c.cor > 1) r.fail("COR", "the coefficient of restitution must lie in [0, 1]");
  // The reference reads maxiters as a number and truncates it.
  const double maxiters = r.number("maxiters", 10.0);
  if (std::fabs(maxiters) > 1e9) r.fail("maxiters", "is out of range");
  c.maxIterations = static_cast<int>(maxiters);
  const std::string failsafe = r.text("failsafe", "projection");
  if (failsafe == "projection") c.failsafe = Failsafe::Projection;
  else if (failsafe == "rigid") c.failsafe = Failsafe::Rigid;
  else r.fail("failsafe", "unknown failsafe \"" + failsafe + "\" (valid: projection, rigid)");
  c.penaltyK = r.positive("k", entry->defaultK, /*allowZero=*/true);
  c.penaltyThickness = r.positive("thickness", entry->defaultThickness, /*allowZero=*/true);
  b.collisionWhere = r.where();
}

void readParticleColor(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i");
  b.particleColors.push_back({std::move(i), readRgb(r)});
}

void readEdgeColor(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i");
  b.edgeColors.push_back({std::move(i), readRgb(r)});
}

void readHalfplaneColor(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i");
  b.halfplaneColors.push_back({std::move(i), readRgb(r)});
}

void readParticlePath(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i");
  ParticlePath path;
  path.duration = r.positive("duration", true);
  path.color = readRgb(r);
  b.paths.push_back({std::move(i), path});
}

struct ElementRule {
  const char* name;
  void (*read)(ElementReader&, Builder&);
  bool onlyFirstCounts;  ///< later occurrences are ignored, with a warning (the reference's rule)
};

/// Every element of the scene format.
const std::vector<ElementRule>& elementTable() {
  static const std::vector<ElementRule> table = {
      {"simtype", readSimtype, false},
      {"description", readDescription, false},
      {"scenetag", readSceneTag, false},
      {"duration", readDuration, true},
      {"integrator", readIntegrator, true},
      {"maxsimfreq", readMaxSimFreq, false},
      {"viewport", readViewport, true},
      {"backgroundcolor", readBackground, false},
      {"particle", readParticle, false},
      {"edge", readEdge, false},
      {"halfplane", readHalfplane, false},
      {"springforce", readSpring, false},
      {"simplegravity", readSimpleGravity, false},
      {"constantforce", readConstantForce, false},
      {"gravitationalforce", readGravitational, false},
      {"dragdamping", readDragDamping, false},
      {"vortexforce", readVortex, false},
      {"collision", readCollision, true},
      {"particlecolor", readParticleColor, false},
      {"edgecolor", readEdgeColor, false},
      {"halfplanecolor", readHalfplaneColor, false},
      {"particlepath", readParticlePath, false},
  };
  return table;
}

void checkIndex(const IndexRef& ref, size_t count, const char* what) {
  if (ref.value >= static_cast<long>(count))
    throw LoadError(ref.where + ": " + what + " " + std::to_string(ref.value) + " does not exist (the scene has " +
                    std::to_string(count) + " " + what + (count == 1 ? "" : "s") + ")");
}

/// Resolves indices and builds the Scene, State and Appearance.
void assemble(Builder& b, const std::string& file) {
  SceneFile& out = b.out;
  Scene& scene = out.scene;
  if (!b.hasIntegrator) throw LoadError(file + ": the scene has no <integrator type=... dt=...> element (required)");
  if (!b.hasDuration) throw LoadError(file + ": the scene has no <duration time=...> element (required)");
  // A run longer than this many steps is certainly a typo (and would overflow step counters).
  constexpr double kMaxSteps = 1e12;
  if (!(scene.duration / scene.dt <= kMaxSteps))
    throw LoadError(b.integratorWhere + ": duration / dt asks for more than 1e12 steps");

  const size_t n = b.particles.size(), edges = scene.edges.size(), planes = scene.halfplanes.size();
  // Nothing to simulate, and trajectory records of no particles (and no impulses) have no bytes,
  // so a file of them could not be read back.
  if (n == 0) throw LoadError(file + ": the scene has no <particle> elements (at least one is required)");
  addParticles(scene, b.particles);
  out.initial.x = Eigen::Map<const VecX>(b.positions.data(), static_cast<Eigen::Index>(b.positions.size()));
  out.initial.v = Eigen::Map<const VecX>(b.velocities.data(), static_cast<Eigen::Index>(b.velocities.size()));
  for (const auto& [i, j] : b.edgeEnds) checkIndex(i, n, "particle"), checkIndex(j, n, "particle");

  // Forces in the reference's summation order.
  for (const SpringSpec& s : b.springs) {
    checkIndex(s.edge, edges, "edge");
    const Edge& e = scene.edges[s.edge.value];
    scene.forces.push_back(std::make_unique<SpringForce>(e.i, e.j, s.k, s.l0, s.b));
  }
  for (auto& f : b.gravity) scene.forces.push_back(std::move(f));
  for (const PairForceSpec& f : b.gravitational) {
    checkIndex(f.i, n, "particle"), checkIndex(f.j, n, "particle");
    scene.forces.push_back(std::make_unique<GravitationalForce>(f.i.value, f.j.value, f.a));
  }
  for (auto& f : b.constant) scene.forces.push_back(std::move(f));
  for (auto& f : b.drag) scene.forces.push_back(std::move(f));
  for (const PairForceSpec& f : b.vortex) {
    checkIndex(f.i, n, "particle"), checkIndex(f.j, n, "particle");
    scene.forces.push_back(std::make_unique<VortexForce>(f.i.value, f.j.value, f.a, f.b));
  }
  const CollisionEntry* collision = findCollisionType(scene.collision.type);
  if (collision && collision->addsPenaltyForce)
    scene.forces.push_back(std::make_unique<PenaltyForce>(scene.collision.penaltyK, scene.collision.penaltyThickness));

  // Appearance: defaults, then the file's colours.
  Appearance& look = out.look;
  look.particleColors.assign(n, kDefaultParticleColor);
  look.edgeColors.assign(edges, kDefaultEdgeColor);
  look.halfplaneColors.assign(planes, kDefaultHalfplaneColor);
  for (const auto& c : b.particleColors) checkIndex(c.ref, n, "particle"), look.particleColors[c.ref.value] = c.value;
  for (const auto& c : b.edgeColors) checkIndex(c.ref, edges, "edge"), look.edgeColors[c.ref.value] = c.value;
  for (const auto& c : b.halfplaneColors)
    checkIndex(c.ref, planes, "half-plane"), look.halfplaneColors[c.ref.value] = c.value;
  for (auto& p : b.paths) {
    checkIndex(p.ref, n, "particle");
    p.value.particle = p.ref.value;
    look.paths.push_back(p.value);
  }

  const IntegratorEntry* integrator = findIntegrator(scene.integrator);
  if (integrator->implicit)
    for (const auto& f : scene.forces)
      if (!f->hasJacobians())
        out.warnings.push_back(b.integratorWhere + ": " + f->keyword() +
                               " provides no Jacobian; the implicit integrator treats it explicitly");
}

}  // namespace

Status parseScene(const std::string& text, const std::string& name, SceneFile& out) {
  out = SceneFile{};
  out.path = name;
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLError parsed = doc.Parse(text.data(), text.size());
  if (parsed == tinyxml2::XML_ERROR_EMPTY_DOCUMENT)
    return Status::error(name + ": the file is empty (expected an XML document with root <scene>)");
  if (parsed != tinyxml2::XML_SUCCESS) {
    std::string detail = doc.ErrorStr() ? doc.ErrorStr() : "malformed XML";
    return Status::error(name + ":" + std::to_string(doc.ErrorLineNum()) + ": not well-formed XML: " + detail);
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) return Status::error(name + ": the file holds no XML element (expected <scene>)");
  if (std::string(root->Name()) != "scene")
    return Status::error(name + ":" + std::to_string(root->GetLineNum()) + ": the root element is <" +
                         root->Name() + ">, expected <scene>");
  if (root->NextSiblingElement())
    return Status::error(name + ":" + std::to_string(root->NextSiblingElement()->GetLineNum()) +
                         ": unexpected element <" + root->NextSiblingElement()->Name() + "> after </scene>");
  try {
    Builder builder(out);
    std::vector<std::string> seen;
    for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
      ElementReader reader(*e, name);
      const ElementRule* rule = nullptr;
      for (const auto& r : elementTable())
        if (std::string(r.name) == e->Name()) rule = &r;
      if (!rule) {
        std::string valid;
        for (const auto& r : elementTable()) valid += (valid.empty() ? "" : ", ") + std::string(r.name);
        out.warnings.push_back(reader.where() + ": unknown element ignored (valid: " + valid + ")");
        continue;
      }
      if (rule->onlyFirstCounts) {
        if (std::find(seen.begin(), seen.end(), rule->name) != seen.end()) {
          out.warnings.push_back(reader.where() + ": ignored, only the first <" + rule->name + "> counts");
          continue;
        }
        seen.emplace_back(rule->name);
      }
      rule->read(reader, builder);
      for (const auto& a : reader.unknownAttributes())
        out.warnings.push_back(reader.where(a.c_str()) + ": unknown attribute ignored (valid: " +
                               reader.knownAttributes() + ")");
    }
    assemble(builder, name);
  } catch (const LoadError& e) {
    return Status::error(e.what());
  }
  return Status::ok();
}

Status loadScene(const std::string& path, SceneFile& out) {
  out = SceneFile{};
  out.path = path;
  if (Status st = io_detail::checkInputPath(path, "scene file"); !st) return st;
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::error(path + ": cannot open the scene file (" + std::strerror(errno) + ")");
  // Read in chunks up to a limit, so that a device such as /dev/zero cannot exhaust the memory.
  constexpr std::streamsize kMaxBytes = 256 << 20, kChunk = 1 << 16;
  std::string text;
  while (in) {
    const size_t used = text.size();
    text.resize(used + kChunk);
    in.read(&text[used], kChunk);
    text.resize(used + static_cast<size_t>(in.gcount()));
    if (static_cast<std::streamsize>(text.size()) > kMaxBytes)
      return Status::error(path + ": the scene file is larger than 256 MiB; is it a scene file?");
  }
  if (in.bad()) return Status::error(path + ": cannot read the scene file (" + std::strerror(errno) + ")");
  return parseScene(text, path, out);
}

}  // namespace fosssim
