#include "clipper/detail/point_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace shadowgen::clipper::detail {
namespace {

TEST(PointIndex, DenseIdsInOrderOfFirstSightThroughGrowth) {
  PointIndex index(1);  // far too small: it must grow
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(index.id({i * 0.5, -i * 0.25}), static_cast<std::size_t>(i));
  }
  EXPECT_EQ(index.size(), 1000u);
  for (int i = 999; i >= 0; --i) {
    ASSERT_EQ(index.id({i * 0.5, -i * 0.25}), static_cast<std::size_t>(i));
  }
  EXPECT_EQ(index.size(), 1000u);
  EXPECT_EQ(index.point(7), (Point2{3.5, -1.75}));
  // -0.0 == 0.0, so they are one point; a point one ulp away is another.
  EXPECT_EQ(index.id({-0.0, 0.0}), index.id({0.0, -0.0}));
  EXPECT_EQ(index.id({0.0, 0.0}), 0u);
  EXPECT_EQ(index.id({std::nextafter(0.0, 1.0), 0.0}), 1000u);
}

// PointIndex takes a slot from the hash's low bits. The corners of blocks on a grid
// (integers and halves, dozens of trailing zero bits) all had the same low bits, so every
// lookup walked one run of the table: 65,536 blocks on a ground took 24 s to clip.
TEST(Point2Hash, GridPointsSpreadOverTheLowBits) {
  std::set<std::size_t> low_bits;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) low_bits.insert(Point2Hash{}({i * 10.0 + 2.5, j * 10.0}) & 4095);
  }
  // 4,096 points into 4,096 slots: a uniform hash fills about 1 - 1/e of them (2,589).
  EXPECT_GT(low_bits.size(), 2400u);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
