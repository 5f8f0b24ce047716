// Narrow-phase throughput: particle-particle and particle-edge continuous-time queries per second
// on one core, through the detector the handlers use (ContinuousDetector, no polynomial log).
#pragma once

#include <string>
#include <vector>

namespace fosssim::bench {

struct QueryRate {
  std::string name;
  double perSecond = 0;  ///< queries per second of CPU time, best of the repeats
  double hitRate = 0;    ///< fraction of the queries that found a collision
};

/// Candidate pairs of the rain pile (PP) and the chains pile (PE) as the broad phase hands them
/// over, and near pairs built to need every polynomial (PP within 1.5 reach, PE within 1.5 reach
/// of a point of the edge).
std::vector<QueryRate> measureQueryRates();

}  // namespace fosssim::bench
