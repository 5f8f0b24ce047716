// Grading: the step loop, the comparisons, record 0 and the other mode's second opinion. What a
// grade prints is in grade_report.cpp.
#include "fosssim/io/grader.h"

#include "grade_text.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fosssim {
namespace {

/// Below this L1 norm a polynomial counts as zero (the reference grader's threshold).
constexpr double kZeroPolynomialNorm = 1e-10;

std::string pairName(const Impulse& im) {
  switch (im.kind) {
    case PairKind::ParticleParticle: return "particles " + std::to_string(im.i) + " and " + std::to_string(im.j);
    case PairKind::ParticleEdge: return "particle " + std::to_string(im.i) + " and edge " + std::to_string(im.j);
    case PairKind::ParticleHalfPlane:
      return "particle " + std::to_string(im.i) + " and half-plane " + std::to_string(im.j);
  }
  return "an unknown pair";
}

/// "particle 3's position is (0, 0) in the file, (1, 2) in the scene", for the first particle of
/// `file` that is not within `tol` of `scene`; "" when every particle is.
std::string firstMismatch(const VecX& file, const VecX& scene, const char* what, double tol, long& count) {
  std::string first;
  for (int i = 0; i < static_cast<int>(scene.size() / 2); ++i)
    if (!((at(file, i) - at(scene, i)).norm() < tol)) {
      if (count++ == 0)
        first = "particle " + std::to_string(i) + "'s " + what + " is " + grade_text::vec(at(file, i)) +
                " in the file, " + grade_text::vec(at(scene, i)) + " in the scene";
    }
  return first;
}

/// The first non-finite number of a record, e.g. "particle 3's velocity (nan, 0)"; "" if none.
std::string firstNonFinite(const TrajectoryRecord& r) {
  for (int i = 0; i < static_cast<int>(r.x.size() / 2); ++i) {
    if (!at(r.x, i).allFinite()) return "particle " + std::to_string(i) + "'s position " + grade_text::vec(at(r.x, i));
    if (!at(r.v, i).allFinite()) return "particle " + std::to_string(i) + "'s velocity " + grade_text::vec(at(r.v, i));
  }
  return "";
}

/// Compares simulated records with the file's and accumulates the findings.
class Grader final : public StepObserver {
 public:
  Grader(const Scene& scene, const GradeOptions& options, GradeReport& report)
      : scene_(scene), options_(options), tol_(options.tolerances), report_(report) {}

  TrajectoryReader* reader = nullptr;
  long step = 0;

  /// Reads the file's next record; false (with report_.structuralError set) if there is none.
  bool readNext(TrajectoryRecord& record, const char* which) {
    bool atEnd = false;
    if (Status s = reader->next(record, atEnd); !s) {
      report_.structuralError = s.message();
      return false;
    }
    if (atEnd) {
      report_.structuralError = "the file ends early at record " + std::to_string(reader->recordsRead()) + " (byte " +
                                std::to_string(reader->offset()) + " of " + std::to_string(reader->fileSize()) +
                                "): the " + which + " record" + (step ? " of step " + std::to_string(step) : "") +
                                " is missing (the scene has " + std::to_string(scene_.numSteps()) + " steps)";
      return false;
    }
    return true;
  }

  /// A record a step is about to start from must be finite: say which record, not which step.
  bool startable(const TrajectoryRecord& record, const char* which) {
    const std::string bad = firstNonFinite(record);
    if (bad.empty()) return true;
    report_.structuralError = "record " + std::to_string(reader->recordsRead() - 1) + " (the " + which +
                              " record of step " + std::to_string(step) + ") holds a non-finite number, " + bad +
                              ": no step can start from it";
    return false;
  }

  void compare(bool midStep, const State& mine, const CollisionLog& log, const TrajectoryRecord& ref) {
    midStep_ = midStep;
    residuals(mine.x, ref.x, report_.positionSum, report_.positionMax, GradeFinding::Positions);
    residuals(mine.v, ref.v, report_.velocitySum, report_.velocityMax, GradeFinding::Velocities);
    impulses(log, ref.log);
    polynomials(log.polynomials, ref.log.polynomials);
  }

  const State* midStep(const CollisionLog& log, const State& state) override {
    if (failed_ || stopped()) return nullptr;
    if (!readNext(mid_, "mid-step")) {
      failed_ = true;
      return nullptr;
    }
    compare(true, state, log, mid_);
    if (!startable(mid_, "mid-step")) {
      failed_ = true;
      return nullptr;
    }
    // Continue from the file's state, as the reference grader does.
    replacement_.x = mid_.x;
    replacement_.v = mid_.v;
    return &replacement_;
  }

