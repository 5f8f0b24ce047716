// The values a scene's elements may take, in one place. The loader checks each attribute it reads
// with these rules (src/io/xml_reader.cpp) and Simulator::create and step check a scene built in
// code with checkSceneValues, so that a file and a library caller are refused the same values in
// the same words, and the two cannot drift apart.
#pragma once

#include "fosssim/core/scene.h"

#include <string>

namespace fosssim {

/// The most impulse passes (hybrid, --compat) or impulses per particle (default mode) a step may
/// take before the failsafe (<collision maxiters>).
inline constexpr int kMaxCollisionIterations = 10000;
/// Why more are refused, for the messages and the format's documentation.
inline constexpr const char* kMaxCollisionIterationsReason =
    "each pass detects the step's contacts again, and a jammed pile makes every pass: one step of 400 "
    "overlapping disks took 2 minutes at 10000 and 12 minutes per step at 100000 (--compat, 2 shared cores); "
    "the course's scenes use at most 10000";
/// The most steps a run may take: more is certainly a typo (and would overflow step counters).
inline constexpr double kMaxSteps = 1e12;

/// The ranges of the scene format's numbers.
enum class ValueRule {
  Positive,     ///< finite, > 0, with a finite reciprocal (masses, radii and time steps are divided by)
  NonNegative,  ///< finite, >= 0
  Fraction,     ///< in [0, 1]
};

/// Why `value` breaks `rule`, worded as the scene file's messages word it ("must be > 0"), or ""
/// when it keeps it. `name` stands for the value in "1/NAME is not finite".
std::string valueProblem(ValueRule rule, double value, const char* name);

/// Why a run of `duration` at steps of `dt` (> 0) is refused: more than kMaxSteps steps
/// ("duration / dt = 1e9 / 1e-9 asks for 1e+18 steps; at most 1e+12 (...)"), or "".
std::string stepCountProblem(double duration, double dt);

/// Whether every value of `scene` is one its scene file could hold: masses and radii > 0, edges
/// between two different particles, half-plane normals finite and not zero (nor of a squared
/// length that overflows or underflows), the COR in [0, 1], maxiters at most
/// kMaxCollisionIterations, the penalty's k and thickness >= 0, a duration >= 0 of at most
/// kMaxSteps steps. The message names the element, its index and the value ("particle 3's mass:
/// must be > 0, got -1"). Expects a scene whose shape checkSceneShape accepts. O(N + E + H).
Status checkSceneValues(const Scene& scene);

}  // namespace fosssim
