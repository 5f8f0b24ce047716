// The seven multi-contact problems of contact_problems.h: their scenes and what each one judges.
// Every scene uses symplectic Euler at dt = 0.01 s (free flight is exact for it) and the hybrid
// without its penalty layer (k = 0): the problems compare contact handling, and a penalty force
// acting before contact would blur the closed forms (a rebound at exactly the impact speed, a
// speed kept in a corridor) that the tests hold the default mode to.
#include "contact_problems.h"
#include "number_text.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fosssim::study {
namespace {

constexpr double kDt = 0.01;
const Vec2 kGravity(0, -9.81);

/// The scene's heading: integrator, step, collision type with its COR (hybrid: penalty k = 0).
SceneBuilder heading(const std::string& collision, double cor, double duration) {
  CollisionChoice c{collision};
  c.cor = cor;
  if (collision == "hybrid") c.k = 0;
  SceneBuilder x;
  x.duration(duration).integrator("symplectic-euler", kDt).collision(c);
  return x;
}

ContactProblem problem(std::string name, std::string title, std::string speedLabel = "") {
  ContactProblem p;
  p.name = std::move(name);
  p.title = std::move(title);
  p.speedLabel = std::move(speedLabel);
  return p;
}

/// Index of the last particle: the problems with one moving body add it last.
int lastParticle(const State& s) { return s.numParticles() - 1; }

// ---- Joint drop --------------------------------------------------------------------------------
// A ball (radius 0.1) dropped from 0.5 m onto the joint of two collinear fixed floor edges: three
// fixed particles at x = -1, 0, 1 joined by two edges (radius 0.02). 3 mm beside the joint the
// ball meets both edges (one on its face, one on its end cap) and the joint particle in the same
// instant, all with the normal straight up (exactly at the joint the course's edge test leaves the
// ends to the particle, and one contact remains). An elastic bounce reverses the vertical velocity,
// so the ball leaves at its impact speed. Speed ratio: rebound speed over impact speed (the
// integrator's prediction v + h g at the contact step).

constexpr double kJointOffset = 0.003, kJointCor = 1.0;

class JointDropJudge final : public ContactJudge {
 public:
  void step(const Scene& scene, const State& before, const State& after, long contacts) override {
    if (contacts == 0 || seen_) return;
    seen_ = true;
    const int ball = lastParticle(after);
    impact_ = (at(before.v, ball) + scene.dt * kGravity).norm();
    rebound_ = at(after.v, ball).norm();
  }
  bool outside(const Scene&, const State& s, int i) const override { return at(s.x, i).y() < 0; }
  void finish(ContactResult& r) override { r.speedRatio = seen_ ? rebound_ / impact_ : kNotApplicable; }

