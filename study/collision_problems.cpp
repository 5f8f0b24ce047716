// The problems that compare collision methods. Free flight is exact for every integrator, so the
// methods differ only in how they find and answer contacts; all run with symplectic Euler (the
// penalty force has no Jacobian, so the implicit integrators would treat it explicitly anyway).
#include "closed_forms.h"
#include "number_text.h"
#include "problems.h"

#include <cmath>
#include <utility>

namespace fosssim::study {
namespace {

std::vector<double> collisionSweep(bool quick) {
  if (quick) return {0.02, 0.01};
  return {0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4};
}

/// A collision problem's heading: every collision method over the collision time steps.
Problem collisionProblem(std::string name, std::string title, std::string errorLabel, bool quick) {
  return problemHeading(std::move(name), std::move(title), std::move(errorLabel), "collisions", collisionMethods(),
                        collisionSweep(quick));
}

/// The first step end at which particle p's velocity departs from its free flight by more than
/// half of the exact collision's velocity change: the measured moment of contact (resolution dt;
/// a penalty force, which brakes gradually, is caught in the middle of its contact).
class ContactWatch {
 public:
  ContactWatch(int particle, Vec2 v0, Vec2 g, double change) : p_(particle), v0_(v0), g_(g), half_(change / 2) {}
  void step(const State& s) {
    if (std::isnan(time_) && (at(s.v, p_) - (v0_ + g_ * s.time)).norm() > half_) time_ = s.time;
  }
  double time() const { return time_; }

 private:
  int p_;
  Vec2 v0_, g_;
  double half_;
  double time_ = kNotApplicable;
};

/// The conservation errors of a run without external forces doing work: the relative change of
/// kinetic energy and of momentum (relative to sum m|v0|) from velocities v0 to v.
void conservationErrors(const Scene& scene, const VecX& v0, const VecX& v, Metrics& m) {
  const double k0 = kineticEnergy(scene, v0);
  m.energy = std::abs(kineticEnergy(scene, v) - k0) / k0;
  m.momentum = (momentum(scene, v) - momentum(scene, v0)).norm() / momentumScale(scene, v0);
}

// ---- Two disks ---------------------------------------------------------------------------------
// Unequal masses meeting off-centre (the normal is 30 degrees off the line of motion).

struct Disk {
  Vec2 x, v;
  double m, r;
};
const Disk kDisk1{Vec2(-0.5, 0.0), Vec2(1.0, 0.0), 1.0, 0.1};
const Disk kDisk2{Vec2(0.5, 0.1), Vec2(-1.0, 0.0), 2.0, 0.1};

DiskCollision twoDisks() {
  return diskCollision(kDisk1.x, kDisk1.v, kDisk1.m, kDisk1.r, kDisk2.x, kDisk2.v, kDisk2.m, kDisk2.r, 1.0);
}

class DisksMeasure final : public Measurement {
 public:
  DisksMeasure() : exact_(twoDisks()), watch_(0, kDisk1.v, Vec2::Zero(), (exact_.v1After - kDisk1.v).norm()) {}
  void step(const Scene&, const State& s) override { watch_.step(s); }
  Metrics finish(const Scene& scene, const State& initial, const RunResult& run) override {
    const State& s = run.final;
    const double t = s.time, tc = exact_.time;
    const Vec2 x1 = kDisk1.x + kDisk1.v * tc + exact_.v1After * (t - tc);
    const Vec2 x2 = kDisk2.x + kDisk2.v * tc + exact_.v2After * (t - tc);
    Metrics m;
    m.position = std::max((at(s.x, 0) - x1).norm(), (at(s.x, 1) - x2).norm());
    m.velocity = std::max((at(s.v, 0) - exact_.v1After).norm(), (at(s.v, 1) - exact_.v2After).norm());
    conservationErrors(scene, initial.v, s.v, m);
    m.contactTime = watch_.time() - tc;
    m.error = m.position;
    return m;
  }

