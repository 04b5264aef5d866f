#include "clipper/detail/box_masks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

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

bool meets(const Lanes& b, std::size_t k, double x0, double x1, double y0, double y1) {
  return b.xlo[k] <= x1 && x0 <= b.xhi[k] && b.ylo[k] <= y1 && y0 <= b.yhi[k];
}

TEST(BoxMasks, EveryBitIsTheClosedOverlapOfItsBoxAndNoBitLiesPastTheEnd) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coordinate(-8, 8), extent(0, 4);
  for (std::size_t count = 0; count <= MaskLane::kCapacity; ++count) {
    for (int trial = 0; trial < 20; ++trial) {
      const Lanes b = random_boxes(rng, count);
      const double x0 = coordinate(rng), y0 = coordinate(rng);
      const double x1 = x0 + extent(rng), y1 = y0 + extent(rng);
      for (std::size_t first = 0; first < count; first += 64) {
        const std::size_t end = std::min(count, first + 64);
        std::uint64_t expected = 0;
        for (std::size_t k = first; k < end; ++k) {
          if (meets(b, k, x0, x1, y0, y1)) expected |= std::uint64_t{1} << (k - first);
        }
        ASSERT_EQ(boxes_meeting(b.xlo, b.xhi, b.ylo, b.yhi, first, end, x0, x1, y0, y1), expected)
            << count << " boxes from " << first << ", trial " << trial;
        ASSERT_EQ(boxes_meeting_scalar(b.xlo, b.xhi, b.ylo, b.yhi, first, end, x0, x1, y0, y1),
                  expected)
            << count << " boxes from " << first << ", trial " << trial;
      }
    }
  }
}

TEST(BoxMasks, EachBoxMeetingVisitsTheMeetingBoxesFromTheFirstInOrderAndStopsWhenAsked) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> coordinate(-8, 8), extent(0, 4);
  for (const std::size_t count : {0u, 1u, 5u, 63u, 64u, 65u, 100u, 128u}) {
    const Lanes b = random_boxes(rng, count);
    const double x0 = coordinate(rng), y0 = coordinate(rng);
    const double x1 = x0 + extent(rng), y1 = y0 + extent(rng);
    for (const std::size_t from : {0u, 1u, 3u, 63u, 64u, 66u, 127u, 128u}) {
      if (from > count) continue;
      std::vector<std::size_t> expected, visited;
      for (std::size_t k = from; k < count; ++k) {
        if (meets(b, k, x0, x1, y0, y1)) expected.push_back(k);
      }
      EXPECT_TRUE(each_box_meeting(b.xlo, b.xhi, b.ylo, b.yhi, from, count, x0, x1, y0, y1,
                                   [&](std::size_t k) {
                                     visited.push_back(k);
                                     return true;
                                   }));
      ASSERT_EQ(visited, expected) << count << " boxes from " << from;
      if (expected.empty()) continue;
      // Stopped at the last one it meets: every one before it visited, and false back.
      visited.clear();
      EXPECT_FALSE(each_box_meeting(b.xlo, b.xhi, b.ylo, b.yhi, from, count, x0, x1, y0, y1,
                                    [&](std::size_t k) {
                                      visited.push_back(k);
                                      return k != expected.back();
                                    }));
      EXPECT_EQ(visited, expected);
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
  EXPECT_EQ(boxes_meeting(x, x, y, y, 0, 5, 1.0, 3.0, 2.0, 4.0), 0b10011u);
  EXPECT_EQ(boxes_meeting_scalar(x, x, y, y, 0, 5, 1.0, 3.0, 2.0, 4.0), 0b10011u);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
