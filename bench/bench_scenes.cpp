#include "bench_scenes.h"

#include "fosssim/core/collision_handler.h"
#include "fosssim/core/forces.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace fosssim::bench {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStep = 0.005;  ///< dt of every scene (the Box2D comparison's)

/// What every scene shares besides its bodies.
struct Setup {
  double cor = 0.5;
  double gravity = -9.81;
  long steps = 200;
  double thickness = 0.005;  ///< penalty thickness: a tenth of the disks' radius
  double k = 10;             ///< penalty stiffness (the scene format's hybrid default)
  int maxIterations = 10;    ///< hybrid impulse passes (the scene format's default)
};

class Builder {
 public:
  Builder(BenchScene& s, unsigned seed) : s_(s), rng_(seed) {}
  /// Every scene calls this once a statement (x's jitter before y's): two calls in one expression,
  /// as in Vec2(uniform(...), uniform(...)), come in an order the compiler picks (gcc right to left,
  /// clang left to right), and a seed must give the same scene under both.
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int add(double m, Vec2 x, Vec2 v, double r, bool fixed = false) {
    addParticle(s_.scene, m, fixed, r);
    return s_.state.addParticle(x, v);
  }
  void plane(Vec2 point, Vec2 normal) { s_.scene.halfplanes.push_back(HalfPlane{point, normal}); }
  void link(int i, int j, double radius, double k, double l0, double damping) {
    s_.scene.edges.push_back(Edge{i, j, radius});
    if (k == 0) return;
    s_.scene.forces.push_back(std::make_unique<SpringForce>(i, j, k, l0, damping));
  }
  void finish(const std::string& collision, const Setup& setup) {
    Scene& scene = s_.scene;
    scene.integrator = "symplectic-euler";
    scene.dt = kStep;
    scene.duration = static_cast<double>(setup.steps) * kStep;
    scene.collision.type = findCollisionType(collision)->type;
    scene.collision.cor = setup.cor;
    scene.collision.maxIterations = setup.maxIterations;
    // Forces in the loader's order: springs (already added), gravity, then the penalty force.
    s_.gravity = setup.gravity;
    if (setup.gravity != 0) scene.forces.push_back(std::make_unique<SimpleGravityForce>(Vec2(0, setup.gravity)));
    scene.collision.penaltyK = setup.k;
    scene.collision.penaltyThickness = setup.thickness;
    finalizeScene(scene);  // the penalty force, when the collision type has one
  }

 private:
  BenchScene& s_;
  std::mt19937 rng_;
};

/// n unit disks of radius 0.05 on a square grid of pitch 2.5 r over a V of two half-planes at
/// 45 degrees, the lowest row 4 radii above the V's arms at the grid's edges plus `lift`; each
/// start moved by up to `jitterShare` of the gap between neighbours (below 0.5, neighbours cannot
/// start overlapping). A perfect lattice falls as a block and stacks in columns, which flatters any
/// method; a jittered one has to pile up.
void jitteredGridOverV(Builder& b, int n, double jitterShare, bool liftByHeight) {
  const double r = 0.05, spacing = 2.5 * r;
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const int rows = (n + columns - 1) / columns;
  const double width = (columns - 1) * spacing, height = (rows - 1) * spacing;
  const double bottom = 0.5 * width + 4 * r + (liftByHeight ? height : 0.0);
  const double jitter = jitterShare * (spacing - 2 * r);
  for (int k = 0; k < n; ++k) {
    const double dx = b.uniform(-jitter, jitter);
    const double dy = b.uniform(-jitter, jitter);
    b.add(1.0, Vec2(-0.5 * width + (k % columns) * spacing + dx, bottom + (k / columns) * spacing + dy), Vec2::Zero(),
          r);
  }
  b.plane(Vec2(0, 0), Vec2(1, 1));
  b.plane(Vec2(0, 0), Vec2(-1, 1));
}