 private:
  bool seen_ = false;
  double impact_ = 0, rebound_ = 0;
};

ContactProblem jointDrop(bool quick) {
  ContactProblem p = problem("joint-drop",
                             "Joint drop: ball (COR " + numberText(kJointCor) + ") onto the joint of two floor edges",
                             "rebound speed / impact speed at the first bounce");
  p.contained = true;
  p.scene = [quick](const std::string& collision, int) {
    SceneBuilder x = heading(collision, kJointCor, quick ? 0.4 : 1.5);
    x.gravity(kGravity);
    for (int k = 0; k < 3; ++k) x.particle(Vec2(k - 1.0, 0), Vec2::Zero(), 1.0, true, 0.02);
    x.edge(0, 1, 0.02);
    x.edge(1, 2, 0.02);
    x.particle(Vec2(kJointOffset, 0.5), Vec2::Zero(), 1.0, false, 0.1);
    return x;
  };
  p.judge = [] { return std::make_unique<JointDropJudge>(); };
  return p;
}

// ---- Touching rack -----------------------------------------------------------------------------
// A cue ball at 5 m/s into the apex of a 15-ball triangle whose neighbours touch to within 1e-12
// (radius 0.1), no gravity, COR 1: every contact of the rack arrives in the same instant. Free
// particles only, so kinetic energy (COR 1), momentum and angular momentum are invariants.

constexpr double kRackR = 0.1, kRackCor = 1.0;
constexpr int kRackRows = 5;

ContactProblem touchingRack(bool quick) {
  ContactProblem p = problem("touching-rack", "Touching rack: cue ball into " +
                                                 std::to_string(kRackRows * (kRackRows + 1) / 2) +
                                                 " touching balls (COR " + numberText(kRackCor) + ")");
  p.isolated = true;
  p.scene = [quick](const std::string& collision, int) {
    const double d = 2 * kRackR + 1e-12;  // centre distance of touching neighbours
    SceneBuilder x = heading(collision, kRackCor, quick ? 0.3 : 0.8);
    x.particle(Vec2(-1, 0), Vec2(5, 0), 1.0, false, kRackR);
    for (int row = 0; row < kRackRows; ++row)
      for (int j = 0; j <= row; ++j)
        x.particle(Vec2(row * d * std::sqrt(3.0) / 2, (j - row / 2.0) * d), Vec2::Zero(), 1.0, false, kRackR);
    return x;
  };
  p.judge = [] { return std::make_unique<ContactJudge>(); };
  return p;
}

// ---- Corridor ----------------------------------------------------------------------------------
// A particle (radius 0.05) at (10, -100) m/s between the half-planes y = 0 and y = 0.5, COR 1: it
// crosses the 0.4 m it has in 4 ms, so it bounces two or three times in every step. Elastic walls
// only reverse the vertical velocity: its speed and its 10 m/s along the corridor are kept, and it
// never leaves. Speed ratio: speed at the end over the start's.

const Vec2 kCorridorV(10, -100);
constexpr double kCorridorWidth = 0.5, kCorridorCor = 1.0;

class CorridorJudge final : public ContactJudge {
 public:
  void start(const Scene&, const State& s) override { v0_ = at(s.v, 0).norm(); }
  void step(const Scene&, const State&, const State& after, long) override { v_ = at(after.v, 0).norm(); }
  bool outside(const Scene&, const State& s, int i) const override {
    const double y = at(s.x, i).y();
    return y < 0 || y > kCorridorWidth;
  }
  void finish(ContactResult& r) override {
    r.speedRatio = v_ / v0_;
  }

 private:
  double v0_ = 1, v_ = 0;
};

ContactProblem corridor(bool quick) {
  ContactProblem p = problem("corridor",
                             "Corridor: particle at (" + numberText(kCorridorV.x()) + ", " +
                                 numberText(kCorridorV.y()) + ") m/s between half-planes " +
                                 numberText(kCorridorWidth) + " m apart (COR " + numberText(kCorridorCor) + ")",
                             "speed at the end / speed at the start");
  p.contained = true;
  p.scene = [quick](const std::string& collision, int) {
    SceneBuilder x = heading(collision, kCorridorCor, quick ? 0.3 : 2.0);
    x.particle(Vec2(0, kCorridorWidth / 2), kCorridorV, 1.0, false, 0.05);
    x.halfplane(Vec2(0, 0), Vec2(0, 1));
    x.halfplane(Vec2(0, kCorridorWidth), Vec2(0, -1));
    return x;
  };
  p.judge = [] { return std::make_unique<CorridorJudge>(); };
  return p;
}

// ---- Slot --------------------------------------------------------------------------------------
// Seeded shots of three disks (radius 0.02, masses 0.5-2) at 20-200 m/s across a slot 0.1 m wide
// between two thin fixed edges (radius 0.005, 100 m long), COR 1: up to 40 bounces per step. A
// disk whose centre crosses an edge's line has gone through it (escaped).

/// A fixed linear congruential sequence (as pile.cpp): the same shots on every machine.
class Lcg {
 public:
  explicit Lcg(unsigned seed) : state_(seed) {}
  /// Called once a statement by the scenes: two calls in one expression, as in
  /// Vec2(uniform(...), uniform(...)), come in an order the compiler picks (gcc right to left, clang
  /// left to right), and a scene must be the same under both.
  double uniform(double lo, double hi) {
    state_ = state_ * 1103515245u + 12345u;
    return lo + (hi - lo) * ((state_ >> 8) & 0xFFFFFF) / double(0xFFFFFF);
  }

