// Stability against stiffness: the largest time step at which each integrator keeps a spring
// system bounded, found by bisection. "Unstable" means the run failed (non-finite state, failed
// solve) or its energy moved by more than 1e6 times its start within the horizon (runScene).
#pragma once

#include "run.h"
#include "scene_builder.h"

#include <string>

namespace fosssim::study {

/// A row of `bobs` unit masses on the x axis joined by springs of stiffness k and rest length 1,
/// the first one to a fixed anchor; released from rest with alternating displacements of 1e-4
/// (which puts energy into the highest mode too). bobs = 1 is a single spring.
SceneBuilder springRow(int bobs, double k, const std::string& integrator, double dt);

/// Highest angular frequency of springRow: the stiffness matrix k T (T tridiagonal 2, -1 with a
/// last diagonal entry 1) has eigenvalues 4 k sin^2((2j - 1) pi / (4 bobs + 2)), j = 1..bobs.
double highestFrequency(int bobs, double k);

/// Steps a stability probe takes: 10 periods of the highest mode, and at least 200 steps (so that
/// a slow geometric growth near a limit has time to show).
long stabilityHorizon(double omegaMax, double dt);

/// One probe: runs springRow for stabilityHorizon steps.
RunResult probeStability(int bobs, double k, const std::string& integrator, double dt);

struct StabilityLimit {
  double largestStable = 0;     ///< largest dt found stable (NaN if even the smallest tried failed)
  double smallestUnstable = 0;  ///< smallest dt found unstable (NaN if even the largest tried held)
  bool capped = false;          ///< stable at the largest dt tried
  RunResult failure;            ///< the probe at smallestUnstable (why it failed)
  int probes = 0;
};

/// Bisects omegaMax * dt in log space between sLow and sHigh (ratio below 1.001 at the end).
StabilityLimit findStabilityLimit(int bobs, double k, const std::string& integrator, double sLow, double sHigh);

}  // namespace fosssim::study