void rain(Builder& b, int n, Setup& setup) {
  jitteredGridOverV(b, n, 0.2, false);  // the lowest row starts inside the V
  setup.cor = 0.0;
  setup.steps = 400;
}

void gas(Builder& b, int n, Setup& setup) {
  const double r = 0.05;
  const double spacing = std::sqrt(kPi * r * r / 0.1);  // 10% of the box covered
  const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
  const double side = columns * spacing, jitter = 0.45 * (spacing - 2 * r);
  for (int k = 0; k < n; ++k) {
    const Vec2 cell(-0.5 * side + (k % columns + 0.5) * spacing, -0.5 * side + (k / columns + 0.5) * spacing);
    const double angle = b.uniform(0, 2 * kPi), speed = b.uniform(0.0, 1.0);
    const double dx = b.uniform(-jitter, jitter);
    const double dy = b.uniform(-jitter, jitter);
    b.add(1.0, cell + Vec2(dx, dy), speed * Vec2(std::cos(angle), std::sin(angle)), r);
  }
  const double half = 0.5 * side;
  b.plane(Vec2(0, -half), Vec2(0, 1));
  b.plane(Vec2(0, half), Vec2(0, -1));
  b.plane(Vec2(-half, 0), Vec2(1, 0));
  b.plane(Vec2(half, 0), Vec2(-1, 0));
  setup.cor = 1.0;
  setup.gravity = 0;
  setup.steps = 200;
}

void chains(Builder& b, const BenchScene& s, int n, Setup& setup) {
  const int links = 10;
  const double r = 0.03, spacing = 0.15, pitchX = (links - 1) * spacing + 0.3, pitchY = 0.3;
  const int count = std::max(1, n / links);
  const int columns = std::max(1, static_cast<int>(std::round(std::sqrt(count * pitchY / pitchX))));
  const double width = columns * pitchX;
  for (int c = 0; c < count; ++c) {
    const Vec2 origin(-0.5 * width + (c % columns) * pitchX + b.uniform(0, 0.1), 0.5 + (c / columns) * pitchY);
    const double tilt = b.uniform(-0.1, 0.1);
    const int first = s.scene.numParticles();
    for (int k = 0; k < links; ++k) b.add(0.1, origin + k * spacing * Vec2(1, tilt), Vec2::Zero(), r);
    for (int k = 0; k + 1 < links; ++k) b.link(first + k, first + k + 1, r, 500.0, spacing, 0.5);
  }
  b.plane(Vec2(0, 0), Vec2(0, 1));
  b.plane(Vec2(-0.5 * width - 0.5, 0), Vec2(1, 0));
  b.plane(Vec2(0.5 * width + 0.5, 0), Vec2(-1, 0));
  setup.cor = 0.2;
  setup.steps = 300;
  setup.thickness = 0.1 * r;
  // On a pile of chains the impulse passes diverge: a joint resting on another chain meets it
  // as a particle and as the ends of its two edges at once, and a pass sums the impulses of all
  // these redundant contacts, computed from the same positions. Ten passes then throw joints
  // kilometres away (and every swept box overlaps every other) before the failsafe freezes the
  // pile; three passes keep the divergence small.
  setup.maxIterations = 3;
}

