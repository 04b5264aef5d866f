#include "clipper/detail/point_location.h"

#include <gtest/gtest.h>

#include <vector>

namespace shadowgen::clipper::detail {
namespace {

// The parcel of the JTS case pg-4182-2 (tests/clipper/regressions/pg-4182-2-*): it runs
// v4 -> v3, up a crack to v2 and back to v1, one ulp (4.7e-10) beside v3. The segment
// v1 -> v4, the neighbour's edge, lies in the sliver between v4 -> v3 and the crack's
// mouth, inside the parcel; its midpoint rounded to doubles lies outside.
const Point2 v0{3461832.4700000002, 5343064.6100000003};
const Point2 v1{3461825.8900000001, 5343072.2300000004};
const Point2 v2{3461840.6316683637, 5343080.5565981604};
const Point2 v3{3461825.8899999997, 5343072.2300000004};
const Point2 v4{3461819.8500000001, 5343079.2199999997};
const Point2 v5{3461814.04, 5343085.96};
const Loop2 parcel{
    v5, v4, v3, v2, v1, v0, {3461898.41, 5343102.2097999994}, {3461814.04, 5343102.21}};

TEST(LocateMidpoint, InsideASliverWhereTheRoundedMidpointIsOutside) {
  const Point2 rounded{0.5 * (v1.x + v4.x), 0.5 * (v1.y + v4.y)};
  ASSERT_EQ(locate(rounded, parcel), Location::kOutside);  // what rounding gave
  EXPECT_EQ(locate_midpoint(v1, v4, parcel), Location::kInside);
  EXPECT_EQ(locate_midpoint(v4, v1, parcel), Location::kInside);
  EXPECT_EQ(locate_midpoint(v1, v4, std::vector<Loop2>{parcel}), Location::kInside);
  const Loop2 reversed(parcel.rbegin(), parcel.rend());  // orientation does not matter
  EXPECT_EQ(locate_midpoint(v1, v4, reversed), Location::kInside);
}

TEST(LocateMidpoint, OnTheBoundaryWhereNoDoubleLies) {
  // The sliver itself: the midpoints of its edges are on its boundary, although the one
  // of v3 v1 (half an ulp from either) is no double and the others round off the edges.
  const Loop2 sliver{v4, v3, v1};
  EXPECT_EQ(locate_midpoint(v1, v4, sliver), Location::kBoundary);
  EXPECT_EQ(locate_midpoint(v3, v4, sliver), Location::kBoundary);
  EXPECT_EQ(locate_midpoint(v3, v1, sliver), Location::kBoundary);
  EXPECT_EQ(locate_midpoint(v3, v1, parcel), Location::kOutside);  // the crack's mouth
  EXPECT_EQ(locate_midpoint(v0, v1, parcel), Location::kBoundary);
  EXPECT_EQ(locate_midpoint(v2, v5, parcel), Location::kInside);
  EXPECT_EQ(locate_midpoint(v5, {3461700.0, 5343085.96}, parcel), Location::kOutside);
}

}  // namespace
}  // namespace shadowgen::clipper::detail
