// Running the multi-contact problems (contact_problems.h) in both modes and writing their CSV
// files. The run loop is the study's own rather than runScene's: the time series needs the
// simulator's per-step counters (zones, rigid zones) and the two modes' simulator options.
#include "contact_problems.h"

#include "csv.h"
#include "experiments.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace fosssim::study {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Particles in failsafe zones and zones moved rigidly after the last step. The default mode
/// counts both in StepStats; the course's handler counts only zones, every one of them rigid, and
/// names each particle's zone (zoneOf), which is what is counted for it.
void zoneCounts(const Simulator& sim, const Scene& scene, ContactMode mode, ContactSample& s) {
  const StepStats& st = sim.stats();
  if (mode == ContactMode::Default) {
    s.zoneParticles += st.zoneParticles;
    s.rigidZones += st.rigidZones;
    return;
  }
  for (int i = 0; i < scene.numParticles(); ++i) s.zoneParticles += !scene.isFixed(i) && sim.zoneOf(i) >= 0;
  s.rigidZones += st.zones;
}

/// The invariants of a state, added into `s` (the slot's shots add up).
void measure(const Scene& scene, const State& state, ContactSample& s) {
  s.kinetic += kineticEnergy(scene, state.v);
  s.energy += mechanicalEnergy(scene, state);
  s.momentum += momentum(scene, state.v).norm();
  double l = 0, height = 0;
  int movable = 0;
  for (int i = 0; i < scene.numParticles(); ++i) {
    l += scene.massOf(i) * cross(at(state.x, i), at(state.v, i));
    if (!scene.isFixed(i)) height += at(state.x, i).y(), ++movable;
  }
  s.angularMomentum += l;
  s.height += height / std::max(1, movable);
  s.overlap = std::max(s.overlap, measureOverlap(scene, state.x).deepest);
}

/// Sum m |x| |v|: the scale of an angular momentum error (the total may be near zero).
double angularScale(const Scene& scene, const State& s) {
  double l = 0;
  for (int i = 0; i < scene.numParticles(); ++i) l += scene.massOf(i) * at(s.x, i).norm() * at(s.v, i).norm();
  return l;
}

}  // namespace

const char* contactModeName(ContactMode mode) { return mode == ContactMode::Compat ? "compat" : "default"; }

ContactResult runContactProblem(const ContactProblem& problem, ContactMode mode, const std::string& collision) {
  ContactResult r;
  r.problem = problem.name;
  r.title = problem.title;
  r.mode = contactModeName(mode);
  r.collision = collision;
  r.shots = problem.shots;
  std::unique_ptr<ContactJudge> judge = problem.judge();
  long done = std::numeric_limits<long>::max();  // steps every shot completed
  for (int shot = 0; shot < problem.shots; ++shot) {
    SceneFile file;
    if (Status s = problem.scene(collision, shot).build(problem.name + ".xml", file); !s) {
      r.outcome = Outcome::Error;
      r.message = s.message();
      return r;
    }
    const Scene& scene = file.scene;
    std::unique_ptr<Simulator> sim;
    if (Status s = Simulator::create(scene, studySimulatorOptions(mode == ContactMode::Compat), sim); !s) {
      r.outcome = Outcome::Error;
      r.message = s.message();
      return r;
    }
    State state = file.initial, before;
    const State initial = state;
    r.dt = scene.dt;
    r.particles = 0;
    for (int i = 0; i < scene.numParticles(); ++i) r.particles += !scene.isFixed(i);
    if (problem.contained) r.escapable += r.particles;
    judge->start(scene, state);
    const long steps = scene.numSteps();
    if (r.series.size() < static_cast<size_t>(steps + 1)) r.series.resize(steps + 1);
    measure(scene, state, r.series[0]);
    std::vector<char> out(scene.numParticles(), 0);
    int escapedHere = 0;
    long completed = 0;
    for (long k = 0; k < steps; ++k) {
      before = state;
      const auto begin = std::chrono::steady_clock::now();
      const Status s = sim->step(scene, state);
      r.wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      if (!s) {  // a failed step is a result: the shot stops there, the others still run
        r.outcome = s.message().find("non-finite") != std::string::npos ? Outcome::NonFinite : Outcome::Error;
        r.message = "shot " + std::to_string(shot) + ": " + s.message();
        break;
      }
      ContactSample& sample = r.series[k + 1];
      sample.step = k + 1;
      sample.time = state.time;
      sample.contacts += std::max<long>(static_cast<long>(sim->log().impulses.size()), sim->stats().collisions);
      zoneCounts(*sim, scene, mode, sample);
      measure(scene, state, sample);
      judge->step(scene, before, state, sample.contacts);
      for (int i = 0; i < scene.numParticles(); ++i)
        if (!scene.isFixed(i) && !out[i] && judge->outside(scene, state, i)) out[i] = 1, ++escapedHere;
      sample.escaped += escapedHere;  // so far in this shot; the slot adds up its shots
      ++completed;
    }
    done = std::min(done, completed);
    r.escaped += escapedHere;
    r.shotsEscaped += escapedHere > 0;
    if (problem.isolated) {
      r.momentumDrift =
          (momentum(scene, state.v) - momentum(scene, initial.v)).norm() / momentumScale(scene, initial.v);
      ContactSample l0, l1;
      measure(scene, initial, l0);
      measure(scene, state, l1);
      r.angularDrift = std::abs(l1.angularMomentum - l0.angularMomentum) / angularScale(scene, initial);
    }
  }
  // Totals over the steps every shot completed (a failed shot's later samples are incomplete).
  if (done < static_cast<long>(r.series.size())) r.series.resize(done + 1);
  const double e0 = r.series.empty() ? 0 : r.series[0].energy;
  // E / E0 where E0 > 0; in general 1 + (E - E0) / |E0|, which is the same there and still rises
  // with a gain where the start is negative (a clump bound by its own gravitation).
  const auto relative = [e0](double e) { return 1.0 + (e - e0) / std::abs(e0); };
  r.energyGain = 1;
  for (const ContactSample& s : r.series) {
    r.energyGain = std::max(r.energyGain, relative(s.energy));
    const double fraction = s.zoneParticles / double(std::max(1, r.particles * r.shots));
    if (s.step > 0) {
      r.zoneFractionMean += fraction;
      r.zoneFractionMax = std::max(r.zoneFractionMax, fraction);
      r.failsafeSteps += s.zoneParticles > 0;
      r.rigidZoneSteps += s.rigidZones > 0;
    }
    r.maxOverlap = std::max(r.maxOverlap, s.overlap);
    r.contacts += s.contacts;
  }
  if (r.series.size() > 1) r.zoneFractionMean /= static_cast<double>(r.series.size() - 1);
  if (!r.series.empty()) r.energyEnd = relative(r.series.back().energy);
  double peak = 0;
  for (const ContactSample& s : r.series) peak = std::max(peak, s.kinetic);
  for (size_t k = r.series.size(); k-- > 0 && r.series[k].kinetic <= kStoppedEnergy * peak;)
    r.stoppedTime = r.series[k].time;
  if (r.series.size() > 1)
    r.stopped = r.stoppedTime <= r.series[1].time + kStoppedShare * (r.series.back().time - r.series[1].time);
  r.frozen = r.stopped;
  judge->finish(r);
  return r;
}