void bullets(Builder& b, const BenchScene& s, int n, Setup& setup) {
  // Sparse (a bullet's path crosses a neighbour's only now and then) and not quite elastic:
  // a bullet meeting several objects in one pass gets all their impulses, computed from the same
  // path and summed, and in a dense, elastic field such a bullet sets off a cascade that grows
  // pass by pass until the failsafe freezes the whole field.
  const double r = 0.01, spacing = 1.0, spread = 0.3;
  const int columns = std::max(2, static_cast<int>(std::sqrt(std::max(1.0, n - 2.0 * std::sqrt(n)))));
  const double width = columns * spacing;
  const int nodes = static_cast<int>(width / 0.1) + 1;  // the fixed chain below
  const int first = s.scene.numParticles();
  for (int k = 0; k < nodes; ++k) b.add(1.0, Vec2(-0.5 * width + 0.1 * k, 0.0), Vec2::Zero(), 0.005, true);
  for (int k = 0; k + 1 < nodes; ++k) b.link(first + k, first + k + 1, 0.005, 0, 0, 0);
  const int shots = std::max(0, n - nodes);
  for (int k = 0; k < shots; ++k) {
    const double angle = -0.5 * kPi + b.uniform(-spread, spread), speed = b.uniform(40, 60);
    b.add(0.01, Vec2(-0.5 * width + (k % columns + 0.5) * spacing, 0.5 + (k / columns) * spacing),
          speed * Vec2(std::cos(angle), std::sin(angle)), r);
  }
  const double top = 0.5 + (shots / columns + 2) * spacing;
  b.plane(Vec2(0, top), Vec2(0, -1));
  b.plane(Vec2(-0.5 * width - 0.1, 0), Vec2(1, 0));
  b.plane(Vec2(0.5 * width + 0.1, 0), Vec2(-1, 0));
  b.plane(Vec2(0, -1), Vec2(0, 1));  // a floor below the chain catches what slips through a gap
  setup.cor = 0.5;
  setup.gravity = 0;
  setup.steps = 200;
  setup.thickness = 0.1 * r;
}

// The dense-pile family (bench_scenes.h). Runs of 1,000 steps (5 s): long enough for the V piles
// to pour, pile up and slow down, and for the cost per 100-step block to show where it goes.
constexpr long kPileSteps = 1000;

/// The V piles: rain's grid and V, jittered by 0.4 of the gap between neighbours (rain's 0.2 lets
/// a block fall nearly as a lattice), so that two neighbours still cannot start overlapping (each
/// moves at most 0.4 of the gap towards the other). Low: the lowest row starts just above the V's
/// arms (4 radii above them at the grid's edges), so the pile forms at once, in the issue's "poured
/// into a V from just above it". High: the block lifted by its own height, so it lands at
/// sqrt(2 g height) (11 m/s at N = 2,500, about a radius per step) and the impacts run through it.
void pileV(Builder& b, int n, Setup& setup, double cor, bool high) {
  jitteredGridOverV(b, n, 0.4, high);
  setup.cor = cor;
  setup.steps = kPileSteps;
}

/// A pile that comes to rest: hexagonal rows in a flat-bottomed box, alternately m disks and m - 1
/// disks in the grooves between them, each row a little above where it will settle, so that the
/// pile sinks by a few hundredths of a radius per row and then stays. Frictionless disks rest in
/// such a stack (each sits in a groove; the walls hold the ends of the full rows), which they do
/// not in a V, where a frictionless pile keeps creeping. Horizontal pitch 2.04r (2% slack: the
/// rows are not wedged between the walls); settled rows are then sqrt(4 - 1.02^2) r = 1.72r apart,
/// and they start 1.8r apart. Jitter: 0.01r across, 0.02r up and down, which keeps every pair
/// apart (nearest neighbours in the row above are at least sqrt(1.0^2 + 1.76^2) r = 2.02r away).
void pileRest(Builder& b, int n, Setup& setup) {
  const double r = 0.05, pitchX = 2.04 * r, pitchY = 1.8 * r;
  // About square: width 2.04r m, height 1.8r n / (m - 0.5).
  const int m = std::max(2, static_cast<int>(std::round(std::sqrt(0.88 * n))));
  const double width = m * pitchX;
  for (int k = 0, row = 0; k < n; ++row) {
    const bool full = row % 2 == 0;
    for (int i = 0; i < (full ? m : m - 1) && k < n; ++i, ++k) {
      const double dx = b.uniform(-0.01 * r, 0.01 * r);
      const double dy = b.uniform(-0.02 * r, 0.02 * r);
      b.add(1.0, Vec2(-0.5 * width + (i + (full ? 0.5 : 1.0)) * pitchX + dx, 1.03 * r + row * pitchY + dy),
            Vec2::Zero(), r);
    }
  }
  b.plane(Vec2(0, 0), Vec2(0, 1));
  b.plane(Vec2(-0.5 * width, 0), Vec2(1, 0));  // the walls' points on the floor: see box2d_pile.cpp
  b.plane(Vec2(0.5 * width, 0), Vec2(-1, 0));
  setup.cor = 0.0;
  setup.steps = kPileSteps;
}

}  // namespace

