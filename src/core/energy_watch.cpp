// The energy watch (see energy_watch.h for the criterion and why).
#include "energy_watch.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace fosssim {
namespace {

/// Diagonal of the box around every particle's disk: how far anything in the scene is from
/// anything else at the start (independent of where the origin is).
double extentOf(const Scene& scene, const VecX& x) {
  if (scene.numParticles() == 0) return 0;
  Vec2 lo = at(x, 0), hi = lo;
  for (int i = 0; i < scene.numParticles(); ++i) {
    const Vec2 r = Vec2::Constant(scene.radius[i]);
    lo = lo.cwiseMin(at(x, i) - r);
    hi = hi.cwiseMax(at(x, i) + r);
  }
  return (hi - lo).norm();
}

/// What the forces that are not spring-like (stiffness() == 0: gravity, constant forces,
/// gravitation) may add per step through the first-order error of a step: the kinetic energy of
/// one explicit step, sum_i |F_i dt|^2 / (2 m_i). Explicit Euler moves particles with the old
/// velocity, so a fall from rest gains exactly that per step; a collision response that reflects
/// a velocity which took a full step of gravity gains about as much per step of a bouncing
/// ball's run (measured: a ball with COR 1 under continuous-time or hybrid handling gains
/// 0.9 m g^2 dt / 2 per unit of time). Capped by the work those forces could do across the whole
/// scene, extent * sum_i |F_i| (gravitation between disks that start very close is huge).
double driftPerStep(const Scene& scene, const State& start) {
  VecX gradE = VecX::Zero(start.x.size());
  for (const auto& f : scene.forces)
    if (f->stiffness() == 0) f->addGradient(scene, start.x, start.v, gradE);
  double force = 0, oneStep = 0;
  for (int i = 0; i < scene.numParticles(); ++i) {
    if (scene.isFixed(i)) continue;
    force += at(gradE, i).norm();
    oneStep += at(gradE, i).squaredNorm() * scene.dt * scene.dt / (2 * scene.massOf(i));
  }
  return std::min(oneStep, extentOf(scene, start.x) * force);
}

/// True when nothing outside the scene's potentials can add energy (see energy_watch.h).
bool closedScene(const Scene& scene, const State& state) {
  for (const auto& f : scene.forces)
    if (f->mayAddEnergy()) return false;
  for (int i = 0; i < scene.numParticles(); ++i)
    if (scene.isFixed(i) && !at(state.v, i).isZero(0)) return false;
  return true;
}

std::string number(double value) {
  std::ostringstream s;
  s.precision(3);
  s << value;
  return s.str();
}

/// "'springforce' #2 (k = 100)".
std::string forceName(const Scene& scene, int index) {
  std::string name = forceOrdinal(scene, index);
  const Force& force = *scene.forces[static_cast<size_t>(index)];
  if (force.stiffness() > 0) name += " (k = " + number(force.stiffness()) + ")";
  return name;
}

}  // namespace

std::string forceOrdinal(const Scene& scene, int index) {
  const Force& force = *scene.forces[static_cast<size_t>(index)];
  int nth = 1;
  for (int f = 0; f < index; ++f)
    nth += std::string(scene.forces[static_cast<size_t>(f)]->keyword()) == force.keyword();
  return "'" + std::string(force.keyword()) + "' #" + std::to_string(nth);
}

void EnergyWatch::potentials(const Scene& scene, const VecX& x, const VecX& v, ForceContext& forces,
                             std::vector<double>& out) const {
  out.resize(scene.forces.size());
  for (size_t f = 0; f < scene.forces.size(); ++f) out[f] = scene.forces[f]->energyWith(scene, x, v, forces);
}

Status EnergyWatch::begin(const Scene& scene, const State& start, ForceContext& forces) {
  started_ = true;
  active_ = wanted_ && closedScene(scene, start);
  largestGrowth_ = 0;
  released_ = 0;
  tracked_.clear();
  if (!active_) return Status::ok();
  std::vector<double> potential0;
  potentials(scene, start.x, start.v, forces, potential0);
  const double kinetic0 = kineticEnergy(scene, start.v);
  double magnitude = kinetic0, stored = 0;
  energy0_ = kinetic0;
  for (size_t f = 0; f < potential0.size(); ++f) {
    const Force& force = *scene.forces[f];
    energy0_ += potential0[f];
    magnitude += std::abs(potential0[f]);
    if (force.stiffness() > 0) stored += potential0[f];
    else if (force.hasPotential()) tracked_.push_back(Tracked{static_cast<int>(f), potential0[f]});
  }
  baseScale_ = kinetic0 + stored + kRoundingShare * magnitude;
  driftPerStep_ = driftPerStep(scene, start);
  steps_ = 0;
  if (std::isfinite(energy0_) && std::isfinite(baseScale_)) return Status::ok();
  active_ = false;  // no baseline: a caller that goes on anyway is not checked against garbage
  std::ostringstream msg;
  msg << "the scene's energy at the start is not finite: ";
  for (int i = 0; i < scene.numParticles(); ++i) {
    const double kinetic = 0.5 * scene.massOf(i) * at(start.v, i).squaredNorm();
    if (std::isfinite(kinetic)) continue;
    msg << "particle " << i << "'s kinetic energy m |v|^2 / 2 overflows (mass " << number(scene.massOf(i))
        << ", speed " << number(std::hypot(start.v[2 * i], start.v[2 * i + 1]))
        << "); velocities and masses this large leave no room for a step's arithmetic: choose smaller units";
    return Status::error(msg.str());
  }
  for (size_t f = 0; f < potential0.size(); ++f) {
    if (std::isfinite(potential0[f])) continue;
    msg << "the potential of " << forceOrdinal(scene, static_cast<int>(f)) << " is " << number(potential0[f])
        << "; its parameters or the positions are too large to represent its energy: choose smaller units";
    return Status::error(msg.str());
  }
  msg << "the sum of the kinetic and potential energies overflows (" << number(energy0_)
      << "); choose smaller units";
  return Status::error(msg.str());
}

