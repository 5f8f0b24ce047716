// State::addParticle: what building a scene by hand relies on (rows 2i and 2i + 1 for particle i).
#include <gtest/gtest.h>

#include "fosssim/core/state.h"

namespace fosssim {
namespace {

TEST(State, AddParticleAppendsAtRows2iAnd2iPlus1AndKeepsTheOthers) {
  State s;
  EXPECT_EQ(s.addParticle(Vec2(1, 2), Vec2(3, 4)), 0);
  EXPECT_EQ(s.addParticle(Vec2(-5, 6), Vec2(7, -8)), 1);
  ASSERT_EQ(s.numParticles(), 2);
  ASSERT_EQ(s.x.size(), 4);
  ASSERT_EQ(s.v.size(), 4);
  // Written out, not read back through the layout the method assumes.
  EXPECT_EQ(s.x(0), 1);
  EXPECT_EQ(s.x(1), 2);
  EXPECT_EQ(s.x(2), -5);
  EXPECT_EQ(s.x(3), 6);
  EXPECT_EQ(s.v(0), 3);
  EXPECT_EQ(s.v(1), 4);
  EXPECT_EQ(s.v(2), 7);
  EXPECT_EQ(s.v(3), -8);
  EXPECT_EQ(s.time, 0);
  EXPECT_EQ(s.step, 0);
}

}  // namespace
}  // namespace fosssim
