#include "fosssim/io/grader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace fosssim {
namespace {

/// Below this L1 norm a polynomial counts as zero (the reference grader's threshold).
constexpr double kZeroPolynomialNorm = 1e-10;

std::string listOf(const double* c, int n) {
  std::ostringstream s;
  s.precision(17);
  s << "(";
  for (int k = 0; k < n; ++k) s << (k ? ", " : "") << c[k];
  s << ")";
  return s.str();
}

std::string describe(const Impulse& im) {
  std::ostringstream s;
  s << pairKindName(im.kind) << " (" << im.i << ", " << im.j << ") normal (" << im.n.x() << ", " << im.n.y() << ")";
  return s.str();
}

/// Compares one simulated record with the file's and accumulates the findings.
class Grader final : public StepObserver {
 public:
  Grader(const GradeTolerances& tol, GradeReport& report, std::ostream& out, int maxFindings)
      : tol_(tol), report_(report), out_(out), maxFindings_(maxFindings) {}

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
      report_.structuralError = "the file ends before the " + std::string(which) + " record of step " +
                                std::to_string(step) + " (" + std::to_string(reader->recordsRead()) +
                                " records read)";
      return false;
    }
    return true;
  }

  void compare(const char* which, const State& mine, const CollisionLog& log, const TrajectoryRecord& ref) {
    residuals(which, mine.x, ref.x, report_.positionSum, report_.positionMax, "position");
    residuals(which, mine.v, ref.v, report_.velocitySum, report_.velocityMax, "velocity");
    impulses(which, log, ref.log);
    polynomials(which, log.polynomials, ref.log.polynomials);
  }

  void midStep(const CollisionLog& log, State& state) override {
    if (failed_) return;
    if (!readNext(mid_, "mid-step")) {
      failed_ = true;
      return;
    }
    compare("mid-step", state, log, mid_);
    state.x = mid_.x;  // continue from the file's state, as the reference grader does
    state.v = mid_.v;
  }

  bool failed() const { return failed_; }

 private:
  void finding(const std::string& text) {
    if (findings_++ < maxFindings_) out_ << "step " << step << ": " << text << "\n";
    if (findings_ == maxFindings_ + 1) out_ << "(further findings not shown)\n";
  }

  void residuals(const char* which, const VecX& mine, const VecX& ref, double& sum, double& max, const char* what) {
    for (int i = 0; i < static_cast<int>(mine.size() / 2); ++i) {
      const double r = (at(mine, i) - at(ref, i)).norm();
      sum += std::isnan(r) ? INFINITY : r;
      if (!(r <= max)) max = std::isnan(r) ? INFINITY : r;
      if (!(r < tol_.residualMax)) {
        std::ostringstream s;
        s << which << " " << what << " of particle " << i << " differs by " << r;
        finding(s.str());
      }
    }
  }

  void impulses(const char* which, const CollisionLog& mine, const CollisionLog& ref) {
    std::vector<char> used(mine.impulses.size(), 0);
    for (const Impulse& r : ref.impulses) {
      bool sameKey = false, matched = false;
      for (size_t k = 0; k < mine.impulses.size() && !matched; ++k) {
        const Impulse& m = mine.impulses[k];
        if (used[k] || m.kind != r.kind || m.i != r.i || m.j != r.j) continue;
        sameKey = true;
        if ((m.n - r.n).cwiseAbs().maxCoeff() <= tol_.normal) used[k] = 1, matched = true;
      }
      if (matched) continue;
      if (sameKey) {
        ++report_.impulsesWrongNormal;
        finding(std::string(which) + " impulse with a wrong normal, expected " + describe(r));
        for (size_t k = 0; k < mine.impulses.size(); ++k)  // consume the mismatching one
          if (!used[k] && mine.impulses[k].kind == r.kind && mine.impulses[k].i == r.i && mine.impulses[k].j == r.j) {
            used[k] = 1;
            break;
          }
      } else {
        ++report_.impulsesMissed;
        finding(std::string(which) + " missed impulse " + describe(r));
      }
    }
    for (size_t k = 0; k < mine.impulses.size(); ++k)
      if (!used[k]) {
        ++report_.impulsesSuperfluous;
        finding(std::string(which) + " superfluous impulse " + describe(mine.impulses[k]));
      }
  }

  void polynomials(const char* which, const PolynomialLog& mine, const PolynomialLog& ref) {
    if (mine.size() != ref.size()) {
      ++report_.polynomialMismatches;
      finding(std::string(which) + " " + std::to_string(mine.size()) + " polynomials, the file has " +
              std::to_string(ref.size()));
      return;
    }
    for (int k = 0; k < ref.size(); ++k)
      if (!samePolynomial(mine.coefficients(k), mine.length(k), ref.coefficients(k), ref.length(k), tol_.polynomial)) {
        ++report_.polynomialMismatches;
        finding(std::string(which) + " polynomial " + std::to_string(k) + " differs: mine " +
                listOf(mine.coefficients(k), mine.length(k)) + ", the file's " + listOf(ref.coefficients(k), ref.length(k)));
      }
  }

  const GradeTolerances& tol_;
  GradeReport& report_;
  std::ostream& out_;
  int maxFindings_;
  int findings_ = 0;
  bool failed_ = false;
  TrajectoryRecord mid_;
};

