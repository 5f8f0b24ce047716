#include "fosssim/core/simulator.h"

#include "energy_watch.h"

#include "core/collision/parallel_rows.h"
#include "core/short_number.h"
#include "fosssim/core/scene_values.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fosssim {

Simulator::Simulator() = default;
Simulator::~Simulator() = default;

Status Simulator::create(const Scene& scene, const SimulatorOptions& options,
                         std::unique_ptr<Simulator>& out) {
  const IntegratorEntry* integrator = findIntegrator(scene.integrator);
  if (!integrator) return Status::error("unknown integrator '" + scene.integrator + "'");
  if (!(scene.dt > 0.0) || !std::isfinite(scene.dt))
    return Status::error("the time step must be positive and finite, got " + shortNumber(scene.dt));
  if (options.handler.threads < 1)
    return Status::error("threads must be at least 1, got " + std::to_string(options.handler.threads));
  if (Status s = checkSceneShape(scene); !s) return s;
  if (Status s = checkSceneValues(scene); !s) return s;
  const CollisionEntry* collision = &collisionEntry(scene.collision.type);
  std::unique_ptr<Simulator> sim(new Simulator());
  sim->collision_ = collision;
  sim->integratorKeyword_ = scene.integrator;
  sim->dt_ = scene.dt;
  sim->settings_ = scene.collision;
  sim->integrator_ = integrator->make();
  sim->integrator_->setCourseForm(options.handler.compat);
  sim->holdsResting_ = integrator->implicit;
  if (collision->make) sim->handler_ = collision->make(scene.collision, options.handler);
  sim->log_.polynomials.setEnabled(options.logPolynomials && collision->layout.polynomials);
  sim->forces_ = ForceContext(options.handler.allPairs, options.handler.threads);
  sim->energyWatch_ = std::make_unique<EnergyWatch>(options.watchEnergy);
  out = std::move(sim);
  return Status::ok();
}

