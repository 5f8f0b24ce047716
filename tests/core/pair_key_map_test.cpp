// The failsafe's flat pair-key map against std::map: the same entries after random inserts (real
// pair keys of every kind, neighbours whose keys differ in a few bits, so probes collide and
// wrap), lookups of absent keys, repeated inserts that must keep the first value, growth through
// many doublings, and clears that must forget everything while the storage is reused.
#include "core/collision/pair_key_map.h"

#include "core/collision/pair_candidates.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

namespace fosssim {
namespace {

uint64_t randomKey(std::mt19937& rng, int particles) {
  std::uniform_int_distribution<int> particle(0, particles - 1), kind(0, 2);
  const PairKind k = static_cast<PairKind>(kind(rng));
  // Drawn in separate statements: a call's arguments are evaluated in an order the compiler picks
  // (gcc right to left, clang left to right), and both must see the same keys.
  const int i = particle(rng);
  const int j = particle(rng);
  return pairKey(i, k, j);
}

void expectSame(const PairKeyMap<int>& map, const std::map<uint64_t, int>& expected) {
  ASSERT_EQ(map.size(), static_cast<int>(expected.size()));
  for (const auto& [key, value] : expected) {
    const int* found = map.find(key);
    ASSERT_NE(found, nullptr) << key;
    EXPECT_EQ(*found, value);
  }
  std::map<uint64_t, int> visited;
  map.forEach([&](uint64_t key, int value) { EXPECT_TRUE(visited.emplace(key, value).second) << "twice: " << key; });
  EXPECT_EQ(visited, expected);
}

TEST(PairKeyMap, HoldsWhatAStdMapHoldsThroughGrowthAndClears) {
  std::mt19937 rng(7);
  PairKeyMap<int> map;
  EXPECT_EQ(map.find(pairKey(0, PairKind::ParticleParticle, 1)), nullptr);  // empty, no storage yet
  for (int round = 0; round < 4; ++round) {
    std::map<uint64_t, int> expected;
    // Small particle counts make many keys repeat (insert must keep the first value); large ones
    // spread them. 5,000 entries is many doublings from the first 64 slots.
    const int particles = round % 2 == 0 ? 40 : 100000;
    for (int k = 0; k < 5000; ++k) {
      const uint64_t key = randomKey(rng, particles);
      const bool fresh = expected.emplace(key, k).second;
      EXPECT_EQ(map.insert(key, k), fresh);
    }
    expectSame(map, expected);
    for (int k = 0; k < 2000; ++k) {
      const uint64_t key = randomKey(rng, particles);
      EXPECT_EQ(map.contains(key), expected.count(key) == 1);
    }
    map.clear();
    EXPECT_EQ(map.size(), 0);
    for (const auto& entry : expected) EXPECT_FALSE(map.contains(entry.first));
  }
}

TEST(PairKeyMap, NeighbouringKeysThatShareTheirHighBitsStayApart) {
  // One particle's pairs with 3,000 consecutive others: keys that differ only in their low bits.
  PairKeyMap<int> map;
  std::map<uint64_t, int> expected;
  for (int other = 0; other < 3000; ++other) {
    const uint64_t key = pairKey(12345, PairKind::ParticleEdge, other);
    ASSERT_TRUE(map.insert(key, other));
    expected.emplace(key, other);
  }
  expectSame(map, expected);
  EXPECT_FALSE(map.contains(pairKey(12345, PairKind::ParticleParticle, 17)));
  EXPECT_FALSE(map.contains(pairKey(12346, PairKind::ParticleEdge, 17)));
}

}  // namespace
}  // namespace fosssim