 private:
  unsigned state_;
};

constexpr int kSlotDisks = 3;
constexpr double kSlotWidth = 0.1, kSlotSlowest = 20, kSlotFastest = 200, kSlotCor = 1.0;

class SlotJudge final : public ContactJudge {
 public:
  bool outside(const Scene&, const State& s, int i) const override {
    const Vec2 x = at(s.x, i);
    return std::abs(x.x()) < 50 && (x.y() < 0 || x.y() > kSlotWidth);
  }
};

ContactProblem slot(bool quick) {
  ContactProblem p = problem("slot", "Slot: " + countWord(kSlotDisks) + " disks at " + numberText(kSlotSlowest) + "-" +
                                         numberText(kSlotFastest) + " m/s in a " + numberText(kSlotWidth) +
                                         " m slot between thin edges (COR " + numberText(kSlotCor) + ")");
  p.contained = true;
  p.shots = quick ? 4 : 30;
  p.scene = [quick](const std::string& collision, int shot) {
    Lcg rng(1000u + static_cast<unsigned>(shot));
    SceneBuilder x = heading(collision, kSlotCor, quick ? 0.1 : 0.5);
    for (double y : {0.0, kSlotWidth}) {
      const int a = x.particle(Vec2(-50, y), Vec2::Zero(), 1.0, true, 0.005);
      const int b = x.particle(Vec2(50, y), Vec2::Zero(), 1.0, true, 0.005);
      x.edge(a, b, 0.005);
    }
    for (int k = 0; k < kSlotDisks; ++k) {
      const double speed = rng.uniform(kSlotSlowest, kSlotFastest);
      const double vy = speed * (rng.uniform(0, 1) < 0.5 ? -1 : 1);
      const double mass = rng.uniform(0.5, 2);
      const double px = -0.5 + 0.5 * k + rng.uniform(-0.1, 0.1);
      const double py = rng.uniform(0.03, 0.07);
      const double vx = rng.uniform(-2, 2);
      x.particle(Vec2(px, py), Vec2(vx, vy), mass, false, 0.02);
    }
    return x;
  };
  p.judge = [] { return std::make_unique<SlotJudge>(); };
  return p;
}

// ---- Newton's cradle ---------------------------------------------------------------------------
// A five-ball cradle: the first ball comes in at 5 m/s onto four equal balls touching to within
// 1e-12 (radius 0.1), COR 1. Elastic contacts between equal masses, taken in time order, pass the
// whole velocity down the row: the last ball leaves at 5 m/s and the others rest. Speed ratio:
// the last ball's speed over the first's; "others" is the fastest of the first four, the same way.

constexpr double kCradleSpeed = 5.0, kCradleCor = 1.0;
constexpr int kCradleStill = 4;  // the balls at rest

class CradleJudge final : public ContactJudge {
 public:
  void step(const Scene&, const State&, const State& after, long) override { v_ = after.v; }
  void finish(ContactResult& r) override {
    const int n = static_cast<int>(v_.size() / 2);
    r.speedRatio = at(v_, n - 1).norm() / kCradleSpeed;
    r.othersSpeed = 0;
    for (int i = 0; i < n - 1; ++i) r.othersSpeed = std::max(r.othersSpeed, at(v_, i).norm() / kCradleSpeed);
  }