namespace {

/// What made the first non-finite particle of `end` so: when the integrator's prediction was
/// already non-finite, the forces on it at the step's start (one that is non-finite there, else
/// the largest), named as the energy watch names them (forceOrdinal: "'springforce' #2", the
/// second <springforce> of the file); otherwise the collision response. Only on failure, and
/// only when evaluating every force separately is cheap enough (forces x particles <= 5e7).
std::string blameNonFinite(const Scene& scene, const State& start, const State& end, bool predictionFinite,
                           const char* handler) {
  if (predictionFinite)
    return std::string("; the integrator's prediction was finite: the collision response (") + handler +
           ") made it non-finite";
  int i = 0;
  while (i < end.numParticles() && at(end.x, i).allFinite() && at(end.v, i).allFinite()) ++i;
  const size_t n = scene.forces.size();
  if (i == end.numParticles() || n == 0 || static_cast<double>(n) * end.numParticles() > 5e7 ||
      start.x.size() != end.x.size())
    return n == 0 ? "; no force acts: the integrator made it non-finite" : "";
  int blamed = -1;
  double largest = -1;
  bool nonFinite = false;
  VecX gradient(start.x.size());
  for (size_t f = 0; f < n && !nonFinite; ++f) {
    gradient.setZero();
    scene.forces[f]->addGradient(scene, start.x, start.v, gradient);
    const Vec2 pull = at(gradient, i);
    nonFinite = !pull.allFinite();
    if (nonFinite || pull.norm() > largest) blamed = static_cast<int>(f), largest = pull.norm();
  }
  const std::string name = forceOrdinal(scene, blamed);
  if (nonFinite) return "; the force " + name + " on it was already non-finite at the step's start";
  return "; the integrator made it non-finite; the largest force on it at the step's start was " + name + " (|F| = " +
         shortNumber(largest) + "): a smaller dt or a weaker force may help";
}

/// Why an integrator's solve failed, where a force says: the first force (in the scene's order)
/// that is non-finite on some particle at the step's start (coincident ends of a spring, a
/// gravitational or a vortex pair), naming both. Empty when every force is finite there, or when
/// evaluating each force separately is too costly (as blameNonFinite).
/// Otherwise, when one force is so stiff that its entry in the system (M - h dF/dv - h^2 dF/dx)
/// swamps a free particle's mass (h^2 |d2E/dx2| + h |dF/dv| above 1e12 m on the diagonal; beyond
/// about 1e16 the mass is lost in rounding and the matrix is singular, e.g. a spring of k = 1e300),
/// that force and particle, with what to change.
std::string blameSolve(const Scene& scene, const State& start, double dt) {
  const size_t n = scene.forces.size();
  if (n == 0 || static_cast<double>(n) * start.numParticles() > 5e7) return "";
  VecX gradient(start.x.size());
  for (size_t f = 0; f < n; ++f) {
    gradient.setZero();
    scene.forces[f]->addGradient(scene, start.x, start.v, gradient);
    for (int i = 0; i < start.numParticles(); ++i)
      if (!at(gradient, i).allFinite())
        return "; the force " + forceOrdinal(scene, static_cast<int>(f)) + " on particle " + std::to_string(i) +
               " is non-finite at the step's start";
  }
  int blamed = -1, particle = -1;
  double largest = 0;
  Triplets jx, jv;
  VecX diagonal(start.x.size());
  for (size_t f = 0; f < n; ++f) {
    if (!scene.forces[f]->hasJacobians()) continue;
    jx.clear();
    jv.clear();
    scene.forces[f]->addJacobianX(scene, start.x, start.v, jx);
    scene.forces[f]->addJacobianV(scene, start.x, start.v, jv);
    diagonal.setZero();
    for (const auto& t : jx)
      if (t.row() == t.col()) diagonal[t.row()] += dt * dt * t.value();
    for (const auto& t : jv)
      if (t.row() == t.col()) diagonal[t.row()] += dt * t.value();
    for (Eigen::Index r = 0; r < diagonal.size(); ++r) {
      const int i = static_cast<int>(r / 2);
      const double ratio = std::fabs(diagonal[r]) / scene.mass[r];
      if (!scene.isFixed(i) && ratio > largest) largest = ratio, blamed = static_cast<int>(f), particle = i;
    }
  }
  if (blamed < 0 || !(largest > 1e12)) return "";
  return "; the stiffest force is " + forceOrdinal(scene, blamed) + " on particle " + std::to_string(particle) +
         ": dt^2 times its stiffness is " + shortNumber(largest) +
         " times the particle's mass (beyond about 1e16 the mass is lost in rounding); make that force softer (its k) "
         "or dt smaller, until dt^2 k / m is far below 1e12";
}

/// to = from, the positions and velocities by ranges of particles on `threads`.
void copyState(const State& from, State& to, int threads) {
  to.time = from.time;  // State's four members
  to.step = from.step;
  copyByParticles(from.x, to.x, threads);
  copyByParticles(from.v, to.v, threads);
}

/// Equal, or both NaN (a hand-built scene's NaN setting is the same setting).
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

bool sameSettings(const CollisionSettings& a, const CollisionSettings& b) {
  return a.type == b.type && same(a.cor, b.cor) && a.maxIterations == b.maxIterations && a.failsafe == b.failsafe &&
         same(a.penaltyK, b.penaltyK) && same(a.penaltyThickness, b.penaltyThickness);
}

}  // namespace