 private:
  DiskCollision exact_;
  ContactWatch watch_;
};

Problem disks(bool quick) {
  Problem p = collisionProblem("disks",
                               "Elastic collision of two disks (masses " + numberText(kDisk1.m) + " and " +
                                   numberText(kDisk2.m) + ", oblique)",
                               "position error at the end [m]", quick);
  p.scene = [](const Method& m, double dt) {
    SceneBuilder x;
    x.duration(1.0).method(m, dt);
    for (const Disk& d : {kDisk1, kDisk2}) x.particle(d.x, d.v, d.m, false, d.r);
    return x;
  };
  p.measure = [] { return std::make_unique<DisksMeasure>(); };
  p.setup = {{"m1", kDisk1.m},      {"m2", kDisk2.m},      {"r", kDisk1.r},       {"x1", kDisk1.x.x()},
             {"y1", kDisk1.x.y()},  {"x2", kDisk2.x.x()},  {"y2", kDisk2.x.y()},  {"v1", kDisk1.v.x()},
             {"v2", kDisk2.v.x()},  {"duration", 1.0},     {"contact_time", twoDisks().time},
             {"cor", p.methods.front().collision.cor}};
  return p;
}

// ---- Floor bounce ------------------------------------------------------------------------------
// A disk dropped from rest at 1 m with 1 m/s sideways onto the floor y = 0; 0.8 s covers the first
// bounce and stops before a second one for every COR.

FloorBounce bounce(double cor) { return FloorBounce{Vec2(0, 1), Vec2(1, 0), 9.81, 0.1, cor}; }
constexpr double kBounceMass = 1.0;

class BounceMeasure final : public Measurement {
 public:
  explicit BounceMeasure(double cor)
      : exact_(bounce(cor)),
        watch_(0, exact_.v0, Vec2(0, -exact_.g), (1 + cor) * std::abs(exact_.velocityBefore().y())) {}
  void step(const Scene&, const State& s) override { watch_.step(s); }
  Metrics finish(const Scene&, const State&, const RunResult& run) override {
    const State& s = run.final;
    Metrics m;
    m.position = (at(s.x, 0) - exact_.position(s.time)).norm();
    m.velocity = (at(s.v, 0) - exact_.velocity(s.time)).norm();
    // Kinetic plus gravitational energy of a unit mass, against the closed form's (the penalty
    // layers' own energy is left out: the exact answer has none).
    auto energy = [&](const Vec2& x, const Vec2& v) { return 0.5 * v.squaredNorm() + exact_.g * x.y(); };
    m.energy = std::abs(energy(at(s.x, 0), at(s.v, 0)) - energy(exact_.position(s.time), exact_.velocity(s.time))) /
               energy(exact_.x0, exact_.v0);
    m.contactTime = watch_.time() - exact_.contactTime();
    m.error = m.position;
    return m;
  }

