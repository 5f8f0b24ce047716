#include "fosssim/math/geometry.h"

#include <gtest/gtest.h>

namespace fosssim::math {
namespace {

TEST(Geometry, SegmentParameter) {
  const Vec2 a(0.0, 0.0), b(2.0, 0.0);
  EXPECT_DOUBLE_EQ(segmentParameterUnclamped(Vec2(0.5, 3.0), a, b), 0.25);
  EXPECT_DOUBLE_EQ(segmentParameterUnclamped(Vec2(3.0, 1.0), a, b), 1.5);
  EXPECT_DOUBLE_EQ(segmentParameterUnclamped(Vec2(-1.0, 1.0), a, b), -0.5);
  EXPECT_EQ(segmentParameterClamped(Vec2(3.0, 1.0), a, b), 1.0);
  EXPECT_EQ(segmentParameterClamped(Vec2(-1.0, 1.0), a, b), 0.0);
  EXPECT_DOUBLE_EQ(segmentParameterClamped(Vec2(0.5, 3.0), a, b), 0.25);
}

TEST(Geometry, DegenerateSegmentGivesEndpointA) {
  const Vec2 a(1.0, 1.0);
  EXPECT_EQ(segmentParameterUnclamped(Vec2(5.0, 0.0), a, a), 0.0);
  const Vec2 n = segmentContactVector(Vec2(5.0, 0.0), a, a);
  EXPECT_EQ(n, Vec2(-4.0, 1.0));
}

TEST(Geometry, SegmentContactVectorPointsToClosestPoint) {
  double alpha = -1.0;
  const Vec2 n = segmentContactVector(Vec2(3.0, 1.0), Vec2(0.0, 0.0), Vec2(2.0, 0.0), &alpha);
  EXPECT_EQ(alpha, 1.0);
  EXPECT_EQ(n, Vec2(-1.0, -1.0));
  EXPECT_EQ(pointOnSegment(Vec2(0.0, 0.0), Vec2(2.0, 4.0), 0.5), Vec2(1.0, 2.0));
}

TEST(Geometry, HalfPlaneContactVectorIgnoresNormalScale) {
  const Vec2 x(3.0, 2.0), p(0.0, -1.0);
  const Vec2 n1 = halfPlaneContactVector(x, p, Vec2(0.0, 1.0));
  const Vec2 n2 = halfPlaneContactVector(x, p, Vec2(0.0, 7.0));
  EXPECT_EQ(n1, Vec2(0.0, -3.0));
  EXPECT_DOUBLE_EQ(n2.y(), -3.0);
  // Slanted normal: distance from x to the line y = -x through the origin, m = (1, 1).
  const Vec2 n3 = halfPlaneContactVector(Vec2(1.0, 1.0), Vec2(0.0, 0.0), Vec2(1.0, 1.0));
  EXPECT_DOUBLE_EQ(n3.x(), -1.0);
  EXPECT_DOUBLE_EQ(n3.y(), -1.0);
}

}  // namespace
}  // namespace fosssim::math