Status Simulator::step(const Scene& scene, State& state, StepObserver* observer) {
  const double dt = dt_;
  const long stepNumber = state.step + 1;
  // Every failure names the step by its interval, whichever phase failed (the verify phase has
  // moved state.time to the end by then; a failure in the prediction has not).
  const double t0 = state.time;
  auto failure = [&](const std::string& what) {
    return Status::error("step " + std::to_string(stepNumber) + " (t = " + shortNumber(t0) + " to " +
                         shortNumber(t0 + dt) + "): " + what);
  };
  if (!same(scene.dt, dt_) || scene.integrator != integratorKeyword_ || !sameSettings(scene.collision, settings_))
    return failure("the scene's settings (integrator, dt or collision) changed since the simulator was created; "
                   "create a new simulator for the new settings");
  // A scene built in code can change between steps, in place too (an edge's index, a mass): its
  // shape and values are checked at every step. That is O(N + E + forces), a pass over arrays the
  // step itself reads several times over; a check only when a count changed let an index changed
  // in place through, and the step read out of bounds.
  if (Status s = checkSceneShape(scene, &state); !s) return failure(s.message());
  if (Status s = checkSceneValues(scene); !s) return failure(s.message());

  stats_.clear();
  const StepTimer stepTimer(timing_, stats_.total);

  // 1. Predict: the integrator moves every particle as if nothing collided.
  copyState(state, start_, forces_.threads());
  {
    const StepTimer timer(timing_, stats_.integrate);
    // Sleepers go back where they rest whatever is predicted for them. An explicit method
    // predicts every other particle from its own force, which stays the same bit for bit, and
    // leaves the sleepers' predictions incomplete: not with the polynomial log, which records
    // every pair's predicted motion, sleepers' too. An implicit method holds them where they rest
    // (their prediction: at rest, which the log may record).
    const bool restingKnown = handler_ && (holdsResting_ || !log_.polynomials.enabled());
    forces_.setResting(restingKnown ? handler_->restingAtStart(scene, start_) : nullptr);
    const Status s = integrator_->step(scene, state, dt, forces_);
    forces_.setResting(nullptr);
    stats_.newtonIterations = integrator_->newtonIterations();  // failed solves too: how far Newton got
    if (!s) return failure(s.message() + blameSolve(scene, start_, dt));
  }
  const bool predictionFinite = state.x.allFinite() && state.v.allFinite();  // to blame forces or response
  // A non-finite prediction is the forces' doing: said here, naming the particle and force,
  // before the collision handler tries to test its pairs and reports an overflow instead.
  if (!predictionFinite)
    if (Status s = checkFinite(state, forces_.threads()); !s)
      return failure(s.message() + blameNonFinite(scene, start_, state, false, collision_->keyword));

  // 2-3. Detect and respond: the handler turns the prediction into a collision-free end state.
  log_.clear();
  if (handler_) {
    StepContext ctx{dt, &log_, observer, &stats_, timing_};
    if (Status s = handler_->handle(scene, start_, state, ctx); !s) return failure(s.message());
  }

  // 4. Verify: a non-finite state or an energy blow-up is reported, never carried on.
  state.step = stepNumber;
  state.time = start_.time + dt;
  if (Status s = checkFinite(state, forces_.threads()); !s)
    return failure(s.message() + blameNonFinite(scene, start_, state, predictionFinite, collision_->keyword));
  if (Status s = energyWatch_->check(scene, start_, state, forces_); !s) return failure(s.message());
  return Status::ok();
}

std::vector<Violation> Simulator::unresolved(const Scene& scene, const State& state, size_t limit) const {
  // Before the first step there is no step's motion to check (start_ is empty); a state of
  // another size than the last step's is not that step's end.
  if (start_.x.size() == 0 || start_.x.size() != state.x.size()) return {};
  if (handler_) return handler_->unresolved(scene, start_.x, state.x, limit);
  return unresolvedCollisions(scene, start_.x, state.x, nullptr, limit);
}

double Simulator::energyGrowth() const { return energyWatch_->largestGrowth(); }

Status checkFinite(const State& state, int threads) {
  const int n = state.numParticles();
  if (state.x.size() == state.v.size() && state.x.size() == 2L * n) {
    std::vector<char> finite(static_cast<size_t>(rowRangesFor(n, threads)), 1);
    forRowRanges(n, threads, [&](int range, int first, int end) {
      const long k = 2L * first, count = 2L * (end - first);
      finite[range] = state.x.segment(k, count).allFinite() && state.v.segment(k, count).allFinite();
    });
    if (std::all_of(finite.begin(), finite.end(), [](char f) { return f != 0; })) return Status::ok();
  }
  for (int i = 0; 2L * i + 1 < std::min(state.x.size(), state.v.size()); ++i) {
    const bool badX = !at(state.x, i).allFinite(), badV = !at(state.v, i).allFinite();
    if (!badX && !badV) continue;
    std::ostringstream msg;
    msg << "particle " << i << " has a non-finite " << (badX ? "position" : "velocity") << " ("
        << (badX ? at(state.x, i) : at(state.v, i)).transpose() << ")";
    return Status::error(msg.str());
  }
  return Status::error("the state has the wrong size");
}

}  // namespace fosssim
