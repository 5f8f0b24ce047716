#include "fosssim/core/scene_values.h"

#include "core/short_number.h"

#include <cmath>
#include <limits>

namespace fosssim {

std::string valueProblem(ValueRule rule, double value, const char* name) {
  // NaN fails every comparison: it would pass "value < 0 || value > 1" unnoticed.
  if (!std::isfinite(value)) return "must be finite";
  switch (rule) {
    case ValueRule::Positive:
      if (!(value > 0)) return "must be > 0";
      // A subnormal such as 1e-320 is > 0, yet its reciprocal is infinite.
      if (!std::isfinite(1 / value))
        return "too small: 1/" + std::string(name) + " is not finite (at least about 5.6e-309)";
      break;
    case ValueRule::NonNegative:
      if (value < 0) return "must be >= 0";
      break;
    case ValueRule::Fraction:
      if (value < 0 || value > 1) return "must lie in [0, 1]";
      break;
  }
  return "";
}

std::string stepCountProblem(double duration, double dt) {
  if (duration / dt <= kMaxSteps) return "";
  return "duration / dt = " + shortNumber(duration) + " / " + shortNumber(dt) + " asks for " +
         shortNumber(duration / dt) + " steps; at most " + shortNumber(kMaxSteps) +
         " (more would overflow the step counters and run for years)";
}

namespace {

/// Whether `value` keeps `rule`: valueProblem's test without its words, for the per-particle loop
/// that runs at every step (no string is made unless a value is bad).
bool keeps(ValueRule rule, double value) {
  switch (rule) {
    case ValueRule::Positive: return value > 0 && std::isfinite(value) && std::isfinite(1 / value);
    case ValueRule::NonNegative: return value >= 0 && std::isfinite(value);
    case ValueRule::Fraction: return value >= 0 && value <= 1;
  }
  return false;
}

/// `what` ("particle 3's mass") and why `value` breaks `rule`, or "".
std::string problem(const std::string& what, ValueRule rule, double value, const char* name) {
  if (keeps(rule, value)) return "";
  return what + ": " + valueProblem(rule, value, name) + ", got " + shortNumber(value);
}

/// keeps(Positive) without its division, for the values far from its edges (every particle's mass
/// and radius, at every step): 1 / value is surely finite from 1e-300 up; from the smallest
/// subnormal to there keeps() decides.
bool surelyPositive(double value) { return value >= 1e-300 && value <= std::numeric_limits<double>::max(); }

std::string particleProblem(const Scene& scene, int i) {
  const double m = scene.mass[2 * i];
  if (m == scene.mass[2 * i + 1] && keeps(ValueRule::Positive, m) && keeps(ValueRule::Positive, scene.radius[i]))
    return "";
  const std::string p = "particle " + std::to_string(i);
  std::string why = problem(p + "'s mass", ValueRule::Positive, m, "m");
  if (why.empty() && !(m == scene.mass[2 * i + 1]))
    why = p + "'s mass: its two entries of the mass vector differ (" + shortNumber(m) + " and " +
          shortNumber(scene.mass[2 * i + 1]) + ")";
  if (why.empty()) why = problem(p + "'s radius", ValueRule::Positive, scene.radius[i], "radius");
  return why;
}

std::string halfPlaneProblem(const HalfPlane& h, size_t index) {
  if (h.point.allFinite() && std::isnormal(h.normal.squaredNorm())) return "";
  const std::string p = "half-plane " + std::to_string(index);
  if (!h.point.allFinite() || !h.normal.allFinite()) return p + ": its point and normal must be finite";
  if (h.normal == Vec2::Zero()) return p + ": the half-plane normal (nx, ny) must not be zero";
  // Distances divide by sqrt(nx^2 + ny^2): a square that overflows makes every distance 0 or NaN
  // (particles fall through), a subnormal one is imprecise. The loader rescales such a normal
  // exactly; a caller may scale it by any power of two (the direction is what counts).
  if (!std::isnormal(h.normal.squaredNorm()))
    return p + ": the normal (" + shortNumber(h.normal.x()) + ", " + shortNumber(h.normal.y()) +
           ")'s squared length overflows or underflows; scale it (its direction is what counts)";
  return "";
}

std::string settingsProblem(const Scene& scene) {
  const CollisionSettings& c = scene.collision;
  // At every step: no string is made unless something is wrong (the names below are longer than
  // a string's inline buffer, and five allocations a step were a fifth of a two-disk step).
  if (keeps(ValueRule::Fraction, c.cor) && c.maxIterations <= kMaxCollisionIterations &&
      keeps(ValueRule::NonNegative, c.penaltyK) && keeps(ValueRule::NonNegative, c.penaltyThickness) &&
      keeps(ValueRule::NonNegative, scene.duration) && !(scene.dt > 0 && !(scene.duration / scene.dt <= kMaxSteps)))
    return "";
  std::string why = problem("the collision's COR", ValueRule::Fraction, c.cor, "COR");
  if (why.empty() && c.maxIterations > kMaxCollisionIterations)
    why = "the collision's maxiters: must be at most " + std::to_string(kMaxCollisionIterations) + ", got " +
          std::to_string(c.maxIterations) + ": " + kMaxCollisionIterationsReason;
  if (why.empty()) why = problem("the collision's penalty k", ValueRule::NonNegative, c.penaltyK, "k");
  if (why.empty())
    why = problem("the collision's penalty thickness", ValueRule::NonNegative, c.penaltyThickness, "thickness");
  if (why.empty()) why = problem("the duration", ValueRule::NonNegative, scene.duration, "duration");
  if (why.empty() && scene.dt > 0) why = stepCountProblem(scene.duration, scene.dt);
  return why;
}

}  // namespace

Status checkSceneValues(const Scene& scene) {
  std::string why = settingsProblem(scene);
  const int n = scene.numParticles();
  const double* mass = scene.mass.data();
  const double* radius = scene.radius.data();
  for (int i = 0; why.empty() && i < n; ++i)
    if (!(surelyPositive(mass[2 * i]) && mass[2 * i] == mass[2 * i + 1] && surelyPositive(radius[i])))
      why = particleProblem(scene, i);  // the words, or "" for a value near the rule's edge
  for (size_t e = 0; why.empty() && e < scene.edges.size(); ++e) {
    const Edge& edge = scene.edges[e];
    if (edge.i != edge.j && keeps(ValueRule::Positive, edge.radius)) continue;
    if (edge.i == edge.j)
      why = "edge " + std::to_string(e) + ": an edge needs two different particles, got i = j = " +
            std::to_string(edge.i);
    else
      why = problem("edge " + std::to_string(e) + "'s radius", ValueRule::Positive, edge.radius, "radius");
  }
  for (size_t h = 0; why.empty() && h < scene.halfplanes.size(); ++h) why = halfPlaneProblem(scene.halfplanes[h], h);
  return why.empty() ? Status::ok() : Status::error(why);
}

}  // namespace fosssim
