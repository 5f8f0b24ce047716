// What a grade prints. A failed grade leads with what a reader needs first, where the run first
// diverged from the file (or why the file does not fit the scene), and only then the details; the
// category lines and the reference's closing line ("Overall success: ...", which scripts look for)
// come last, and a category is never "passed" for steps that were not graded.
#include "fosssim/io/grader.h"

#include "grade_text.h"

#include <algorithm>
#include <cstdio>

namespace fosssim {
namespace {

const char* const kCategoryNames[4] = {"positions", "velocities", "impulses", "polynomials"};

std::string time(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t);
  return buffer;
}

/// "step 12, end-of-step record 12" or "step 12, mid-step record 23".
std::string place(const GradeFinding& f) {
  return "step " + std::to_string(f.step) + ", " + (f.midStep ? "mid-step" : "end-of-step") + " record " +
         std::to_string(f.record);
}

std::string body(const GradeFinding& f) {
  return std::string(kCategoryNames[f.category]) + ": " + (f.who.empty() ? "" : f.who + " ") + f.what;
}

std::string divergence(const GradeReport& r, const Scene& scene) {
  const GradeFinding& f = r.findings.front();
  const double end = static_cast<double>(f.step) * scene.dt;
  const std::string when = f.midStep ? "t = " + time(end - scene.dt) + " to " + time(end) : "t = " + time(end);
  return "the run first diverges from the file in step " + std::to_string(f.step) + " of " +
         std::to_string(r.numSteps) + " (" + when + ", " + (f.midStep ? "mid-step" : "end-of-step") + " record " +
         std::to_string(f.record) + "): " + body(f);
}

/// One category's verdict: never "passed" for steps that were not graded.
std::string verdict(bool ok, bool inRecords, const GradeReport& r) {
  if (!ok) return "FAILED";
  if (!inRecords) return "none in this scene's records";
  if (r.stepsGraded == 0) return "not graded";
  if (r.stepsGraded < r.numSteps)
    return "passed in the " + std::to_string(r.stepsGraded) + " of " + std::to_string(r.numSteps) + " steps graded";
  return "passed";
}

}  // namespace

void printGrade(const GradeReport& r, const Scene& scene, std::ostream& out, const GradeOptions& options) {
  if (r.unreadable) return;
  const GradeTolerances& tol = options.tolerances;
  const bool posOk = r.positionSum < tol.residualSum && r.positionMax < tol.residualMax;
  const bool velOk = r.velocitySum < tol.residualSum && r.velocityMax < tol.residualMax;
  const bool impOk = r.impulsesMissed + r.impulsesSuperfluous + r.impulsesWrongNormal == 0;
  const bool polyOk = r.polynomialMismatches == 0;
  const bool passed = r.passed(tol);

  if (!r.findings.empty()) out << "Failed: " << divergence(r, scene) << "\n";
  if (!r.structuralError.empty()) out << (r.findings.empty() ? "Failed: " : "Then: ") << r.structuralError << "\n";
  if (!passed && r.findings.empty() && r.structuralError.empty())  // many residuals, each below the maximum
    out << "Failed: no single residual reaches " << tol.residualMax << ", but their sum over the run does ("
        << (posOk ? "velocities " + grade_text::num(r.velocitySum) : "positions " + grade_text::num(r.positionSum))
        << ", at most " << tol.residualSum << ")\n";
  if (!r.hint.empty()) out << "Hint: " << r.hint << "\n";
  if (r.findingCount > 0) {
    out << "Findings: " << r.findingCount << " in " << r.stepsDiverged << " step" << (r.stepsDiverged == 1 ? "" : "s")
        << " (";
    const char* sep = "";
    for (int c = 0; c < 4; ++c)
      if (r.categoryFindings[c]) out << sep << kCategoryNames[c] << " " << r.categoryFindings[c], sep = ", ";
    const long shown = std::min<long>(r.findingCount, std::max(0, options.maxFindings));
    out << ")"
        << (shown == 0                ? ""
            : shown == r.findingCount ? ":"
                                      : "; the first " + std::to_string(shown) + ":")
        << "\n";
    for (long k = 0; k < shown && k < static_cast<long>(r.findings.size()); ++k)
      out << "  " << place(r.findings[k]) << ": " << body(r.findings[k]) << "\n";
    if (r.findingCount > shown) out << "  (" << r.findingCount - shown << " more not shown)\n";
  }
  out << "Steps graded: " << r.stepsGraded << " of " << r.numSteps << "\n";
  out << "Positions: residual sum " << r.positionSum << ", max " << r.positionMax << ": " << verdict(posOk, true, r)
      << "\n"
      << "Velocities: residual sum " << r.velocitySum << ", max " << r.velocityMax << ": " << verdict(velOk, true, r)
      << "\n"
      << "Impulses: " << r.impulsesMissed << " missed, " << r.impulsesSuperfluous << " superfluous, "
      << r.impulsesWrongNormal << " wrong normals: " << verdict(impOk, r.layout.impulses, r) << "\n"
      << "Polynomials: " << r.polynomialMismatches << " mismatches: " << verdict(polyOk, r.layout.polynomials, r)
      << "\n"
      << "Overall success: " << (passed ? "Passed." : "Failed.") << "\n";
}

std::string polynomialOwner(const Scene& scene, long k, long logSize) {
  const long n = scene.numParticles(), edges = static_cast<long>(scene.edges.size());
  const long planes = static_cast<long>(scene.halfplanes.size());
  std::vector<long> incident(static_cast<size_t>(n), 0);
  for (const Edge& e : scene.edges) ++incident[e.i], ++incident[e.j];
  std::vector<long> row(static_cast<size_t>(n));  // polynomials of particle i's pairs in one pass
  long pass = 0;
  for (long i = 0; i < n; ++i) pass += row[i] = 2 * (n - 1 - i) + 4 * (edges - incident[i]) + 2 * planes;
  if (pass == 0 || k < 0 || k >= logSize || logSize % pass != 0) return "";
  const std::string passNote = logSize > pass ? " (detection pass " + std::to_string(k / pass + 1) + ")" : "";
  long r = k % pass, i = 0;
  while (r >= row[i]) r -= row[i++];
  static const char* const kTwo[2] = {"distance", "approach"};
  static const char* const kFour[4] = {"distance", "alpha > 0", "alpha < 1", "approach"};
  const std::string p = "particle " + std::to_string(i);
  if (r < 2 * (n - 1 - i))
    return "the " + std::string(kTwo[r % 2]) + " polynomial of particles " + std::to_string(i) + " and " +
           std::to_string(i + 1 + r / 2) + passNote;
  r -= 2 * (n - 1 - i);
  if (r < 4 * (edges - incident[i])) {
    long skip = r / 4;
    for (long e = 0; e < edges; ++e) {
      if (scene.edges[e].i == i || scene.edges[e].j == i) continue;
      if (skip-- == 0)
        return "the " + std::string(kFour[r % 4]) + " polynomial of " + p + " and edge " + std::to_string(e) + passNote;
    }
  }
  r -= 4 * (edges - incident[i]);
  return "the " + std::string(kTwo[r % 2]) + " polynomial of " + p + " and half-plane " + std::to_string(r / 2) +
         passNote;
}

}  // namespace fosssim
