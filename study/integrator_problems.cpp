// The problems that compare integrators: forces only, no collisions. Every answer comes from
// closed_forms.h; the scenes are chosen so that one period or flight is resolved by the coarsest
// time step and the finest one is still cheap.
#include "closed_forms.h"
#include "number_text.h"
#include "problems.h"

#include <cmath>
#include <utility>

namespace fosssim::study {
namespace {

std::vector<double> sweep(bool quick, std::vector<double> full) {
  if (!quick) return full;
  return {full[0], full[1]};  // the two coarsest: cheap enough for sanitizer builds
}

/// An integrator problem's heading: every integrator over the time steps `dts`.
Problem integratorProblem(std::string name, std::string title, std::string errorLabel, std::vector<double> dts) {
  return problemHeading(std::move(name), std::move(title), std::move(errorLabel), "integrators", integratorMethods(),
                        std::move(dts));
}

// ---- Projectile --------------------------------------------------------------------------------

const Projectile kThrow{Vec2(0, 0), Vec2(3, 10), Vec2(0, -9.81)};
constexpr double kThrowMass = 1.0, kThrowTime = 2.0;

class ProjectileMeasure final : public Measurement {
 public:
  void step(const Scene& scene, const State& s) override { track_.add(drift(scene, s).energy); }
  /// Energy against the start's m |v0|^2 / 2 - m g . x0 (relative to its kinetic part); momentum
  /// against m v(t) (relative to m |v0|); angular momentum about the origin against m x(t) × v(t)
  /// (relative to m |v0|^3 / g, the throw's natural scale).
  Drift drift(const Scene& scene, const State& s) const override {
    const double kinetic0 = 0.5 * kThrowMass * kThrow.v0.squaredNorm();
    const double e0 = kinetic0 - kThrowMass * kThrow.g.dot(kThrow.x0);
    const Vec2 x = at(s.x, 0), v = at(s.v, 0), xe = kThrow.position(s.time), ve = kThrow.velocity(s.time);
    const double speed = kThrow.v0.norm();
    Drift d;
    d.energy = std::abs(mechanicalEnergy(scene, s) - e0) / kinetic0;
    d.momentum = (v - ve).norm() / speed;
    d.angularMomentum = std::abs(cross(x, v) - cross(xe, ve)) * kThrow.g.norm() / (speed * speed * speed);
    return d;
  }
  Metrics overRun() const override {
    Metrics m;
    track_.fill(m);
    return m;
  }
  Metrics finish(const Scene& scene, const State& initial, const RunResult& run) override {
    const State& s = run.final;
    Metrics m;
    m.position = (at(s.x, 0) - kThrow.position(s.time)).norm();
    m.velocity = (at(s.v, 0) - kThrow.velocity(s.time)).norm();
    const double e0 = mechanicalEnergy(scene, initial);
    m.energy = std::abs(mechanicalEnergy(scene, s) - e0) / kineticEnergy(scene, initial.v);
    m.error = m.position;
    return m;
  }

