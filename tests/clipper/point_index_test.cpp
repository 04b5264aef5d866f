#include "clipper/detail/point_index.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace shadowgen::clipper::detail
