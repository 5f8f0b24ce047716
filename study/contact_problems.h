// Multi-contact problems: scenes where several contacts meet in one step (a joint of two floor
// edges, a touching rack, a narrow corridor or slot, a cradle, a pile in a V, a self-gravitating
// clump). Each runs with the
// default mode's time-ordered contacts and with --compat (the course's summed impulses, one-pass
// continuous-time and freezing rigid zones), for "continuous-time" and "hybrid", recording energy,
// momentum and angular momentum over time and the outcome each problem is about (a gain of
// energy, an escape through a wall, a frozen particle or pile). Written to contacts_series.csv and
// contacts_summary.csv (experiments.h: runContacts).
#pragma once

#include "problems.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fosssim::study {

enum class ContactMode { Default, Compat };
/// "default", "compat".
const char* contactModeName(ContactMode mode);

/// One step end of a run. For a problem of several shots (the slot), the shots' values are added.
struct ContactSample {
  long step = 0;
  double time = 0;
  double energy = 0;           ///< kinetic + potential (gravity, and the hybrid's penalty layer)
  double kinetic = 0;
  double momentum = 0;         ///< |sum m v|
  double angularMomentum = 0;  ///< sum m x × v about the origin
  long contacts = 0;           ///< impulses (or, where the handler logs none, collisions found)
  int zoneParticles = 0;       ///< particles in failsafe zones at the end of the step
  int rigidZones = 0;          ///< zones moved rigidly (--compat: every zone)
  double overlap = 0;          ///< deepest overlap of any pair at the step end [m]
  int escaped = 0;             ///< particles that have left their container so far
  double height = 0;           ///< mean centre height of the movable particles [m]
};

/// A run has stopped when its kinetic energy stays at or below kStoppedEnergy of its peak from a
/// time within the first kStoppedShare of the run to its end.
constexpr double kStoppedEnergy = 1e-12, kStoppedShare = 0.75;
/// The pile is frozen when it stopped packed looser than this (contact_scenes.cpp says why).
constexpr double kLoosestRest = 0.75;

/// A problem's run in one mode with one collision type, and its outcome.
struct ContactResult {
  std::string problem, title, mode, collision;
  Outcome outcome = Outcome::Ok;
  std::string message;
  int shots = 1;
  int particles = 0;  ///< movable particles per shot
  double dt = 0;
  std::vector<ContactSample> series;
  /// Largest E / E0 over the run (in general 1 + (E - E0) / |E0|: the same for E0 > 0, and still a
  /// gain above 1 for a negative E0, a clump bound by its own gravitation).
  double energyGain = kNotApplicable;
  double energyEnd = kNotApplicable;      ///< E_end / E0 (the same generalised)
  double momentumDrift = kNotApplicable;  ///< |P_end - P_0| / sum m|v_0| (problems without walls or floors)
  double angularDrift = kNotApplicable;   ///< |L_end - L_0| / sum m|x_0||v_0| (the same problems)
  int escaped = 0;              ///< particles that left their container (summed over shots)
  int escapable = 0;            ///< particles that could have (summed over shots)
  int shotsEscaped = 0;         ///< shots in which some particle left
  double speedRatio = kNotApplicable;     ///< the problem's headline speed ratio (ContactProblem::speedLabel)
  double othersSpeed = kNotApplicable;    ///< cradle: fastest of the first four balls at the end / cue speed
  /// Time from which the kinetic energy stays at or below 1e-12 of its peak until the end (NaN
  /// if it does not end so): a course rigid zone touching a wall or floor sets its velocities to 0.
  double stoppedTime = kNotApplicable;
  bool stopped = false;         ///< at rest for at least the last quarter of the run
  /// Stopped where it should not have: by default the same as `stopped` (nothing in these
  /// problems comes to rest but a pile); the pile's judge adds "while loosely packed".
  bool frozen = false;
  double zoneFractionMean = 0;  ///< particles in zones / movable particles, mean over steps
  double zoneFractionMax = 0;
  long failsafeSteps = 0;       ///< steps with some particle in a zone
  long rigidZoneSteps = 0;      ///< steps with some rigid zone
  double heightFrozen = kNotApplicable;   ///< pile: mean height had the column stopped at its first contact
  double heightPacked = kNotApplicable;   ///< pile: mean height of the densest lattice filling of the V
  double packingEnd = kNotApplicable;     ///< pile: packing fraction the mean height at the end implies
  double maxOverlap = 0;
  long contacts = 0;
  double wallSeconds = 0;

};

class ContactJudge;

struct ContactProblem {
  std::string name;        ///< file-friendly id, e.g. "joint-drop"
  std::string title;       ///< for charts and tables
  std::string speedLabel;  ///< what ContactResult::speedRatio is ("" when the problem has none)
  int shots = 1;
  /// No obstacles and no external forces: momentum and angular momentum are invariants, and
  /// their drift is reported.
  bool isolated = false;
  /// Walls, a floor or edges hold the particles in (ContactJudge::outside says when one left).
  bool contained = false;
  /// The scene of one shot for a collision type ("continuous-time" or "hybrid").
  std::function<SceneBuilder(const std::string& collision, int shot)> scene;
  std::function<std::unique_ptr<ContactJudge>()> judge;
};

/// Watches a problem's runs (every shot) and fills the outcome it is about.
class ContactJudge {
 public:
  virtual ~ContactJudge() = default;
  /// Before each shot's first step.
  virtual void start(const Scene&, const State&) {}
  /// After each step: `before` is the state at its beginning, `contacts` what the step counted.
  virtual void step(const Scene&, const State& /*before*/, const State& /*after*/, long /*contacts*/) {}
  /// Whether movable particle i has left its container (checked at every step end, counted once).
  virtual bool outside(const Scene&, const State&, int /*i*/) const { return false; }
  /// After the last shot.
  virtual void finish(ContactResult&) {}
};

/// The seven problems: joint drop, touching rack, corridor, slot, Newton's cradle, pile in a V,
/// clump.
/// `quick`: shorter runs, fewer shots, a smaller pile (the same code).
std::vector<ContactProblem> contactProblems(bool quick);

/// The pile in a V: `columns` x `rows` disks poured for `duration` seconds (contactProblems has
/// 10 x 20 for 2 s; tests take a smaller one).
ContactProblem pileInV(int columns, int rows, double duration);

/// The problem called `name` from contactProblems(quick) (tests); aborts the lookup with an empty
/// problem if there is none.
ContactProblem contactProblem(const std::string& name, bool quick);

/// Runs every shot of `problem` with `collision` in `mode`, stopping a shot at its first failed step.
ContactResult runContactProblem(const ContactProblem& problem, ContactMode mode, const std::string& collision);

}  // namespace fosssim::study