 private:
  VecX v_;
};

ContactProblem cradle(bool quick) {
  ContactProblem p = problem("cradle",
                             "Newton's cradle: a ball at " + numberText(kCradleSpeed) + " m/s onto " +
                                 countWord(kCradleStill) + " touching balls (COR " + numberText(kCradleCor) + ")",
                             "last ball's speed / first ball's speed");
  p.isolated = true;
  p.scene = [quick](const std::string& collision, int) {
    SceneBuilder x = heading(collision, kCradleCor, quick ? 0.15 : 0.3);
    x.particle(Vec2(-0.5, 0), Vec2(kCradleSpeed, 0), 1.0, false, 0.1);
    for (int k = 0; k < kCradleStill; ++k) x.particle(Vec2(k * (0.2 + 1e-12), 0), Vec2::Zero(), 1.0, false, 0.1);
    return x;
  };
  p.judge = [] { return std::make_unique<CradleJudge>(); };
  return p;
}

// ---- Pile in a V -------------------------------------------------------------------------------
// Disks (radius 0.05) poured from a column into a V of two half-planes (walls y = |x|), COR 0.5,
// under gravity. Reference heights from geometry alone: had the column stopped rigidly at its
// first contact (what freezing zones do), its mean height would be `heightFrozen`; the N lowest
// sites of a triangular lattice of touching disks inside the V (rows √3 r apart, alternate rows
// shifted by r: packing fraction π/(2√3) = 0.907) have the mean height `heightPacked`. A pile
// that fills the V to height H covers an area ∝ H² ∝ N / φ, so the mean height above the V's
// apex for centres (r√2) scales as 1/√φ: a pile at mean height h packs at about
// φ = 0.907 ((heightPacked - r√2) / (h - r√2))² (`packingEnd`). A pile may come to rest; frozen is
// resting looser than kLoosestRest (contact_problems.h): frictionless equal disks at rest pack near
// random close packing (0.82 ± 0.02 for disks: J. G. Berryman, Phys. Rev. A 27, 1053, 1983) or
// denser, so a pile standing looser is held up by zones stopped against the walls, not by its
// contacts.

constexpr double kPileR = 0.05, kPileCor = 0.5;

class PileJudge final : public ContactJudge {
 public:
  void start(const Scene&, const State& s) override {
    const int n = s.numParticles();
    double mean = 0, drop = 1e300;
    for (int i = 0; i < n; ++i) {
      const Vec2 x = at(s.x, i);
      mean += x.y() / n;
      // Height the disk can fall straight down before touching the wall on its side.
      drop = std::min(drop, x.y() - std::abs(x.x()) - kPileR * std::sqrt(2.0));
    }
    stopped_ = mean - drop;
    packed_ = latticeHeight(n);
  }
  bool outside(const Scene&, const State& s, int i) const override {
    const Vec2 x = at(s.x, i);
    return x.y() < std::abs(x.x());
  }
  void finish(ContactResult& r) override {
    r.heightFrozen = stopped_;
    r.heightPacked = packed_;
    if (!r.series.empty()) {
      const double apex = kPileR * std::sqrt(2.0), ratio = (packed_ - apex) / (r.series.back().height - apex);
      r.packingEnd = kLattice * ratio * ratio;
    }
    r.frozen = r.stopped && r.packingEnd < kLoosestRest;
  }

