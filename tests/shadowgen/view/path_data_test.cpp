// SVG path data (shadowgen/view/detail/path_data.h): the exact form as before, and the
// grid's: vertices rounded to 1/1000 pixel, written relative with as few characters as the
// numbers need, the vertices that rounding leaves repeated or on a straight line dropped.

#include "shadowgen/view/detail/path_data.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace shadowgen {
namespace {

std::string grid(const std::vector<clipper::PolygonWithHoles2>& shapes) {
  std::string out;
  view::detail::append_grid_path_data(out, shapes);
  return out;
}

std::string exact(const std::vector<clipper::PolygonWithHoles2>& shapes) {
  std::string out;
  view::detail::append_exact_path_data(out, shapes);
  return out;
}

TEST(PathData, TheExactFormIsAbsoluteWithRoundTripCoordinates) {
  const clipper::PolygonWithHoles2 square{{{0.1, 0}, {2, 0}, {2, 2}, {0.1, 2}},
                                          {{{0.5, 0.5}, {0.5, 1}, {1, 1}}}};
  EXPECT_EQ(exact({square}), "M0.1,0 L2,0 2,2 0.1,2 Z M0.5,0.5 L0.5,1 1,1 Z");
}

TEST(PathData, OnTheGridEachSubpathIsRelativeToTheLastOnesStart) {
  // A square with a triangular hole, then a second square: "m" from the start before, "h"
  // and "v" along the axes, "l" otherwise; no separator before a minus sign, no zero
  // before the point.
  const clipper::PolygonWithHoles2 square{{{10, 10}, {12, 10}, {12, 12}, {10, 12}},
                                          {{{10.5, 10.5}, {10.5, 11}, {11.25, 10.875}}}};
  const clipper::PolygonWithHoles2 other{{{20, 10}, {21, 10}, {21, 11}, {20, 11}}, {}};
  EXPECT_EQ(grid({square, other}), "M10 10h2v2h-2zm.5 .5v.5l.75-.125zm9.5-.5h1v1h-1z");
}

TEST(PathData, VerticesRoundToAThousandthOfAPixel) {
  const clipper::PolygonWithHoles2 triangle{{{0.0004, 0}, {3.1416, 0.0006}, {1.00049, 2.7183}}, {}};
  EXPECT_EQ(grid({triangle}), "M0 0l3.142 .001-2.142 2.717z");
  // Negative coordinates (a picture's pieces stay within it, a path may not).
  const clipper::PolygonWithHoles2 left{{{-1.5, -2}, {-0.25, -2}, {-0.25, -1}}, {}};
  EXPECT_EQ(grid({left}), "M-1.5-2h1.25v1z");
}

TEST(PathData, VerticesThatRoundingLeavesRepeatedOrInLineAreDropped) {
  // Pieces joined along an edge leave vertices a few ulps off the straight line; on the
  // grid they are on it, and go (the first vertex too: the loop starts at the next).
  const clipper::PolygonWithHoles2 strip{{{1, 496.69014084507046},
                                          {0, 496.6901408450704},
                                          {0, 490},
                                          {2, 490},
                                          {2.0000001, 496.6901408450704},
                                          {2, 496.6901408450704}},
                                         {}};
  EXPECT_EQ(grid({strip}), "M0 496.69v-6.69h2v6.69z");
  // A loop left without area (a sliver thinner than the grid) is not written.
  const clipper::PolygonWithHoles2 sliver{{{0, 0}, {5, 0.0001}, {10, 0}, {5, 0.0002}}, {}};
  const clipper::PolygonWithHoles2 unit{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  EXPECT_EQ(grid({sliver, unit}), "M0 0h1v1h-1z");
}

TEST(PathData, CoordinatesBeyondAMillionPixelsAreWrittenExact) {
  const clipper::PolygonWithHoles2 far{{{0, 0}, {2e6, 0}, {2e6, 1}}, {}};
  EXPECT_EQ(grid({far}), exact({far}));
}

}  // namespace
}  // namespace shadowgen