  bool failed() const { return failed_; }
  bool stopped() const { return options_.stopAtFirstFinding && report_.findingCount > 0; }

 private:
  /// Records a finding; `describe` (which may cost a search) runs only for the findings kept.
  template <class Describe>
  void finding(GradeFinding::Category category, Describe&& describe) {
    ++report_.categoryFindings[category];
    if (lastFindingStep_ != step) ++report_.stepsDiverged, lastFindingStep_ = step;
    if (report_.findingCount++ >= std::max(1, options_.maxFindings)) return;
    GradeFinding f;
    f.category = category;
    f.step = step;
    f.record = reader->recordsRead() - 1;
    f.midStep = midStep_;
    describe(f.who, f.what);
    report_.findings.push_back(std::move(f));
  }

  void residuals(const VecX& mine, const VecX& ref, double& sum, double& max, GradeFinding::Category category) {
    for (int i = 0; i < static_cast<int>(mine.size() / 2); ++i) {
      const double r = (at(mine, i) - at(ref, i)).norm();
      sum += std::isnan(r) ? INFINITY : r;
      if (!(r <= max)) max = std::isnan(r) ? INFINITY : r;
      if (!(r < tol_.residualMax))
        finding(category, [&](std::string& who, std::string& what) {
          who = "particle " + std::to_string(i);
          what = "differs by " + grade_text::num(r) + " (the file's " + grade_text::vec(at(ref, i)) + ", simulated " +
                 grade_text::vec(at(mine, i)) + ")";
        });
    }
  }

  void impulses(const CollisionLog& mine, const CollisionLog& ref) {
    std::vector<char> used(mine.impulses.size(), 0);
    const auto sameKey = [](const Impulse& a, const Impulse& b) {
      return a.kind == b.kind && a.i == b.i && a.j == b.j;
    };
    for (const Impulse& r : ref.impulses) {
      long keyed = -1, matched = -1;
      for (size_t k = 0; k < mine.impulses.size() && matched < 0; ++k) {
        if (used[k] || !sameKey(mine.impulses[k], r)) continue;
        if (keyed < 0) keyed = static_cast<long>(k);
        if ((mine.impulses[k].n - r.n).cwiseAbs().maxCoeff() <= tol_.normal) matched = static_cast<long>(k);
      }
      if (matched >= 0) {
        used[matched] = 1;
      } else if (keyed >= 0) {  // consume the mismatching one
        used[keyed] = 1;
        ++report_.impulsesWrongNormal;
        finding(GradeFinding::Impulses, [&](std::string& who, std::string& what) {
          who = pairName(r);
          what = "impulse with a wrong normal: the file's " + grade_text::vec(r.n) + ", simulated " +
                 grade_text::vec(mine.impulses[keyed].n);
        });
      } else {
        ++report_.impulsesMissed;
        finding(GradeFinding::Impulses, [&](std::string& who, std::string& what) {
          who = pairName(r);
          what = "missed impulse (the file's normal " + grade_text::vec(r.n) + ")";
        });
      }
    }
    for (size_t k = 0; k < mine.impulses.size(); ++k)
      if (!used[k]) {
        ++report_.impulsesSuperfluous;
        finding(GradeFinding::Impulses, [&](std::string& who, std::string& what) {
          who = pairName(mine.impulses[k]);
          what = "superfluous impulse (simulated normal " + grade_text::vec(mine.impulses[k].n) + ")";
        });
      }
  }

  void polynomials(const PolynomialLog& mine, const PolynomialLog& ref) {
    if (mine.size() != ref.size()) {
      ++report_.polynomialMismatches;
      finding(GradeFinding::Polynomials, [&](std::string&, std::string& what) {
        what = std::to_string(mine.size()) + " polynomials simulated, the file has " + std::to_string(ref.size());
      });
      return;
    }
    for (int k = 0; k < ref.size(); ++k)
      if (!samePolynomial(mine.coefficients(k), mine.length(k), ref.coefficients(k), ref.length(k), tol_.polynomial)) {
        ++report_.polynomialMismatches;
        finding(GradeFinding::Polynomials, [&](std::string& who, std::string& what) {
          const std::string owner = polynomialOwner(scene_, k, ref.size());
          who = owner.empty() ? "polynomial " + std::to_string(k)
                              : owner + " (polynomial " + std::to_string(k) + " of the record)";
          what = "differs: the file's " +
                 grade_text::list(ref.coefficients(k), ref.length(k)) + ", simulated " +
                 grade_text::list(mine.coefficients(k), mine.length(k));
        });
      }
  }