const char* verdict(bool ok) { return ok ? "passed" : "FAILED"; }

/// When all records have the same size (positions and velocities only), the file must hold exactly
/// the scene's numSteps() + 1 of them; otherwise report.structuralError says why. Records with
/// impulses or polynomials vary in size and are checked one by one while reading.
bool sizeFits(std::uint64_t bytes, const Scene& scene, const RecordLayout& layout, GradeReport& report) {
  if (layout.impulses || layout.polynomials) return true;
  const std::uint64_t record = 32ull * static_cast<std::uint64_t>(scene.numParticles());
  const std::uint64_t records = bytes / record, wanted = static_cast<std::uint64_t>(scene.numSteps()) + 1;
  if (bytes % record == 0 && records == wanted) return true;
  report.structuralError = "the file has " + std::to_string(bytes) + " bytes, but the trajectory of this scene (" +
                           std::to_string(scene.numParticles()) + " particles, " + std::to_string(record) +
                           " bytes per record, " + std::to_string(wanted) + " records) has " +
                           (wanted <= UINT64_MAX / record ? std::to_string(wanted * record) : "more") +
                           " bytes; is it the trajectory of this scene?";
  return false;
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
  return structuralError.empty() && positionSum < tol.residualSum && positionMax < tol.residualMax &&
         velocitySum < tol.residualSum && velocityMax < tol.residualMax && impulsesMissed == 0 &&
         impulsesSuperfluous == 0 && impulsesWrongNormal == 0 && polynomialMismatches == 0;
}

GradeReport gradeTrajectory(const Scene& scene, const State& initial, Simulator& simulator, const std::string& path,
                            std::ostream& out, const GradeTolerances& tol, int maxFindings) {
  GradeReport report;
  Grader grader(tol, report, out, maxFindings);
  std::unique_ptr<TrajectoryReader> reader;
  if (Status s = TrajectoryReader::open(path, scene.numParticles(), simulator.layout(), reader); !s) {
    report.structuralError = s.message();
  } else if (!sizeFits(reader->fileSize(), scene, simulator.layout(), report)) {
    // report.structuralError says why; nothing is graded
  } else {
    grader.reader = reader.get();
    TrajectoryRecord record;
    State state = initial;
    if (grader.readNext(record, "initial")) {
      if (!(record.x - initial.x).isZero(0) || !(record.v - initial.v).isZero(0))
        out << "note: record 0 differs from the scene's initial state; grading from the file's state\n";
      const long steps = scene.numSteps();
      for (long k = 1; k <= steps; ++k) {
        grader.step = k;
        state.x = record.x;
        state.v = record.v;
        state.step = k - 1;
        state.time = static_cast<double>(k - 1) * scene.dt;
        if (Status stepped = simulator.step(scene, state, &grader); !stepped) {
          report.structuralError = stepped.message();
          break;
        }
        if (grader.failed() || !grader.readNext(record, "end-of-step")) break;
        grader.compare("end-of-step", state, simulator.log(), record);
        ++report.stepsGraded;
      }
      bool atEnd = false;
      if (report.structuralError.empty() && (!reader->next(record, atEnd) || !atEnd))
        report.structuralError = "the file has more records than the scene's " + std::to_string(steps) +
                                 " steps produce; is it the trajectory of this scene?";
    }
  }
  out << "Steps graded: " << report.stepsGraded << " of " << scene.numSteps() << "\n";
  if (!report.structuralError.empty()) out << "Error: " << report.structuralError << "\n";
  const bool posOk = report.positionSum < tol.residualSum && report.positionMax < tol.residualMax;
  const bool velOk = report.velocitySum < tol.residualSum && report.velocityMax < tol.residualMax;
  const bool impOk = report.impulsesMissed + report.impulsesSuperfluous + report.impulsesWrongNormal == 0;
  out << "Positions: residual sum " << report.positionSum << ", max " << report.positionMax << ": " << verdict(posOk) << "\n"
      << "Velocities: residual sum " << report.velocitySum << ", max " << report.velocityMax << ": " << verdict(velOk) << "\n"
      << "Impulses: " << report.impulsesMissed << " missed, " << report.impulsesSuperfluous << " superfluous, "
      << report.impulsesWrongNormal << " wrong normals: " << verdict(impOk) << "\n"
      << "Polynomials: " << report.polynomialMismatches << " mismatches: " << verdict(report.polynomialMismatches == 0) << "\n"
      << "Overall success: " << (report.passed(tol) ? "Passed." : "Failed.") << "\n";
  return report;
}

}  // namespace fosssim
