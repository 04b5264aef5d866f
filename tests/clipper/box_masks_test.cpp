#include "clipper/detail/box_masks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace shadowgen::clipper::detail {
namespace {

struct Lanes {
  MaskLane xlo, xhi, ylo, yhi;
};

// `count` random boxes on a coarse grid, so that many touch the query box exactly (the
// comparisons are closed) and some are points.
Lanes random_boxes(std::mt19937_64& rng, std::size_t count) {
  std::uniform_int_distribution<int> coordinate(-8, 8), extent(0, 3);
  Lanes lanes;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = coordinate(rng), y = coordinate(rng);
    lanes.xlo[k] = x;
    lanes.xhi[k] = x + extent(rng);
    lanes.ylo[k] = y;
    lanes.yhi[k] = y + extent(rng);
  }
  for (MaskLane* lane : {&lanes.xlo, &lanes.xhi, &lanes.ylo, &lanes.yhi}) lane->pad(count);
  return lanes;
}

TEST(BoxMasks, EveryBitIsTheClosedOverlapOfItsBoxAndNoBitLiesPastTheCount) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coordinate(-8, 8), extent(0, 4);
  for (std::size_t count = 0; count <= MaskLane::kCapacity; ++count) {
    for (int trial = 0; trial < 50; ++trial) {
      const Lanes b = random_boxes(rng, count);
      const double x0 = coordinate(rng), y0 = coordinate(rng);
      const double x1 = x0 + extent(rng), y1 = y0 + extent(rng);
      std::uint64_t expected = 0;
      for (std::size_t k = 0; k < count; ++k) {
        if (b.xlo[k] <= x1 && x0 <= b.xhi[k] && b.ylo[k] <= y1 && y0 <= b.yhi[k]) {
          expected |= std::uint64_t{1} << k;
        }
      }
      ASSERT_EQ(boxes_meeting(b.xlo, b.xhi, b.ylo, b.yhi, count, x0, x1, y0, y1), expected)
          << count << " boxes, trial " << trial;
      ASSERT_EQ(boxes_meeting_scalar(b.xlo, b.xhi, b.ylo, b.yhi, count, x0, x1, y0, y1), expected)
          << count << " boxes, trial " << trial;
    }
  }
}

TEST(BoxMasks, PointsOnTheBoundaryAreInAndNanMeetsNothing) {
  MaskLane x, y;
  x[0] = 1.0, y[0] = 2.0;                       // on the box's corner
  x[1] = 1.5, y[1] = 2.0;                       // on its lower side
  x[2] = std::nextafter(1.0, 0.0), y[2] = 2.5;  // an ulp to the left
  x[3] = std::numeric_limits<double>::quiet_NaN(), y[3] = 2.5;
  x[4] = 3.0, y[4] = 4.0;  // the opposite corner
  x.pad(5);
  y.pad(5);
  EXPECT_EQ(boxes_meeting(x, x, y, y, 5, 1.0, 3.0, 2.0, 4.0), 0b10011u);
  EXPECT_EQ(boxes_meeting_scalar(x, x, y, y, 5, 1.0, 3.0, 2.0, 4.0), 0b10011u);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
