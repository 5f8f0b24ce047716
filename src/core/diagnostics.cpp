// Per-step diagnostics (diagnostics.h). Everything is a sum over particles or forces of the
// state as it is, so measuring never changes a run.
#include "fosssim/core/diagnostics.h"

#include "fosssim/core/collision_log.h"

#include <numeric>

namespace fosssim {

double StepDiagnostics::potentialTotal() const { return std::accumulate(potential.begin(), potential.end(), 0.0); }

void measureState(const Scene& scene, const State& state, StepDiagnostics& out) {
  out.step = state.step;
  out.time = state.time;
  out.kinetic = kineticEnergy(scene, state.v);
  out.potential.resize(scene.forces.size());
  for (size_t k = 0; k < scene.forces.size(); ++k) out.potential[k] = scene.forces[k]->energy(scene, state.x, state.v);
  // Fixed particles take no part: they never move, whatever velocity the file gave them.
  double px = 0, py = 0, l = 0;
  for (int i = 0, n = scene.numParticles(); i < n; ++i) {
    if (scene.isFixed(i)) continue;
    const double m = scene.massOf(i);
    const Vec2 x = at(state.x, i), v = at(state.v, i);
    px += m * v.x();
    py += m * v.y();
    l += m * cross(x, v);
  }
  out.momentumX = px;
  out.momentumY = py;
  out.angularMomentum = l;
}

void measureStep(const Scene& scene, const State& state, const CollisionLog& log, const StepStats& stats,
                 StepDiagnostics& out) {
  measureState(scene, state, out);
  out.contacts = static_cast<long>(log.impulses.size());
  out.failsafeZones = stats.zones;
  out.zoneParticles = stats.zoneParticles;
  out.rigidZones = stats.rigidZones;
  out.cost = stats;
}

std::vector<std::string> diagnosticColumns(const Scene& scene) {
  std::vector<std::string> names = {"step", "time", "kinetic", "potential", "energy"};
  for (size_t k = 0; k < scene.forces.size(); ++k) {
    std::string keyword = scene.forces[k]->keyword();
    for (char& c : keyword)
      if (c == ' ') c = '_';  // "collision penalty"
    names.push_back("potential_" + std::to_string(k) + "_" + keyword);
  }
  for (const char* name :
       {"momentum_x", "momentum_y", "angular_momentum", "contacts", "failsafe_zones", "zone_particles", "rigid_zones",
        "candidate_pairs", "newton_iterations", "asleep", "cost_integrate", "cost_broad_phase", "cost_narrow_phase",
        "cost_response", "cost_failsafe", "cost_total"})
    names.emplace_back(name);
  return names;
}

void diagnosticRow(const StepDiagnostics& d, std::vector<double>& row) {
  const double potential = d.potentialTotal();
  row.assign({static_cast<double>(d.step), d.time, d.kinetic, potential, d.kinetic + potential});
  row.insert(row.end(), d.potential.begin(), d.potential.end());
  const StepStats& c = d.cost;
  row.insert(row.end(), {d.momentumX, d.momentumY, d.angularMomentum, static_cast<double>(d.contacts),
                         static_cast<double>(d.failsafeZones), static_cast<double>(d.zoneParticles),
                         static_cast<double>(d.rigidZones), static_cast<double>(c.candidatePairs),
                         static_cast<double>(c.newtonIterations), static_cast<double>(c.asleep), c.integrate,
                         c.broadPhase, c.narrowPhase, c.response, c.failsafe, c.total});
}

}  // namespace fosssim
