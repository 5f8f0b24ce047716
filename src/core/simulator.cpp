#include "fosssim/core/simulator.h"

#include "collision/pair_candidates.h"
#include "energy_watch.h"

#include <cmath>
#include <sstream>

namespace fosssim {

Simulator::Simulator() = default;
Simulator::~Simulator() = default;

Status Simulator::create(const Scene& scene, const SimulatorOptions& options,
                         std::unique_ptr<Simulator>& out) {
  const IntegratorEntry* integrator = findIntegrator(scene.integrator);
  if (!integrator) return Status::error("unknown integrator '" + scene.integrator + "'");
  const CollisionEntry* collision = findCollisionType(scene.collision.type);
  if (!collision) return Status::error("unknown collision type '" + scene.collision.type + "'");
  std::unique_ptr<Simulator> sim(new Simulator());
  sim->collision_ = collision;
  sim->integrator_ = integrator->make();
  if (collision->make) sim->handler_ = collision->make(scene.collision, options.handler);
  sim->log_.polynomials.setEnabled(options.logPolynomials && collision->layout.polynomials);
  sim->handlerOptions_ = options.handler;
  sim->energyWatch_ = std::make_unique<EnergyWatch>(options.watchEnergy);
  out = std::move(sim);
  return Status::ok();
}

Status Simulator::step(const Scene& scene, State& state, StepObserver* observer) {
  const double dt = scene.dt;
  const long stepNumber = state.step + 1;
  auto failure = [&](const std::string& what) {
    return Status::error("step " + std::to_string(stepNumber) + " (t = " + std::to_string(state.time) +
                         "): " + what);
  };

  stats_.clear();
  const StepTimer stepTimer(timing_, stats_.total);
  // For the penalty force (the handlers know already).
  const PairSearchScope pairSearch(PairSearchSettings{handlerOptions_.allPairs, handlerOptions_.threads});

  // 1. Predict: the integrator moves every particle as if nothing collided.
  start_ = state;
  {
    const StepTimer timer(timing_, stats_.integrate);
    if (Status s = integrator_->step(scene, state, dt); !s) return failure(s.message());
  }

  // 2-3. Detect and respond: the handler turns the prediction into a collision-free end state.
  log_.clear();
  if (handler_) {
    StepContext ctx{dt, &log_, observer, &stats_, timing_};
    if (Status s = handler_->handle(scene, start_, state, ctx); !s) return failure(s.message());
  }

  // 4. Verify: a non-finite state or an energy blow-up is reported, never carried on.
  state.step = stepNumber;
  state.time = start_.time + dt;
  if (Status s = checkFinite(state); !s) return failure(s.message());
  if (Status s = energyWatch_->check(scene, start_, state); !s) return failure(s.message());
  return Status::ok();
}

std::vector<Violation> Simulator::unresolved(const Scene& scene, const State& state, size_t limit) const {
  if (handler_) return handler_->unresolved(scene, start_.x, state.x, limit);
  return unresolvedCollisions(scene, start_.x, state.x, nullptr, limit);
}

double Simulator::energyGrowth() const { return energyWatch_->largestGrowth(); }

Status checkFinite(const State& state) {
  if (state.x.allFinite() && state.v.allFinite()) return Status::ok();
  for (int i = 0; i < state.numParticles(); ++i) {
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