 private:
  static constexpr double kLattice = 0.9068996821171089;  // π / (2√3)
  /// Mean height of the n lowest lattice sites in the V (the sites fill rows from the bottom).
  static double latticeHeight(int n) {
    const double apex = kPileR * std::sqrt(2.0), rise = std::sqrt(3.0) * kPileR;
    double sum = 0;
    int placed = 0;
    for (int row = 0; placed < n; ++row) {
      const double y = apex + row * rise, half = y - apex;  // centres' room: |x| <= y - r√2
      const double shift = row % 2 ? kPileR : 0;  // sites at shift + 2 r j
      for (int j = -static_cast<int>(std::ceil(half / (2 * kPileR))) - 1; placed < n && 2 * kPileR * j + shift <= half;
           ++j)
        if (std::abs(2 * kPileR * j + shift) <= half) sum += y, ++placed;
    }
    return sum / n;
  }
  double stopped_ = 0, packed_ = 0;
};

// ---- Clump -------------------------------------------------------------------------------------
// A 7 x 7 hexagonal pack of disks (radius 0.045-0.05, masses 0.5-2, gaps 0.5-10 mm) moving at up to
// 1 m/s each way and squeezed toward its centre at 2 /s, held together by the gravitation of every
// pair (G = 0.05), COR 0.5, no walls, no gravity: the pack collapses into a jostling clump whose
// contacts come at many instants of every step, most of them through the failsafe's zones. Only
// pair forces and contacts act, so momentum and angular momentum are invariants (symplectic Euler
// keeps both under central pair forces: its kick is torque-free, its drift exact).

constexpr int kClumpSide = 7;
constexpr double kClumpCor = 0.5, kClumpG = 0.05;

ContactProblem clump(bool quick) {
  const int side = quick ? 4 : kClumpSide;
  ContactProblem p = problem("clump", "Clump: " + std::to_string(side * side) +
                                          " disks held together by their own gravitation (COR " +
                                          numberText(kClumpCor) + ")");
  p.isolated = true;
  p.scene = [quick, side](const std::string& collision, int) {
    SceneBuilder x = heading(collision, kClumpCor, quick ? 0.3 : 1.0);
    Lcg rng(20261205u);  // the same clump on every machine
    const double r = 0.05, gap = rng.uniform(0.0005, 0.01);
    const Vec2 centre((side - 1) * (r + gap / 2), (side - 1) * (r + gap / 2) * 0.87);
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) {
        const Vec2 site((2 * r + gap) * i + (j % 2) * (r + gap / 2), (2 * r + gap) * 0.87 * j);
        const double vx = rng.uniform(-1, 1);
        const double vy = rng.uniform(-1, 1);
        const Vec2 v(vx, vy);
        const double m = rng.uniform(0.5, 2.0), radius = r * rng.uniform(0.9, 1.0);
        x.particle(site - centre, v - 2.0 * (site - centre), m, false, radius);
      }
    for (int i = 0; i < side * side; ++i)
      for (int j = i + 1; j < side * side; ++j) x.gravitational(i, j, kClumpG);
    return x;
  };
  p.judge = [] { return std::make_unique<ContactJudge>(); };
  return p;
}

}  // namespace

ContactProblem pileInV(int columns, int rows, double duration) {
  ContactProblem p =
      problem("pile", "Pile in a V: " + std::to_string(columns * rows) + " disks poured under gravity (COR " +
                          numberText(kPileCor) + ")");
  p.contained = true;
  p.scene = [=](const std::string& collision, int) {
    SceneBuilder x = heading(collision, kPileCor, duration);
    x.gravity(kGravity);
    x.halfplane(Vec2::Zero(), Vec2(1, 1));
    x.halfplane(Vec2::Zero(), Vec2(-1, 1));
    const double left = -0.055 * (columns - 1);
    for (int row = 0; row < rows; ++row)
      for (int c = 0; c < columns; ++c)
        x.particle(Vec2(left + 0.11 * c + (row % 2 ? 0.004 : -0.003), 0.8 + 0.13 * row), Vec2::Zero(), 1.0, false,
                   kPileR);
    return x;
  };
  p.judge = [] { return std::make_unique<PileJudge>(); };
  return p;
}

std::vector<ContactProblem> contactProblems(bool quick) {
  return {jointDrop(quick), touchingRack(quick), corridor(quick), slot(quick), cradle(quick),
          quick ? pileInV(3, 4, 0.6) : pileInV(10, 20, 2.0), clump(quick)};
}

ContactProblem contactProblem(const std::string& name, bool quick) {
  for (ContactProblem& p : contactProblems(quick))
    if (p.name == name) return p;
  return ContactProblem{};
}

}  // namespace fosssim::study
