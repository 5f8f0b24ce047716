// Shared by the broad phase's tests (broad_phase_test.cpp, broad_phase_grazing_test.cpp): a scene
// with its step's start and end positions, the candidate pairs a PairCandidates lists, and the
// ground truth of every pair checked by the reference's sweep.
#pragma once

#include "core/collision/collision_search.h"
#include "core/collision/pair_candidates.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

namespace fosssim::testing {

/// A scene and one step of it: positions at its start (qs) and end (qe), 2N each.
struct Motion {
  Scene scene;
  VecX qs, qe;
};

/// Every pair the candidates list, as pair keys (and that each particle's lists are sorted).
inline std::set<uint64_t> candidateKeys(const Scene& scene, const PairCandidates& c) {
  std::set<uint64_t> keys;
  std::vector<int> row;
  for (int i = 0; i < scene.numParticles(); ++i) {
    row.clear();
    c.particlesOf(i, -1, row);
    EXPECT_TRUE(std::is_sorted(row.begin(), row.end()));
    for (int j : row) keys.insert(pairKey(i, PairKind::ParticleParticle, j));
    row.clear();
    c.edgesOf(i, -1, row);
    EXPECT_TRUE(std::is_sorted(row.begin(), row.end()));
    for (int e : row) keys.insert(pairKey(i, PairKind::ParticleEdge, e));
    for (int h = 0; h < static_cast<int>(scene.halfplanes.size()); ++h)
      if (c.nearPlane(i, h)) keys.insert(pairKey(i, PairKind::ParticleHalfPlane, h));
  }
  return keys;
}

/// Every collision, checking every pair (the reference's sweep).
inline std::vector<Collision> allPairs(const Scene& scene, const VecX& qs, const VecX& qe, const math::DetectionRules& rules) {
  std::vector<Collision> out;
  ContinuousDetector(rules).forEachCollision(scene, qs, qe, nullptr, [&](const Collision& c) { out.push_back(c); });
  return out;
}

}  // namespace fosssim::testing
