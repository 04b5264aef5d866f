// Tests of clipper/tiles.h: a polygon with a hole per building cut into tiles that cover it
// exactly (CGAL's exact union), keep all its vertices and its orientation.

#include "clipper/tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <set>
#include <span>
#include <utility>

#include "clipper/polygon.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::clipper {
namespace {

// A 100 × 100 ground, with vertices where its bottom and right sides run straight on
// (where a neighbouring region could touch it), and a 15 × 15 grid of diamond holes at
// generic coordinates: 906 vertices.
PolygonWithHoles2 ground_with_holes() {
  PolygonWithHoles2 ground{{{0, 0}, {50, 0}, {100, 0}, {100, 50}, {100, 100}, {0, 100}}, {}};
  for (int i = 0; i < 15; ++i) {
    for (int j = 0; j < 15; ++j) {
      const double x = 6.5 * i + 3.3 + 0.01 * j, y = 6.5 * j + 3.1 + 0.013 * i;
      ground.holes.push_back({{x, y - 1.7}, {x - 2.1, y}, {x, y + 1.9}, {x + 2.3, y}});
    }
  }
  return ground;
}

std::set<std::pair<double, double>> vertices_of(const PolygonSet2& set) {
  std::set<std::pair<double, double>> out;
  for (const PolygonWithHoles2& p : set) {
    for (const Point2& q : p.outer) out.insert({q.x, q.y});
    for (const Loop2& h : p.holes) {
      for (const Point2& q : h) out.insert({q.x, q.y});
    }
  }
  return out;
}

double rounding_bound(const PolygonSet2& set) {
  double bound = 0.0;
  for (const PolygonWithHoles2& p : set) {
    bound += rounding_area_bound(p.outer);
    for (const Loop2& h : p.holes) bound += rounding_area_bound(h);
  }
  return bound;
}

TEST(Tiles, AGroundWithAHolePerBuildingIsCutIntoTilesThatCoverItExactly) {
  const PolygonWithHoles2 ground = ground_with_holes();
  ASSERT_EQ(vertex_count(ground), 906u);
  const PolygonSet2 tiles = split_into_tiles(ground, 256);
  // About 2 · 906 / 256 cells: 3 across and 3 down, each holding its share of the holes.
  EXPECT_GE(tiles.size(), 8u);
  std::size_t largest = 0;
  for (const PolygonWithHoles2& tile : tiles) largest = std::max(largest, vertex_count(tile));
  EXPECT_LE(largest, 256u);
  // Each tile valid; tiles share their seams, so they are not a valid set of disjoint
  // boundaries, but their areas add up to their union's below: they do not overlap.
  for (const PolygonWithHoles2& tile : tiles) EXPECT_EQ(test::validity_problem(tile), "");

  // The tiles' union is the ground, up to the rounding of the crossings on the cut lines.
  const PolygonSet2 whole{ground};
  const test::ExactUnionComparison cover =
      test::compare_exact_unions(std::span(&tiles, 1), std::span(&whole, 1));
  EXPECT_LE(cover.symmetric_difference, rounding_bound(tiles));
  EXPECT_NEAR(test::exact_area_of_pieces(tiles), test::exact_area(whole), rounding_bound(tiles));

  // Every vertex of the ground stays a vertex, those where its sides run straight on too.
  const auto kept = vertices_of(tiles);
  for (const auto& v : vertices_of(whole))
    EXPECT_TRUE(kept.count(v)) << v.first << ", " << v.second;
  EXPECT_TRUE(kept.count({50.0, 0.0}));
  EXPECT_TRUE(kept.count({100.0, 50.0}));
  EXPECT_GT(kept.size(), vertices_of(whole).size());  // the crossings on the cut lines
}

TEST(Tiles, TilesRunTheWayThePolygonRuns) {
  PolygonWithHoles2 clockwise = ground_with_holes();
  std::reverse(clockwise.outer.begin(), clockwise.outer.end());
  for (Loop2& hole : clockwise.holes) std::reverse(hole.begin(), hole.end());
  const PolygonSet2 tiles = split_into_tiles(clockwise, 256);
  ASSERT_GE(tiles.size(), 8u);
  for (const PolygonWithHoles2& tile : tiles) {
    EXPECT_LT(signed_area(tile.outer), 0.0);
    for (const Loop2& hole : tile.holes) EXPECT_GT(signed_area(hole), 0.0);
  }
  EXPECT_NEAR(area(tiles), area(ground_with_holes()), rounding_bound(tiles));
}

TEST(Tiles, APolygonOfFewVerticesIsItsOwnTile) {
  const PolygonWithHoles2 ground = ground_with_holes();
  EXPECT_EQ(split_into_tiles(ground, 906), PolygonSet2{ground});
  const PolygonWithHoles2 square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  EXPECT_EQ(split_into_tiles(square, 4), PolygonSet2{square});
  // One more vertex than allowed: cut in four at x = 0.5 and y = 0.5.
  const PolygonSet2 quarters = split_into_tiles(square, 3);
  EXPECT_EQ(quarters.size(), 4u);
  EXPECT_EQ(area(quarters), 1.0);
}

}  // namespace
}  // namespace shadowgen::clipper