  const Scene& scene_;
  const GradeOptions& options_;
  const GradeTolerances& tol_;
  GradeReport& report_;
  bool failed_ = false, midStep_ = false;
  long lastFindingStep_ = -1;
  TrajectoryRecord mid_;
  State replacement_;  ///< mid_'s positions and velocities, handed back to the handler
};

/// Record 0 must be the scene's initial state, within the tolerance of a single residual.
bool startsFromTheScene(const TrajectoryRecord& record, const State& initial, double tol,
                        const TrajectoryReader& reader, const Scene& scene, RecordLayout layout, std::string& error) {
  long positions = 0, velocities = 0;
  const std::string x = firstMismatch(record.x, initial.x, "position", tol, positions);
  const std::string v = firstMismatch(record.v, initial.v, "velocity", tol, velocities);
  if (positions == 0 && velocities == 0) return true;
  error = "record 0 is not this scene's initial state: " + (x.empty() ? v : x) + " (" +
          std::to_string(positions) + " of " + std::to_string(scene.numParticles()) + " positions and " +
          std::to_string(velocities) + " velocities differ); is it the trajectory of this scene?";
  // Records of positions and velocities alone have one size: a file of another size is another
  // scene's (or cut short), which says more than the values.
  if (!layout.impulses && !layout.polynomials) {
    const std::uint64_t perRecord = 32ull * static_cast<std::uint64_t>(scene.numParticles());
    const std::uint64_t records = static_cast<std::uint64_t>(scene.numSteps()) + 1;
    if (records <= UINT64_MAX / perRecord && reader.fileSize() != records * perRecord)
      error += " (it has " + std::to_string(reader.fileSize()) + " bytes; this scene's has " +
               std::to_string(records * perRecord) + ": " + std::to_string(records) + " records of " +
               std::to_string(perRecord) + ")";
  }
  return false;
}

/// Whether the file at `path` reads to its end as exactly the records of a run of `scene` written
/// with `layout` minus its polynomial log (what -o --compact writes): one initial record, then one
/// per step, or two when the records include one from inside collision handling.
bool readsAsCompact(const std::string& path, const Scene& scene, RecordLayout layout) {
  layout.polynomials = false;
  std::unique_ptr<TrajectoryReader> reader;
  if (!TrajectoryReader::open(path, scene.numParticles(), layout, reader)) return false;
  const long expected = 1 + scene.numSteps() * (layout.midStep ? 2 : 1);
  TrajectoryRecord record;
  for (long k = 0;; ++k) {
    bool atEnd = false;
    if (!reader->next(record, atEnd)) return false;
    if (atEnd) return k == expected;
    if (k >= expected) return false;
  }
}

}  // namespace

bool samePolynomial(const double* a, int na, const double* b, int nb, double tol) {
  if (na != nb) return false;
  double sa = 0, sb = 0;
  for (int k = 0; k < na; ++k) sa += std::fabs(a[k]), sb += std::fabs(b[k]);
  if (sa < kZeroPolynomialNorm && sb < kZeroPolynomialNorm) return true;
  if (sa < kZeroPolynomialNorm || sb < kZeroPolynomialNorm) return false;
  for (int k = 0; k < na; ++k)
    if (!(std::fabs(a[k] / sa - b[k] / sb) <= tol)) return false;
  return true;
}

bool GradeReport::passed(const GradeTolerances& tol) const {
  return structuralError.empty() && !unreadable && positionSum < tol.residualSum && positionMax < tol.residualMax &&
         velocitySum < tol.residualSum && velocityMax < tol.residualMax && impulsesMissed == 0 &&
         impulsesSuperfluous == 0 && impulsesWrongNormal == 0 && polynomialMismatches == 0;
}

