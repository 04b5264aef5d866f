// clipper/normalize.h: the orientation of loops, also of loops that pass a point twice.

#include "clipper/normalize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace shadowgen::clipper {
namespace {

Loop2 reversed(Loop2 loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

// Every rotation of the loop, both ways round: the answer may not depend on where the
// loop starts.
void ExpectOrientation(const Loop2& counter_clockwise) {
  for (std::size_t k = 0; k < counter_clockwise.size(); ++k) {
    Loop2 loop = counter_clockwise;
    std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(k), loop.end());
    EXPECT_TRUE(is_counter_clockwise(loop)) << "rotation " << k;
    EXPECT_FALSE(is_counter_clockwise(reversed(loop))) << "rotation " << k << ", reversed";
  }
}

TEST(IsCounterClockwise, SimpleLoop) { ExpectOrientation({{0, 0}, {4, 0}, {4, 4}, {0, 4}}); }

// A bow pinched at its lowest point (lowest in the clipper's order: x, then y): two
// triangles touching at (0, 0), each counter-clockwise. The turn at the first visit of
// (0, 0) may run from one lobe into the other and then says nothing about the loop's
// sense (it did for four of the six rotations).
TEST(IsCounterClockwise, BowPinchedAtItsLowestPoint) {
  ExpectOrientation({{0, 0}, {1, -3}, {3, -1}, {0, 0}, {3, 1}, {1, 3}});
}

}  // namespace
}  // namespace shadowgen::clipper