 private:
  EnergyErrorTrack track_;
};

Problem projectile(bool quick) {
  Problem p = integratorProblem("projectile", "Projectile under gravity (" + numberText(kThrowTime) + " s flight)",
                                "position error at the end [m]",
                                sweep(quick, {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4}));
  p.scene = [](const Method& m, double dt) {
    SceneBuilder x;
    x.duration(kThrowTime).method(m, dt).gravity(kThrow.g);
    x.particle(kThrow.x0, kThrow.v0, kThrowMass);
    return x;
  };
  p.measure = [] { return std::make_unique<ProjectileMeasure>(); };
  p.setup = {{"mass", kThrowMass}, {"x0", kThrow.x0.x()}, {"y0", kThrow.x0.y()}, {"vx", kThrow.v0.x()},
             {"vy", kThrow.v0.y()}, {"gx", kThrow.g.x()}, {"gy", kThrow.g.y()}, {"duration", kThrowTime}};
  return p;
}

// ---- Springs -----------------------------------------------------------------------------------
// A unit mass on a spring to a fixed anchor at the origin, stretched along x and let go: the
// motion stays on the x axis, where the spring force -k (l - l0) - b l' is linear in l.

constexpr double kRest = 1.0, kStretch = 0.5, kSpringK = 10.0, kSpringMass = 1.0;

class SpringMeasure final : public Measurement {
 public:
  explicit SpringMeasure(double b) : exact_{kSpringMass, kSpringK, b, kStretch, 0.0} {}
  /// Momentum against m v(t) (relative to the largest exact speed, w u0); angular momentum about
  /// the anchor, exactly 0 for a motion along the spring (relative to m l0 w u0).
  Drift drift(const Scene&, const State& s) const override {
    const Vec2 x = at(s.x, 1) - at(s.x, 0), v = at(s.v, 1);
    const double vmax = exact_.omega() * kStretch;
    Drift d;
    d.energy = energyError(s);
    d.momentum = (kSpringMass * v - kSpringMass * Vec2(exact_.velocity(s.time), 0)).norm() / (kSpringMass * vmax);
    d.angularMomentum = std::abs(kSpringMass * cross(x, v)) / (kSpringMass * kRest * vmax);
    return d;
  }
  void step(const Scene&, const State& s) override {
    track_.add(energyError(s));
    // Signed: the bob's coordinate along the spring's starting line, negative once it has passed
    // through the anchor (where the spring's direction, and with it the force's law, flips).
    closest_ = std::min(closest_, (at(s.x, 1) - at(s.x, 0)).x());
  }
  Metrics overRun() const override {
    Metrics m;
    track_.fill(m);
    m.minSeparation = closest_;
    return m;
  }
  Metrics finish(const Scene&, const State&, const RunResult& run) override {
    const State& s = run.final;
    const Vec2 x = at(s.x, 1) - at(s.x, 0), v = at(s.v, 1);
    Metrics m;
    m.position = (x - Vec2(kRest + exact_.displacement(s.time), 0)).norm();
    m.velocity = (v - Vec2(exact_.velocity(s.time), 0)).norm();
    m.energy = energyError(s);
    m.error = m.position;
    return m;
  }

