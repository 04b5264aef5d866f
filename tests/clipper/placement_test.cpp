#include "clipper/placement.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "clipper/detail/point_location.h"
#include "tests/support/cgal_oracle.h"
#include "tests/support/random_polygons.h"

namespace shadowgen::clipper {
namespace {

PolygonWithHoles2 square(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
}

Placement place(const PolygonWithHoles2& polygon, const std::vector<PolygonWithHoles2>& region) {
  std::vector<const PolygonWithHoles2*> pointers;
  for (const PolygonWithHoles2& r : region) pointers.push_back(&r);
  return placement(polygon, pointers);
}

TEST(Placement, AwayFromTheRegionsEdges) {
  const PolygonWithHoles2 big = square(0, 0, 10, 10);
  EXPECT_EQ(place(square(2, 2, 3, 3), {big}), Placement::kInside);
  EXPECT_EQ(place(square(12, 2, 13, 3), {big}), Placement::kOutside);
  EXPECT_EQ(place(square(12, 2, 13, 3), {}), Placement::kOutside);
}

TEST(Placement, SharingAnEdgeOrACornerWithTheRegion) {
  const PolygonWithHoles2 region = square(0, 0, 10, 10);
  EXPECT_EQ(place(square(10, 2, 12, 4), {region}), Placement::kOutside);    // beside it
  EXPECT_EQ(place(square(10, 10, 12, 12), {region}), Placement::kOutside);  // at a corner
  EXPECT_EQ(place(square(0, 0, 4, 10), {region}), Placement::kInside);      // its left part
  EXPECT_EQ(place(square(8, 4, 12, 6), {region}), Placement::kMeeting);     // across its edge
  // A piece whose edge runs along part of the region's, with vertices on it.
  EXPECT_EQ(place(square(3, 10, 5, 11), {region}), Placement::kOutside);
}

TEST(Placement, TheRegionsBoundaryThroughTheInteriorWithoutCrossingAnEdge) {
  // A triangle whose long edge is the square's diagonal: it only touches the square's
  // corners, yet cuts it in two.
  const PolygonWithHoles2 piece = square(0, 0, 4, 4);
  const PolygonWithHoles2 below{{{0, 0}, {4, 0}, {4, 4}}, {}};
  EXPECT_EQ(place(piece, {below}), Placement::kMeeting);
  // A loop of the region lying inside the piece, touching nothing.
  EXPECT_EQ(place(piece, {square(1, 1, 2, 2)}), Placement::kMeeting);
  // The piece is the region: every edge on the region's boundary.
  EXPECT_EQ(place(piece, {piece}), Placement::kMeeting);
}

TEST(Placement, HolesOfTheRegionAndOfThePiece) {
  PolygonWithHoles2 ring = square(0, 0, 10, 10);
  ring.holes.push_back({{3, 3}, {3, 7}, {7, 7}, {7, 3}});             // clockwise
  EXPECT_EQ(place(square(4, 4, 6, 6), {ring}), Placement::kOutside);  // in the hole
  // The hole itself: its whole boundary lies on the region's, which cannot tell.
  EXPECT_EQ(place(square(3, 3, 7, 7), {ring}), Placement::kMeeting);
  EXPECT_EQ(place(square(2, 2, 8, 8), {ring}), Placement::kMeeting);  // around the hole
  // Beside it, along the hole's edge: every edge's midpoint lies on the region's
  // boundary, but not the whole edge.
  EXPECT_EQ(place(square(0, 0, 3, 10), {ring}), Placement::kInside);
  // A piece with a hole around which the region's polygon lies, touching neither loop.
  PolygonWithHoles2 frame = square(0, 0, 10, 10);
  frame.holes.push_back({{2, 2}, {2, 8}, {8, 8}, {8, 2}});
  EXPECT_EQ(place(frame, {square(3, 3, 7, 7)}), Placement::kOutside);
  EXPECT_EQ(place(frame, {square(-1, -1, 11, 11)}), Placement::kInside);
}

TEST(Placement, OverlappingRegionPolygonsCountOnce) {
  EXPECT_EQ(place(square(1, 1, 2, 2), {square(0, 0, 5, 5), square(0, 0, 3, 3)}),
            Placement::kInside);
}

// Whether every edge of `polygon` has its midpoint on the region's boundary: the one case
// where a polygon wholly inside or outside the region may still be kMeeting.
bool boundary_on_region(const PolygonWithHoles2& polygon, const PolygonWithHoles2& region) {
  std::vector<Loop2> loops = region.holes;
  loops.push_back(region.outer);
  std::vector<const Loop2*> own{&polygon.outer};
  for (const Loop2& hole : polygon.holes) own.push_back(&hole);
  for (const Loop2* loop : own) {
    for (std::size_t i = 0; i < loop->size(); ++i) {
      const Point2& a = (*loop)[i];
      const Point2& b = (*loop)[(i + 1) % loop->size()];
      if (a != b && detail::locate_midpoint(a, b, loops) != detail::Location::kBoundary) {
        return false;
      }
    }
  }
  return true;
}

// Random pairs against CGAL's exact areas: a polygon placed inside has no exact area
// outside the region, one placed outside none inside, and a polygon with area on one side
// only is placed unless its whole boundary lies on the region's. Grid polygons share
// vertices and collinear edges with each other most of the time.
template <class MakePiece, class MakeRegion>
void check_random_pairs(MakePiece make_piece, MakeRegion make_region, std::uint64_t seed,
                        int pairs) {
  std::mt19937_64 rng(seed);
  int inside = 0, outside = 0, meeting = 0;
  for (int i = 0; i < pairs; ++i) {
    const PolygonWithHoles2 piece = make_piece(rng);
    const PolygonWithHoles2 region = make_region(rng);
    const test::ExactAreas exact = test::exact_clip_areas({piece}, {region});
    const Placement placed = place(piece, {region});
    SCOPED_TRACE("pair " + std::to_string(i));
    switch (placed) {
      case Placement::kInside:
        ++inside;
        EXPECT_EQ(exact.outside, 0.0);
        EXPECT_GT(exact.inside, 0.0);
        break;
      case Placement::kOutside:
        ++outside;
        EXPECT_EQ(exact.inside, 0.0);
        break;
      case Placement::kMeeting:
        ++meeting;
        if ((exact.inside == 0.0) != (exact.outside == 0.0)) {
          EXPECT_TRUE(boundary_on_region(piece, region));
        }
        break;
    }
  }
  // Both answers occur: the check above is not vacuous.
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
  EXPECT_GT(meeting, 0);
}

TEST(Placement, AgreesWithExactAreasOnGridPolygons) {
  check_random_pairs(test::random_grid_polygon, test::random_grid_polygon, 71, 1500);
}

// Small pieces (a random polygon with holes shrunk to a tenth, anywhere over the
// region's extent) against random polygons with holes: inside them, in their holes,
// outside and across their edges.
TEST(Placement, AgreesWithExactAreasOnPolygonsWithHoles) {
  const auto small_piece = [](std::mt19937_64& rng) {
    PolygonWithHoles2 p = test::random_polygon_with_holes(rng);
    std::uniform_real_distribution<double> at(-1.2, 1.2);
    const Point2 offset{at(rng), at(rng)};
    const auto shrink = [&offset](Loop2& loop) {
      for (Point2& q : loop) q = {0.1 * q.x + offset.x, 0.1 * q.y + offset.y};
    };
    shrink(p.outer);
    for (Loop2& hole : p.holes) shrink(hole);
    return p;
  };
  check_random_pairs(small_piece, test::random_polygon_with_holes, 72, 800);
}

}  // namespace
}  // namespace shadowgen::clipper
