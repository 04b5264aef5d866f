// clipper/normalize.h: the orientation of loops, also of loops that pass a point twice
// and of loops that cross themselves by rounding.

#include "clipper/normalize.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "clipper/clip.h"

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
    EXPECT_TRUE(encloses_counter_clockwise(loop)) << "rotation " << k;
    EXPECT_FALSE(encloses_counter_clockwise(reversed(loop))) << "rotation " << k << ", reversed";
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

// A sliver far from the origin: the signed area's rounding hides its sign, and the exact
// turn decides.
TEST(IsCounterClockwise, SliverFarFromTheOrigin) {
  ExpectOrientation({{1e8, 1e8}, {1e8 + 1.0, 1e8}, {1e8 + 0.5, 1e8 + 0x1p-20}});
}

// The body of a lit polygon as the database reader charted it in its part's plane (reader
// fuzzer finding "scene-split-face-lit-polygons-overlap"): the triangle (0.4, 1), (0, 0),
// (1, 0) run counter-clockwise, with the corner (0, 0) doubled by the rounding of a lift
// into (0, 0) and (-3e-18, 5.6e-16). The edge from the second copy crosses the edge into
// the first, closing a lobe of about 1e-31 that turns clockwise, and the second copy is
// the lowest vertex.
const Loop2 kBodyWithRoundingLobe = {{0.4, 1.0}, {0.0, 0.0}, {-3e-18, 5.6e-16}, {1.0, 8e-16}};

TEST(EnclosesCounterClockwise, FollowsTheBodyNotALobeOfRounding) {
  ASSERT_FALSE(is_counter_clockwise(kBodyWithRoundingLobe)) << "the lobe turns clockwise";
  for (std::size_t k = 0; k < kBodyWithRoundingLobe.size(); ++k) {
    Loop2 loop = kBodyWithRoundingLobe;
    std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(k), loop.end());
    EXPECT_TRUE(encloses_counter_clockwise(loop)) << "rotation " << k;
    EXPECT_FALSE(encloses_counter_clockwise(reversed(loop))) << "rotation " << k << ", reversed";
  }
}

TEST(Normalized, OrientsALoopCrossingItselfByRoundingByItsBody) {
  const PolygonSet2 out = normalized({{reversed(kBodyWithRoundingLobe), {}}});
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(signed_area(out[0].outer), 0.5, 1e-15);
  const Loop2 square = {{-1, -1}, {2, -1}, {2, 2}, {-1, 2}};
  const PolygonSet2 with_hole = normalized({{square, {kBodyWithRoundingLobe}}});
  ASSERT_EQ(with_hole.size(), 1u);
  ASSERT_EQ(with_hole[0].holes.size(), 1u);
  EXPECT_NEAR(signed_area(with_hole[0].holes[0]), -0.5, 1e-15);
}

// What the database reader does with it: the union of the lit polygons within their part.
// Oriented by its lobe, the body was a hole of the clips and covered nothing.
TEST(Normalized, ALoopCrossingItselfByRoundingCoversItsBodyAsAClip) {
  const PolygonWithHoles2 square{{{-1, -1}, {2, -1}, {2, 2}, {-1, 2}}, {}};
  const std::vector<PolygonWithHoles2> clips = {{kBodyWithRoundingLobe, {}}};
  EXPECT_NEAR(area(clip(square, clips).inside), 0.5, 1e-15);
  EXPECT_NEAR(area(clip(square, clips[0]).inside), 0.5, 1e-15);
}

}  // namespace
}  // namespace shadowgen::clipper