 private:
  FloorBounce exact_;
  ContactWatch watch_;
};

Problem floorBounce(bool quick, double cor) {
  Problem p = collisionProblem("bounce-cor" + numberText(cor), "Disk bouncing on a half-plane, COR " + numberText(cor),
                               "position error at the end [m]", quick);
  for (Method& m : p.methods) m.collision.cor = cor;
  p.scene = [](const Method& m, double dt) {
    const FloorBounce b = bounce(m.collision.cor);
    SceneBuilder x;
    x.duration(0.8).method(m, dt).gravity(Vec2(0, -b.g));
    x.particle(b.x0, b.v0, kBounceMass, false, b.r);
    x.halfplane(Vec2(0, 0), Vec2(0, 1));
    return x;
  };
  p.measure = [cor] { return std::make_unique<BounceMeasure>(cor); };
  const FloorBounce b = bounce(cor);
  p.setup = {{"x0", b.x0.x()}, {"y0", b.x0.y()}, {"vx", b.v0.x()},   {"vy", b.v0.y()},        {"g", b.g},
             {"r", b.r},       {"mass", kBounceMass}, {"duration", 0.8}, {"contact_time", b.contactTime()}};
  return p;
}

// ---- Newton's cradle ---------------------------------------------------------------------------
// Five unit disks of radius 0.1 in a row with 0.02 gaps (wider than the penalty thickness, so no
// force acts before the first contact); the first one comes in at 1 m/s from 0.1 away. Hard
// elastic disks pass the momentum down the row one contact at a time: each disk moves across its
// gap and stops, and the last one leaves at 1 m/s. That is the exact answer at the end.

constexpr int kCradle = 5;
constexpr double kCradleR = 0.1, kCradleGap = 0.02, kFirstGap = 0.1, kCradleSpeed = 1.0, kCradleTime = 0.5;

double cradleStart(int i) { return i == 0 ? 0.0 : 2 * kCradleR + kFirstGap + (i - 1) * (2 * kCradleR + kCradleGap); }

class CradleMeasure final : public Measurement {
 public:
  Metrics finish(const Scene& scene, const State& initial, const RunResult& run) override {
    const State& s = run.final;
    Metrics m;
    m.position = m.velocity = 0;
    double hit = kFirstGap / kCradleSpeed;  // when disk i starts moving (i >= 1)
    for (int i = 0; i < kCradle; ++i) {
      double x = cradleStart(i);
      Vec2 v = Vec2::Zero();
      if (i == kCradle - 1) {
        x += kCradleSpeed * (s.time - hit);
        v.x() = kCradleSpeed;
      } else {
        x += i == 0 ? kFirstGap : kCradleGap;
        if (i > 0) hit += kCradleGap / kCradleSpeed;
      }
      m.position = std::max(m.position, (at(s.x, i) - Vec2(x, 0)).norm());
      m.velocity = std::max(m.velocity, (at(s.v, i) - v).norm());
    }
    conservationErrors(scene, initial.v, s.v, m);
    m.error = m.position;
    return m;
  }
};

Problem cradle(bool quick) {
  Problem p = collisionProblem(
      "cradle", "Newton's cradle (" + std::to_string(kCradle) + " disks, " + numberText(kCradleGap) + " gaps)",
      "position error at the end [m]", quick);
  p.scene = [](const Method& m, double dt) {
    SceneBuilder x;
    x.duration(kCradleTime).method(m, dt);
    for (int i = 0; i < kCradle; ++i)
      x.particle(Vec2(cradleStart(i), 0), Vec2(i == 0 ? kCradleSpeed : 0, 0), 1.0, false, kCradleR);
    return x;
  };
  p.measure = [] { return std::make_unique<CradleMeasure>(); };
  p.setup = {{"disks", kCradle},        {"r", kCradleR},          {"gap", kCradleGap},
             {"first_gap", kFirstGap},  {"speed", kCradleSpeed},  {"duration", kCradleTime}};
  return p;
}

// ---- Billiard break ----------------------------------------------------------------------------
// A 15-disk rack (rows of 1..5, 0.02 gaps) hit head-on by a cue disk at 5 m/s, no cushions. The
// outcome is chaotic, but momentum is conserved and, with COR 1, so is kinetic energy.

class BreakMeasure final : public Measurement {
 public:
  Metrics finish(const Scene& scene, const State& initial, const RunResult& run) override {
    const State& s = run.final;
    Metrics m;
    conservationErrors(scene, initial.v, s.v, m);
    m.error = m.energy;
    return m;
  }
};

Problem billiards(bool quick) {
  constexpr double r = 0.1, gap = 0.02, cueSpeed = 5, duration = 0.5;
  constexpr int rows = 5;
  Problem p = collisionProblem("billiards", "", "relative kinetic energy error at the end", quick);
  p.title = "Billiard break (cue + " + std::to_string(rows * (rows + 1) / 2) + " disks, COR " +
            numberText(p.methods.front().collision.cor) + ")";
  p.scene = [=](const Method& m, double dt) {
    constexpr double spacing = 2 * r + gap;
    SceneBuilder x;
    x.duration(duration).method(m, dt);
    x.particle(Vec2(-0.5, 0), Vec2(cueSpeed, 0), 1.0, false, r);  // the cue disk
    for (int row = 0; row < rows; ++row)
      for (int k = 0; k <= row; ++k)
        x.particle(Vec2(row * spacing * std::sqrt(3.0) / 2, (k - row / 2.0) * spacing), Vec2(0, 0), 1.0, false, r);
    return x;
  };
  p.measure = [] { return std::make_unique<BreakMeasure>(); };
  p.setup = {{"rack", rows * (rows + 1) / 2}, {"r", r},          {"gap", gap},
             {"speed", cueSpeed},              {"duration", duration}, {"cor", p.methods.front().collision.cor}};
  return p;
}

}  // namespace

std::vector<Method> collisionMethods() {
  const std::string integrator = "symplectic-euler";
  std::vector<Method> out;
  for (const char* type : {"simple", "continuous-time", "hybrid"})
    out.push_back(Method{type, integrator, CollisionChoice{type}});
  // The hybrid handler without its penalty layer (k = 0 still adds the force, at no strength):
  // shows what the default layer (k = 10, thickness 0.1) does to accuracy.
  CollisionChoice bare{"hybrid"};
  bare.k = 0;
  out.push_back(Method{"hybrid k=0", integrator, bare});
  for (double k : {1e2, 1e4, 1e6}) {
    CollisionChoice c{"penalty"};
    c.k = k;
    out.push_back(Method{"penalty k=1e" + std::to_string(std::lround(std::log10(k))), integrator, c});
  }
  return out;
}

std::vector<Problem> collisionProblems(bool quick) {
  return {disks(quick), floorBounce(quick, 0.0), floorBounce(quick, 0.5), floorBounce(quick, 1.0), cradle(quick),
          billiards(quick)};
}

}  // namespace fosssim::study