Status EnergyWatch::check(const Scene& scene, const State& start, const State& end, ForceContext& forces) {
  if (!started_ || start.step == 0)
    if (Status s = begin(scene, start, forces); !s) return s;
  if (!active_) return Status::ok();
  // Spring-like potentials are left out from here on (see the header): the gain below is a
  // lower bound of the true one, so it never flags what the full sum would not.
  double energy = kineticEnergy(scene, end.v), released = 0;
  for (const Tracked& t : tracked_) {
    const double u = scene.forces[t.force]->energyWith(scene, end.x, end.v, forces);
    energy += u;
    released += std::max(0.0, t.start - u);
  }
  released_ = std::max(released_, released);
  ++steps_;
  const double gain = energy - energy0_, scale = baseScale_ + released_ + steps_ * driftPerStep_;
  if (scale > 0) largestGrowth_ = std::max(largestGrowth_, gain / scale);
  // Written so that a NaN or infinite gain fails too (an overflowed kinetic energy), whatever
  // the scale (a penalty k of 1e308 overflows it, and inf <= inf held). A scene with no energy
  // at all (nothing moves, no force) has scale 0 and stays at gain 0.
  if (std::isfinite(gain) && gain <= kBlowUpGrowth * scale) return Status::ok();
  return Status::error(explain(scene, start, end, forces, gain, scale));
}

std::string EnergyWatch::explain(const Scene& scene, const State& start, const State& end, ForceContext& forces,
                                 double gain, double scale) const {
  std::ostringstream msg;
  msg << "energy blow-up: with nothing outside doing work, the mechanical energy ";
  if (std::isfinite(gain))
    msg << "grew by at least " << number(gain) << ", " << number(gain / scale) << " times the scene's energy scale "
        << number(scale) << " (the limit is " << number(kBlowUpGrowth) << " times)";
  else
    msg << "overflowed";

  // The fastest particle (largest kinetic energy) and the lightest moving mass.
  int fastest = -1;
  double most = -1, lightest = 0;
  for (int i = 0; i < scene.numParticles(); ++i) {
    if (scene.isFixed(i)) continue;
    const double m = scene.massOf(i), kinetic = 0.5 * m * at(end.v, i).squaredNorm();
    if (fastest < 0 || kinetic > most || std::isnan(kinetic)) fastest = i, most = kinetic;
    lightest = lightest == 0 ? m : std::min(lightest, m);
  }
  if (fastest >= 0)  // hypot: |v| squared may overflow where v does not
    msg << "; particle " << fastest << " is fastest, at speed "
        << number(std::hypot(end.v[2 * fastest], end.v[2 * fastest + 1]));

  // Two forces to name: the one whose potential changed most over this step (where the energy
  // went through), and the stiffest spring-like force, the one a step resolves worst (at work
  // in this step if any is: nonzero energy before or after; among equals the one that changed
  // most). They differ when a stiff penalty layer throws two disks apart and the soft spring
  // that ties them takes up the energy: the advice is about the stiff one.
  std::vector<double> before, after;
  potentials(scene, start.x, start.v, forces, before);
  potentials(scene, end.x, end.v, forces, after);
  int changed = -1, stiffest = -1;
  double change = 0;
  auto rank = [&](int f) {
    const bool atWork = before[f] != 0 || after[f] != 0;
    return std::make_tuple(atWork, scene.forces[f]->stiffness(), std::abs(after[f] - before[f]));
  };
  for (int f = 0; f < static_cast<int>(before.size()); ++f) {
    const double c = std::abs(after[f] - before[f]);
    if (c > change || (std::isnan(c) && changed < 0)) changed = f, change = c;
    if (scene.forces[f]->stiffness() > 0 && (stiffest < 0 || rank(f) > rank(stiffest))) stiffest = f;
  }
  if (changed >= 0)
    msg << "; the energy of force " << forceName(scene, changed) << " changed most in this step, by " << number(change);
  if (stiffest >= 0 && stiffest != changed) msg << "; the stiffest force is " << forceName(scene, stiffest);

  msg << ". Try a smaller time step (dt = " << number(scene.dt) << ")";
  if (stiffest >= 0) {
    // A stiffness k on a mass m oscillates at omega = sqrt(k/m); explicit steps (and the
    // implicit integrators for forces without a Jacobian, like the penalty) need omega dt < ~1.
    const double k = scene.forces[stiffest]->stiffness();
    msg << " or a smaller stiffness k: steps resolve k = " << number(k) << " on the lightest mass "
        << number(lightest) << " only for dt below about sqrt(m/k) = " << number(std::sqrt(lightest / k));
  } else {
    msg << " or weaker forces";
  }
  if (scene.integrator == "explicit-euler")
    msg << "; explicit Euler gains energy on every oscillation at any dt, symplectic or implicit Euler do not";
  return msg.str();
}

}  // namespace fosssim