 private:
  /// The energy of the spring-mass system itself (a damped spring has no potential in the
  /// simulator's sense, so the study computes it), against the closed form's, relative to the start.
  double energyError(const State& s) const {
    const Vec2 x = at(s.x, 1) - at(s.x, 0), v = at(s.v, 1);
    const double u = x.norm() - kRest;
    const double energy = 0.5 * kSpringMass * v.squaredNorm() + 0.5 * kSpringK * u * u;
    return std::abs(energy - exact_.energy(s.time)) / exact_.energy(0);
  }
  Oscillator exact_;
  EnergyErrorTrack track_;
  double closest_ = kRest + kStretch;
};

Problem spring(bool quick, double b) {
  const bool damped = b > 0;
  const double duration = damped ? 5.0 : 10.0;
  const double periods = duration * std::sqrt(kSpringK / kSpringMass) / (2 * M_PI);
  const std::string k = "k = " + numberText(kSpringK), time = numberText(duration) + " s";
  Problem p = integratorProblem(damped ? "spring-damped" : "spring",
                                damped ? "Damped spring (" + k + ", b = " + numberText(b) + ", " + time + ")"
                                       : "Undamped spring (" + k + ", " + time + ", " +
                                             numberText(std::round(periods)) + " periods)",
                                "position error at the end [m]",
                                sweep(quick, {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4}));
  p.scene = [b, duration](const Method& m, double dt) {
    SceneBuilder x;
    x.duration(duration).method(m, dt);
    const int anchor = x.particle(Vec2(0, 0), Vec2(0, 0), 1.0, true, 0.05);
    const int bob = x.particle(Vec2(kRest + kStretch, 0), Vec2(0, 0), kSpringMass, false, 0.05);
    x.spring(x.edge(anchor, bob), kSpringK, kRest, b);
    return x;
  };
  p.measure = [b] { return std::make_unique<SpringMeasure>(b); };
  p.omega = std::sqrt(kSpringK / kSpringMass);
  if (!damped) p.exactMinSeparation = kRest - kStretch;
  p.setup = {{"mass", kSpringMass}, {"k", kSpringK}, {"rest", kRest}, {"stretch", kStretch}, {"b", b},
             {"duration", duration}};
  return p;
}

// ---- Two-body orbit ----------------------------------------------------------------------------
// Two equal masses, G (m1 + m2) = 1, separated by 1 and moving apart at an angle: eccentricity
// 0.41, a = 0.770, period 2 pi a^1.5 = 4.25 s. The start is no apsis on purpose: there the first
// step's offset of symplectic Euler happens to be perpendicular to the velocity, which would hide
// its first-order error in the orbit's energy. The centre of mass rests at the origin.

constexpr double kG = 1.0, kBodyMass = 0.5, kOrbitPeriods = 2.0;
const Vec2 kRelX(1.0, 0.0), kRelV(0.25, 0.8);

double mu() { return kG * 2 * kBodyMass; }

class OrbitMeasure final : public Measurement {
 public:
  void step(const Scene& scene, const State& s) override {
    const Vec2 r = at(s.x, 1) - at(s.x, 0);
    closest_ = std::min(closest_, r.norm());
    // The orbit's exact energy (two bodies, resting centre of mass): mu-scaled from the closed form.
    track_.add(std::abs(mechanicalEnergy(scene, s) - energy_) / std::abs(energy_));
    double angle = std::atan2(r.y(), r.x());
    // Unwrap: the orbit turns counter-clockwise by less than pi per step at any sane step.
    while (angle < lastAngle_ - M_PI) angle += 2 * M_PI;
    while (angle > lastAngle_ + M_PI) angle -= 2 * M_PI;
    if (std::isnan(periodTime_) && angle >= 2 * M_PI)
      periodTime_ = lastTime_ + (s.time - lastTime_) * (2 * M_PI - lastAngle_) / (angle - lastAngle_);
    lastAngle_ = angle;
    lastTime_ = s.time;
  }

  Metrics overRun() const override {
    Metrics m;
    track_.fill(m);
    m.minSeparation = closest_;
    return m;
  }

  /// Energy against the orbit's (relative to it); momentum against 0 (relative to the start's
  /// sum m |v|); angular momentum against the start's (relative to it).
  Drift drift(const Scene& scene, const State& s) const override {
    double L = 0, scale = 0;
    for (int i = 0; i < 2; ++i) L += scene.massOf(i) * cross(at(s.x, i), at(s.v, i));
    const double L0 = 2 * kBodyMass * cross(0.5 * kRelX, 0.5 * kRelV);  // both bodies alike about the centre
    for (int i = 0; i < 2; ++i) scale += scene.massOf(i) * 0.5 * kRelV.norm();
    Drift d;
    d.energy = std::abs(mechanicalEnergy(scene, s) - energy_) / std::abs(energy_);
    d.momentum = momentum(scene, s.v).norm() / scale;
    d.angularMomentum = std::abs(L - L0) / std::abs(L0);
    return d;
  }

  Metrics finish(const Scene& scene, const State& initial, const RunResult& run) override {
    const KeplerOrbit orbit(mu(), kRelX, kRelV);
    const State& s = run.final;
    Metrics m;
    m.position = (at(s.x, 1) - at(s.x, 0) - orbit.position(s.time)).norm();
    const double e0 = mechanicalEnergy(scene, initial);
    m.energy = std::abs(mechanicalEnergy(scene, s) - e0) / std::abs(e0);
    m.momentum = momentum(scene, s.v).norm() / momentumScale(scene, initial.v);
    auto angular = [&](const State& st) {
      double L = 0;
      for (int i = 0; i < 2; ++i) L += scene.massOf(i) * cross(at(st.x, i), at(st.v, i));
      return L;
    };
    m.angularMomentum = std::abs(angular(s) - angular(initial)) / std::abs(angular(initial));
    m.period = std::abs(periodTime_ - orbit.period()) / orbit.period();  // NaN: never went round
    m.error = m.position;
    return m;
  }

