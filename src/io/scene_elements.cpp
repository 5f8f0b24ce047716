// The element table and one function per element. A reader takes its attributes through the
// ElementReader, which checks them as the table declares (kind, default, bound); what only the
// element knows (a known integrator, two different particles) is checked here.
#include "scene_elements.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"
#include "fosssim/core/integrator.h"
#include "xml_reader.h"
#include "xml_syntax.h"

#include <algorithm>
#include <cmath>

namespace fosssim::io {
namespace {

Vec2 readVec(ElementReader& r, const char* a, const char* b) { return Vec2(r.number(a), r.number(b)); }

Rgb readRgb(ElementReader& r) { return Rgb{r.number("r"), r.number("g"), r.number("b")}; }

IndexRef readIndex(ElementReader& r, const char* name) { return IndexRef{r.index(name), r.line(), r.where(name)}; }

template <class Table>
std::string keywords(const Table& table) {
  std::string valid;
  for (const auto& e : table) valid += (valid.empty() ? "" : ", ") + std::string(e.keyword);
  return valid;
}

/// What is wrong with an unknown keyword `value` (a `what`: "integrator"), one of `valid`
/// (isValid tells). Numbers may have spaces around them, keywords are compared as written (as the
/// trajectory tools in oracle/ compare them): a keyword with spaces around it was refused as
/// unknown, though it looked right; the message says so.
std::string unknownKeyword(const std::string& what, const std::string& value, const std::string& valid,
                           bool (*isValid)(const std::string&)) {
  const std::string word = trimXmlSpace(value);
  if (word == value) return "unknown " + what + " \"" + clip(value) + "\" (valid: " + valid + ")";
  const bool before = value.find_first_not_of(kXmlSpace) != 0,
             after = value.find_last_not_of(kXmlSpace) + 1 != value.size();
  return what + " \"" + clip(value) + "\" has white space " +
         (before && after ? "around it"
          : before        ? "before it"
                          : "after it") +
         ": keywords are read as written (only numbers may have spaces around them); " +
         (isValid(word) ? "write \"" + clip(word) + "\"" : "valid: " + valid);
}

bool isSimtype(const std::string& type) { return type == "particle-system"; }
bool isIntegrator(const std::string& type) { return findIntegrator(type) != nullptr; }
bool isCollisionType(const std::string& type) { return findCollisionType(type) != nullptr; }
bool isFailsafe(const std::string& type) { return type == "projection" || type == "rigid"; }

void readSimtype(ElementReader& r, Builder&) {
  const std::string type = r.text("type");
  if (type != "particle-system") {
    if (trimXmlSpace(type) == type)
      r.fail("type", "simulation type \"" + clip(type) + "\" is not supported (valid: particle-system)");
    else
      r.fail("type", unknownKeyword("simulation type", type, "particle-system", isSimtype));
  }
}

void readDescription(ElementReader& r, Builder& b) { b.out.description = r.text("text"); }

void readSceneTag(ElementReader& r, Builder& b) { b.out.tag = r.text("tag"); }

void readDuration(ElementReader& r, Builder& b) {
  b.out.scene.duration = r.number("time");
  b.durationOk = r.ok();
  b.sawDuration = true;
}

void readIntegrator(ElementReader& r, Builder& b) {
  const std::string type = r.text("type");
  if (r.has("type") && !findIntegrator(type))
    r.fail("type", unknownKeyword("integrator", type, keywords(integratorTable()), isIntegrator));
  b.out.scene.integrator = findIntegrator(type) ? type : integratorTable().front().keyword;
  b.out.scene.dt = r.number("dt");
  b.integratorOk = r.ok();
  b.sawIntegrator = true;
  b.integratorLine = r.line();
  b.integratorWhere = r.where();
}

void readMaxSimFreq(ElementReader& r, Builder& b) { b.out.look.maxSimFreq = r.number("max"); }

void readViewport(ElementReader& r, Builder& b) {
  b.out.look.viewport = Viewport{r.number("cx"), r.number("cy"), r.number("size")};
}

void readBackground(ElementReader& r, Builder& b) { b.out.look.background = readRgb(r); }

void readParticle(ElementReader& r, Builder& b) {
  ParticleSpec p;
  p.mass = r.number("m");
  const Vec2 x = readVec(r, "px", "py"), v = readVec(r, "vx", "vy");
  p.fixed = r.flag("fixed");
  p.radius = r.number("radius");
  // The course simulator moves a fixed particle at the velocity it starts with; the default
  // mode's continuous-time and hybrid handling refuse one (EventHandler::fixedAtRest), at run
  // time, where this line is no longer known. Only of values read: a velocity already reported
  // (missing, not a number) holds a placeholder, no velocity.
  if (r.ok() && p.fixed && v != Vec2::Zero())
    b.messages.warn(r.line(), "moving fixed particle", "moving fixed particles",
                    r.where(v.x() != 0.0 ? "vx" : "vy") +
                        ": a fixed particle with a velocity moves at it, as in the course simulator (--compat); "
                        "the default mode's continuous-time and hybrid handling stop at its first step");
  b.particles.push_back(p);
  b.positions.insert(b.positions.end(), {x.x(), x.y()});
  b.velocities.insert(b.velocities.end(), {v.x(), v.y()});
}

void readEdge(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i"), j = readIndex(r, "j");
  if (i.value >= 0 && i.value == j.value)
    r.fail("j", "an edge needs two different particles, got i = j = " + std::to_string(i.value));
  b.out.scene.edges.push_back(Edge{i.value, j.value, r.number("radius")});
  b.edgeEnds.emplace_back(std::move(i), std::move(j));
}

void readHalfplane(ElementReader& r, Builder& b) {
  HalfPlane h{readVec(r, "px", "py"), readVec(r, "nx", "ny")};
  if (r.ok() && h.normal.x() == 0.0 && h.normal.y() == 0.0)
    r.fail("nx", "the half-plane normal (nx, ny) must not be zero");
  // The normal need not be a unit vector, and the core takes its length as sqrt(nx^2 + ny^2):
  // beyond about 1e154 the square overflows (every distance became 0 or NaN and particles fell
  // through), below about 1e-154 it is subnormal or 0 (imprecise, or "must not be zero" for a
  // normal that is not). Scaling by a power of two is exact and keeps the direction, so such a
  // normal is brought to a largest component in [1, 2); any other is kept as written.
  if (r.ok() && !std::isnormal(h.normal.squaredNorm())) {
    const int exponent = std::ilogb(h.normal.cwiseAbs().maxCoeff());
    h.normal = Vec2(std::ldexp(h.normal.x(), -exponent), std::ldexp(h.normal.y(), -exponent));
  }
  b.out.scene.halfplanes.push_back(h);
}

void readSpring(ElementReader& r, Builder& b) {
  IndexRef edge = readIndex(r, "edge");
  const double k = r.number("k"), l0 = r.number("l0"), damping = r.number("b");
  b.springs.push_back(SpringSpec{std::move(edge), k, l0, damping});
}

void readSimpleGravity(ElementReader& r, Builder& b) {
  b.gravity.push_back(std::make_unique<SimpleGravityForce>(readVec(r, "fx", "fy")));
}

void readConstantForce(ElementReader& r, Builder& b) {
  b.constant.push_back(std::make_unique<ConstantForce>(readVec(r, "fx", "fy")));
}

void readDragDamping(ElementReader& r, Builder& b) {
  b.drag.push_back(std::make_unique<DragDampingForce>(r.number("b")));
}

PairForceSpec readPairEnds(ElementReader& r) {
  PairForceSpec spec{readIndex(r, "i"), readIndex(r, "j")};
  if (spec.i.value >= 0 && spec.i.value == spec.j.value)
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
  const std::string type = r.text("type");
  const CollisionEntry* entry = findCollisionType(type);
  if (!entry) {
    if (r.has("type"))
      r.fail("type", unknownKeyword("collision type", type, keywords(collisionTable()), isCollisionType));
    entry = &collisionTable().front();
  }
  c.type = entry->type;
  c.cor = r.number("COR");
  // The reference reads maxiters as a number and truncates it.
  c.maxIterations = static_cast<int>(std::max(r.number("maxiters"), -1.0));
  const std::string failsafe = r.text("failsafe");
  if (failsafe == "projection") c.failsafe = Failsafe::Projection;
  else if (failsafe == "rigid") c.failsafe = Failsafe::Rigid;
  else r.fail("failsafe", unknownKeyword("failsafe", failsafe, "projection, rigid", isFailsafe));
  c.penaltyK = r.number("k", entry->defaultK);
  c.penaltyThickness = r.number("thickness", entry->defaultThickness);
  b.collisionOk = r.ok();
}

template <std::vector<Indexed<Rgb>> Builder::*colors>
void readColor(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i");
  (b.*colors).push_back({std::move(i), readRgb(r)});
}

void readParticlePath(ElementReader& r, Builder& b) {
  IndexRef i = readIndex(r, "i");
  ParticlePath path;
  path.duration = r.number("duration");
  path.color = readRgb(r);
  b.paths.push_back({std::move(i), path});
}

// Attribute declarations shared by several elements.
AttributeSpec channel(const char* name, const char* example, const char* fallback = nullptr) {
  return {name, Kind::Fraction, "", fallback,
          name[0] == 'r' ? "red, from 0 to 1" : name[0] == 'g' ? "green, from 0 to 1" : "blue, from 0 to 1", example};
}

AttributeSpec particleIndex(const char* name, const char* meaning, const char* example) {
  return {name, Kind::Index, "", nullptr, meaning, example};
}

}  // namespace

const AttributeSpec* ElementSpec::attribute(const std::string& attributeName) const {
  for (const AttributeSpec& a : attributes)
    if (attributeName == a.name) return &a;
  return nullptr;
}

// The table is laid out by hand, an element's name, section, rule and summary on one line:
// clang-format would put each of those on a line of its own.
// clang-format off
const std::vector<ElementSpec>& elementTable() {
  static const std::vector<ElementSpec> table = {
      // --- the run -----------------------------------------------------------------------------
      {"duration", "The run", true, Repeat::FirstCounts,
       "How long the simulation runs; it takes ceil(time / dt) steps.",
       {{"time", Kind::NonNegative, "s", nullptr, "simulated time", "2.0"}},
       readDuration},
      {"integrator", "The run", true, Repeat::FirstCounts, "The time integrator and its time step.",
       {{"type", Kind::Text, "", nullptr, "one of the integrators listed below", "symplectic-euler"},
        {"dt", Kind::Positive, "s", nullptr, "the time step", "0.01"}},
       readIntegrator},
      {"collision", "The run", false, Repeat::FirstCounts,
       "How collisions are detected and resolved (without it: none). The settings a type does not use are read "
       "and ignored.",
       {{"type", Kind::Text, "", nullptr, "one of the collision types listed below", "hybrid"},
        {"COR", Kind::Fraction, "", "1",
         "coefficient of restitution: 1 elastic, 0 no bounce; in the default mode's continuous-time and hybrid "
         "impulses, below 1, resting contact (closing no faster than twice the step's kicks along its normal, at "
         "least a quarter of that closing new in the step) does not bounce",
         "0.5"},
        {"maxiters", Kind::Number, "", "10",
         "hybrid: impulse passes per step (with --compat) or impulses per particle per step (default mode) "
         "before the failsafe takes over; read as a number and truncated; 0 or less: the failsafe at once",
         "10", kMaxCollisionIterations, kMaxCollisionIterationsReason},
        {"failsafe", Kind::Text, "", "projection",
         "hybrid and continuous-time, default mode: projection (projection of impact zones, with the COR's "
         "restitution for hits) or rigid (the course's rigid zones); --compat always uses rigid zones",
         "projection"},
        {"k", Kind::NonNegative, "N/m", "(by type: the table below)", "stiffness of the penalty force", "10"},
        {"thickness", Kind::NonNegative, "m", "(by type: the table below)",
         "the penalty force acts on pairs closer than their radii plus this", "0.1"}},
       readCollision},
      {"simtype", "The run", false, Repeat::LastCounts, "The kind of simulation; only particle systems exist.",
       {{"type", Kind::Text, "", "particle-system", "particle-system", "particle-system"}},
       readSimtype},
      {"description", "The run", false, Repeat::LastCounts,
       "A sentence about the scene, printed when it starts (not with -q).",
       {{"text", Kind::Text, "", nullptr, "the description", "A ball bounces on a floor."}},
       readDescription},
      {"scenetag", "The run", false, Repeat::LastCounts, "A name for the scene (kept, not used by FOSSSim).",
       {{"tag", Kind::Text, "", nullptr, "the name", "bounce"}},
       readSceneTag},
      // --- bodies ------------------------------------------------------------------------------
      {"particle", "Bodies", true, Repeat::Adds,
       "A disk. Particles are numbered from 0 in file order; at least one is required.",
       {{"m", Kind::Positive, "kg", nullptr, "mass", "1"},
        {"px", Kind::Number, "m", nullptr, "initial position, x", "0"},
        {"py", Kind::Number, "m", nullptr, "initial position, y", "1"},
        {"vx", Kind::Number, "m/s", nullptr, "initial velocity, x", "0"},
        {"vy", Kind::Number, "m/s", nullptr, "initial velocity, y", "0"},
        {"fixed", Kind::Flag, "", nullptr,
         "1: forces and collisions leave it; it keeps its initial velocity (the course simulator moves it at that "
         "velocity; the default mode's continuous-time and hybrid handling need it 0)",
         "0"},
        {"radius", Kind::Positive, "m", "0.1", "disk radius (collisions and pictures)", "0.1"}},
       readParticle},
      {"edge", "Bodies", false, Repeat::Adds,
       "A capsule between two particles (the points within radius of the segment). Edges are numbered from 0 in "
       "file order.",
       {particleIndex("i", "first particle", "0"), particleIndex("j", "second particle, not i", "1"),
        {"radius", Kind::Positive, "m", "0.015", "capsule radius", "0.015"}},
       readEdge},
      {"halfplane", "Bodies", false, Repeat::Adds,
       "A fixed wall: everything on the side the normal points to is free space. Half-planes are numbered from 0 "
       "in file order.",
       {{"px", Kind::Number, "m", nullptr, "a point on the boundary, x", "0"},
        {"py", Kind::Number, "m", nullptr, "a point on the boundary, y", "0"},
        {"nx", Kind::Number, "", nullptr, "normal (need not be a unit vector; not zero), x", "0"},
        {"ny", Kind::Number, "", nullptr, "normal, y", "1"}},
       readHalfplane},
      // --- forces ------------------------------------------------------------------------------
      {"springforce", "Forces", false, Repeat::Adds,
       "A spring along an edge: energy k/2 (l - l0)^2, plus damping b along the edge. The edge's two particles "
       "may not start at one point (the spring would have no direction) unless both are fixed.",
       {{"edge", Kind::Index, "", nullptr, "the edge it acts along", "0"},
        {"k", Kind::NonNegative, "N/m", nullptr, "stiffness", "100"},
        {"l0", Kind::NonNegative, "m", nullptr, "rest length", "1"},
        {"b", Kind::NonNegative, "N s/m", "0", "damping", "0.5"}},
       readSpring},
      {"simplegravity", "Forces", false, Repeat::Adds, "Uniform gravity: the force m g on every particle.",
       {{"fx", Kind::Number, "m/s^2", nullptr, "acceleration g, x", "0"},
        {"fy", Kind::Number, "m/s^2", nullptr, "acceleration g, y", "-9.81"}},
       readSimpleGravity},
      {"constantforce", "Forces", false, Repeat::Adds, "The same force f on every particle, whatever its mass.",
       {{"fx", Kind::Number, "N", nullptr, "force, x", "1"}, {"fy", Kind::Number, "N", nullptr, "force, y", "0"}},
       readConstantForce},
      {"gravitationalforce", "Forces", false, Repeat::Adds,
       "Newtonian attraction between two particles: energy -G m_i m_j / r.",
       {particleIndex("i", "first particle", "0"), particleIndex("j", "second particle, not i", "1"),
        {"G", Kind::Number, "N m^2/kg^2", nullptr, "gravitational constant", "1"}},
       readGravitational},
      {"dragdamping", "Forces", false, Repeat::Adds, "Drag: the force -b v on every particle.",
       {{"b", Kind::NonNegative, "N s/m", nullptr, "drag coefficient", "0.1"}},
       readDragDamping},
      {"vortexforce", "Forces", false, Repeat::Adds,
       "A vortex: particle j circles particle i. With r = x_j - x_i: F_j = kvc/|r|^2 (kbs perp(r/|r|) - (v_j - v_i)), "
       "F_i = -F_j. No energy, no Jacobian: implicit integrators treat it explicitly.",
       {particleIndex("i", "the centre particle", "0"), particleIndex("j", "the circling particle, not i", "1"),
        {"kbs", Kind::Number, "m/s", nullptr, "swirl speed", "1"},
        {"kvc", Kind::Number, "m^2/s", nullptr, "strength (viscous coupling)", "1"}},
       readVortex},
      // --- display -----------------------------------------------------------------------------
      {"viewport", "Display (the physics never reads these)", false, Repeat::FirstCounts,
       "The camera. Without it the view fits the particles.",
       {{"cx", Kind::Number, "m", nullptr, "centre, x", "0"},
        {"cy", Kind::Number, "m", nullptr, "centre, y", "0"},
        {"size", Kind::Positive, "m", nullptr, "half the height of the visible world", "1.5"}},
       readViewport},
      {"maxsimfreq", "Display (the physics never reads these)", false, Repeat::LastCounts,
       "The window's speed limit, in steps per wall-clock second (headless runs ignore it).",
       {{"max", Kind::Positive, "1/s", nullptr, "steps per second (without the element: 100)", "100"}},
       readMaxSimFreq},
      {"backgroundcolor", "Display (the physics never reads these)", false, Repeat::LastCounts,
       "The background colour (without it: white).",
       {channel("r", "1"), channel("g", "1"), channel("b", "1")},
       readBackground},
      {"particlecolor", "Display (the physics never reads these)", false, Repeat::Adds,
       "The colour of one particle (default 0.65 0.29 0, brown); the last one given for a particle counts.",
       {particleIndex("i", "the particle", "0"), channel("r", "0.2"), channel("g", "0.4"), channel("b", "0.8")},
       readColor<&Builder::particleColors>},
      {"edgecolor", "Display (the physics never reads these)", false, Repeat::Adds,
       "The colour of one edge (default 0 0.39 0.39, teal); the last one given for an edge counts.",
       {{"i", Kind::Index, "", nullptr, "the edge", "0"}, channel("r", "0"), channel("g", "0"), channel("b", "0")},
       readColor<&Builder::edgeColors>},
      {"halfplanecolor", "Display (the physics never reads these)", false, Repeat::Adds,
       "The colour of one half-plane (default black); the last one given for a half-plane counts.",
       {{"i", Kind::Index, "", nullptr, "the half-plane", "0"}, channel("r", "0.5"), channel("g", "0.5"),
        channel("b", "0.5")},
       readColor<&Builder::halfplaneColors>},
      {"particlepath", "Display (the physics never reads these)", false, Repeat::Adds,
       "A trail behind a particle: its positions over the last duration seconds (ceil(duration / dt) of them, at "
       "most one per step of the run; 16 bytes each). The rules above bound all trails together.",
       {particleIndex("i", "the particle", "0"),
        {"duration", Kind::NonNegative, "s", nullptr, "trail length in time", "1"}, channel("r", "0.8"),
        channel("g", "0.3"), channel("b", "0.2")},
       readParticlePath},
  };
  return table;
}
// clang-format on

const ElementSpec* findElement(const std::string& name) {
  for (const ElementSpec& e : elementTable())
    if (name == e.name) return &e;
  return nullptr;
}

size_t mostAttributes() {
  size_t most = 0;
  for (const ElementSpec& e : elementTable()) most = std::max(most, e.attributes.size());
  return most;
}

}  // namespace fosssim::io