Status runContacts(const StudyOptions& options) {
  CsvWriter series, summary;
  if (Status s = series.open(options.outDir + "/contacts_series.csv",
                             {"problem", "mode", "collision", "step", "time", "energy", "kinetic", "momentum",
                              "angular_momentum", "contacts", "zone_particles", "zone_fraction", "rigid_zones",
                              "max_overlap", "escaped", "height"});
      !s)
    return s;
  if (Status s = summary.open(options.outDir + "/contacts_summary.csv",
                              {"problem", "title", "mode", "collision", "shots", "particles", "dt", "steps", "outcome",
                               "energy_gain", "energy_end", "momentum_drift", "angular_drift", "escaped", "escapable",
                               "shots_escaped", "speed_ratio", "speed_label", "others_speed", "stopped_time", "stopped",
                               "frozen", "zone_fraction_mean", "zone_fraction_max", "failsafe_steps",
                               "rigid_zone_steps", "height_start", "height_end", "height_frozen", "height_packed",
                               "packing_end", "max_overlap", "contacts", "wall_s", "stopped_energy", "stopped_share",
                               "loosest_rest", "message"});
      !s)
    return s;
  for (const ContactProblem& p : contactProblems(options.quick)) {
    if (options.log) *options.log << "contacts: " << p.name << std::flush;
    for (ContactMode mode : {ContactMode::Default, ContactMode::Compat})
      for (const char* collision : {"continuous-time", "hybrid"}) {
        const ContactResult r = runContactProblem(p, mode, collision);
        const double movable = std::max(1, r.particles * r.shots);
        for (const ContactSample& s : r.series) {
          series << r.problem << r.mode << r.collision << s.step << s.time << s.energy << s.kinetic << s.momentum
                 << s.angularMomentum << s.contacts << s.zoneParticles << s.zoneParticles / movable << s.rigidZones
                 << s.overlap << s.escaped << s.height / r.shots;
          if (Status st = series.endRow(); !st) return st;
        }
        const long steps = r.series.empty() ? 0 : static_cast<long>(r.series.size()) - 1;
        summary << r.problem << r.title << r.mode << r.collision << r.shots << r.particles << r.dt << steps
                << outcomeName(r.outcome) << r.energyGain << r.energyEnd << r.momentumDrift << r.angularDrift
                << r.escaped << r.escapable << r.shotsEscaped << r.speedRatio << p.speedLabel << r.othersSpeed
                << r.stoppedTime << (r.stopped ? 1L : 0L) << (r.frozen ? 1L : 0L)
                << r.zoneFractionMean << r.zoneFractionMax << r.failsafeSteps << r.rigidZoneSteps
                << (r.series.empty() ? kNotApplicable : r.series.front().height / r.shots)
                << (r.series.empty() ? kNotApplicable : r.series.back().height / r.shots) << r.heightFrozen
                << r.heightPacked << r.packingEnd << r.maxOverlap << r.contacts << r.wallSeconds << kStoppedEnergy
                << kStoppedShare << kLoosestRest << r.message;
        if (Status st = summary.endRow(); !st) return st;
        if (options.log) *options.log << "." << std::flush;
      }
    if (options.log) *options.log << "\n";
  }
  return Status::ok();
}

}  // namespace fosssim::study