 private:
  /// E = m_reduced eps with the reduced mass m1 m2 / (m1 + m2) and eps the specific orbital energy.
  static double exactEnergy() {
    return kBodyMass * kBodyMass / (2 * kBodyMass) * KeplerOrbit(mu(), kRelX, kRelV).specificEnergy();
  }
  double lastAngle_ = 0, lastTime_ = 0;
  double periodTime_ = kNotApplicable;
  double closest_ = kRelX.norm();
  const double energy_ = exactEnergy();
  EnergyErrorTrack track_;
};

Problem orbit(bool quick) {
  const KeplerOrbit exact(mu(), kRelX, kRelV);
  Problem p = integratorProblem("orbit",
                                "Two-body orbit (e = " + numberText(exact.eccentricity(), 2) + ", " +
                                    numberText(kOrbitPeriods) + " periods)",
                                "separation error at the end [m]",
                                sweep(quick, {0.05, 0.02, 0.01, 0.005, 0.002, 0.001, 5e-4, 2e-4, 1e-4}));
  p.scene = [](const Method& m, double dt) {
    const KeplerOrbit orbit(mu(), kRelX, kRelV);
    SceneBuilder x;
    x.duration(kOrbitPeriods * orbit.period()).method(m, dt);
    // Each body sits opposite the other about the resting centre of mass (equal masses).
    const int a = x.particle(-0.5 * kRelX, -0.5 * kRelV, kBodyMass, false, 0.02);
    const int b = x.particle(0.5 * kRelX, 0.5 * kRelV, kBodyMass, false, 0.02);
    x.gravitational(a, b, kG);
    return x;
  };
  p.measure = [] { return std::make_unique<OrbitMeasure>(); };
  p.exactMinSeparation = exact.semiMajorAxis() * (1 - exact.eccentricity());
  p.setup = {{"mass", kBodyMass}, {"G", kG},           {"mu", mu()},
             {"rx", kRelX.x()},  {"ry", kRelX.y()},    {"vx", kRelV.x()},
             {"vy", kRelV.y()},  {"periods", kOrbitPeriods}, {"a", exact.semiMajorAxis()},
             {"e", exact.eccentricity()}, {"period", exact.period()}};
  return p;
}

}  // namespace

std::vector<Method> integratorMethods() {
  std::vector<Method> out;
  for (const char* name : {"explicit-euler", "symplectic-euler", "implicit-euler", "linearized-implicit-euler"})
    out.push_back(Method{name, name, CollisionChoice{}});
  return out;
}

Problem problemHeading(std::string name, std::string title, std::string errorLabel, std::string kind,
                       std::vector<Method> methods, std::vector<double> dts) {
  Problem p;
  p.name = std::move(name);
  p.title = std::move(title);
  p.errorLabel = std::move(errorLabel);
  p.kind = std::move(kind);
  p.methods = std::move(methods);
  p.dts = std::move(dts);
  return p;
}

Vec2 momentum(const Scene& scene, const VecX& v) {
  Vec2 p = Vec2::Zero();
  for (int i = 0; i < scene.numParticles(); ++i)
    if (!scene.isFixed(i)) p += scene.massOf(i) * at(v, i);
  return p;
}

double momentumScale(const Scene& scene, const VecX& v) {
  double s = 0;
  for (int i = 0; i < scene.numParticles(); ++i)
    if (!scene.isFixed(i)) s += scene.massOf(i) * at(v, i).norm();
  return s;
}

std::vector<Problem> integratorProblems(bool quick) {
  return {projectile(quick), spring(quick, 0.0), spring(quick, 1.0), orbit(quick)};
}

}  // namespace fosssim::study