const std::vector<std::string>& pileKinds() {
  static const std::vector<std::string> kinds = {"pile-low-cor0", "pile-low-cor0.5", "pile-high-cor0",
                                                 "pile-high-cor0.5", "pile-rest"};
  return kinds;
}

std::vector<std::string> allKinds() {
  std::vector<std::string> kinds = sceneKinds();
  kinds.insert(kinds.end(), pileKinds().begin(), pileKinds().end());
  return kinds;
}

const std::vector<std::string>& sceneKinds() {
  static const std::vector<std::string> kinds = {"rain", "gas", "chains", "bullets"};
  return kinds;
}

bool makeScene(const std::string& kind, int n, const std::string& collision, unsigned seed, BenchScene& out) {
  out = BenchScene{};
  out.name = kind;
  Builder b(out, seed);
  Setup setup;
  if (kind == "rain") rain(b, n, setup);
  else if (kind == "gas") gas(b, n, setup);
  else if (kind == "chains") chains(b, out, n, setup);
  else if (kind == "bullets") bullets(b, out, n, setup);
  else if (kind == "pile-low-cor0") pileV(b, n, setup, 0.0, false);
  else if (kind == "pile-low-cor0.5") pileV(b, n, setup, 0.5, false);
  else if (kind == "pile-high-cor0") pileV(b, n, setup, 0.0, true);
  else if (kind == "pile-high-cor0.5") pileV(b, n, setup, 0.5, true);
  else if (kind == "pile-rest") pileRest(b, n, setup);
  else return false;
  b.finish(collision, setup);
  out.description = kind + ", " + std::to_string(out.scene.numParticles()) + " particles, " +
                    std::to_string(out.scene.edges.size()) + " edges, " + collision;
  return true;
}

std::vector<std::string> collisionTypes() {
  std::vector<std::string> types;
  for (const CollisionEntry& entry : collisionTable()) types.push_back(entry.keyword);
  return types;
}

namespace {

/// A viewport that frames the scene: the particles' discs and the half-planes' anchor points (the
/// floor, the walls, the V's tip), with a margin; half-height from the larger side, so that a
/// square picture (the default) shows it all.
Viewport framing(const BenchScene& s) {
  const Scene& scene = s.scene;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  const auto include = [&](double x, double y, double r) {
    lo[0] = std::min(lo[0], x - r);
    lo[1] = std::min(lo[1], y - r);
    hi[0] = std::max(hi[0], x + r);
    hi[1] = std::max(hi[1], y + r);
  };
  for (int p = 0; p < scene.numParticles(); ++p) include(s.state.x[2 * p], s.state.x[2 * p + 1], scene.radius[p]);
  for (const HalfPlane& h : scene.halfplanes) include(h.point.x(), h.point.y(), 0);
  if (!(lo[0] <= hi[0])) return Viewport{};
  // Rounded to 4 significant digits (a camera needs no more, and the file stays readable); the
  // 10% margin covers the rounding.
  const auto round = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return std::strtod(text, nullptr);
  };
  const double size = 0.55 * std::max({hi[0] - lo[0], hi[1] - lo[1], 1e-3});
  return Viewport{round(0.5 * (lo[0] + hi[0])), round(0.5 * (lo[1] + hi[1])), round(size)};
}

}  // namespace

SceneFile toSceneFile(BenchScene s) {
  SceneFile file;
  file.description = s.description + " (fosssim-scenegen)";
  file.look.viewport = framing(s);
  file.scene = std::move(s.scene);
  file.initial = std::move(s.state);
  return file;
}

}  // namespace fosssim::bench