GradeReport gradeRecords(const Scene& scene, const State& initial, Simulator& simulator, const std::string& path,
                         const GradeOptions& options) {
  GradeReport report;
  report.numSteps = scene.numSteps();
  report.layout = simulator.layout();
  std::unique_ptr<TrajectoryReader> reader;
  if (Status s = TrajectoryReader::open(path, scene.numParticles(), simulator.layout(), reader); !s) {
    report.structuralError = s.message();
    report.unreadable = true;
    return report;
  }
  Grader grader(scene, options, report);
  grader.reader = reader.get();
  TrajectoryRecord record;
  if (!grader.readNext(record, "initial")) {
    // Another scene's file often breaks the reader inside record 0 (its counts read from the wrong
    // bytes); its positions and velocities, when read, say more about why.
    std::string notThisScene;
    if (record.x.size() == initial.x.size() &&
        !startsFromTheScene(record, initial, options.tolerances.residualMax, *reader, scene, report.layout,
                            notThisScene))
      report.structuralError = notThisScene + "; reading on: " + report.structuralError;
    return report;
  }
  if (!startsFromTheScene(record, initial, options.tolerances.residualMax, *reader, scene, report.layout,
                          report.structuralError))
    return report;
  State state = initial;
  const long steps = scene.numSteps();
  for (long k = 1; k <= steps && !grader.stopped(); ++k) {
    if (k > 1 && !grader.startable(record, "end-of-step")) break;  // names step k - 1's record
    grader.step = k;
    state.x = record.x;
    state.v = record.v;
    state.step = k - 1;
    state.time = static_cast<double>(k - 1) * scene.dt;
    if (Status stepped = simulator.step(scene, state, &grader); !stepped) {
      report.structuralError = "the simulation failed: " + stepped.message();
      break;
    }
    if (grader.failed() || grader.stopped() || !grader.readNext(record, "end-of-step")) break;
    grader.compare(false, state, simulator.log(), record);
    ++report.stepsGraded;
  }
  if (report.structuralError.empty() && report.stepsGraded == steps && reader->offset() != reader->fileSize())
    report.structuralError = "the file goes on after the scene's " + std::to_string(steps) + " steps (" +
                             std::to_string(reader->recordsRead()) + " records, " + std::to_string(reader->offset()) +
                             " bytes; the file has " + std::to_string(reader->fileSize()) +
                             "); is it the trajectory of this scene?";
  return report;
}

GradeReport gradeTrajectory(const Scene& scene, const State& initial, Simulator& simulator, const std::string& path,
                            std::ostream& out, const GradeTolerances& tol, int maxFindings) {
  GradeOptions options;
  options.tolerances = tol;
  options.maxFindings = maxFindings;
  GradeReport report = gradeRecords(scene, initial, simulator, path, options);
  printGrade(report, scene, out, options);
  return report;
}

GradeReport gradeFile(const Scene& scene, const State& initial, Simulator& simulator, const SimulatorOptions& made,
                      const std::string& path, std::ostream& out, const GradeOptions& options) {
  GradeReport report = gradeRecords(scene, initial, simulator, path, options);
  if (report.unreadable) return report;
  // A file written with --compact has no polynomial log, which grading reads: its counts are then
  // read from a later record's bytes, and the error says only that the file does not fit.
  if (!report.structuralError.empty() && report.layout.polynomials && readsAsCompact(path, scene, report.layout)) {
    report.hint = "this file looks written with -o --compact, which leaves out the polynomial log that grading "
                  "compares: write it again without --compact";
    // Read as full records, its numbers are no states, and stepping from them may fail: "energy
    // blow-up ... try a smaller dt" would send the user after the scene instead of the file.
    if (report.structuralError.rfind("the simulation failed:", 0) == 0)
      report.structuralError = "the file does not read as this scene's full records (read with the polynomial log "
                               "it lacks, its numbers are no states, and the simulation failed from them)";
    printGrade(report, scene, out, options);
    return report;
  }
  // The modes differ only in continuous-time and hybrid handling (whose records hold polynomials).
  // A file that fits the scene but differs in what the steps produce may have been made in the
  // other mode: grading it again there is the only sure way to tell (the difference may be in
  // impulses, positions or one coefficient of the particle-edge quintic).
  if (report.findingCount > 0 && report.layout.polynomials) {
    SimulatorOptions other = made;
    other.handler.compat = !made.handler.compat;
    std::unique_ptr<Simulator> otherSimulator;
    GradeOptions quick = options;
    quick.stopAtFirstFinding = true;
    if (Simulator::create(scene, other, otherSimulator)) {
      const GradeReport again = gradeRecords(scene, initial, *otherSimulator, path, quick);
      if (again.findingCount == 0 && again.stepsGraded >= report.stepsGraded)
        report.hint = other.handler.compat
                              ? "this file looks made with --compat: grade with --compat (graded again with "
                                "--compat, every step graded matches)"
                              : "this file looks made without --compat (the default mode): grade without --compat "
                                "(graded again without it, every step graded matches)";
    }
  }
  printGrade(report, scene, out, options);
  return report;
}

}  // namespace fosssim
