// Tests of hsr/chart_triangles.h's tiled_chart_triangles: a sloping region with a hole
// per building triangulated in tiles, its own corners kept exactly, the cut lines'
// crossings on its plane, the triangles' area its exact area (CGAL).

#include "hsr/chart_triangles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <set>
#include <tuple>

#include "clipper/polygon.h"
#include "hsr/plane_chart.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::hsr {
namespace {

// A ground sloping up along x and y (z = 0.3 x + 0.2 y + 7) with a 15 × 15 grid of diamond
// holes: 904 corners, its chart drops z.
Polygon3 sloping_ground_with_holes() {
  auto at = [](double x, double y) { return glm::dvec3(x, y, 0.3 * x + 0.2 * y + 7.0); };
  Polygon3 ground{{at(0, 0), at(100, 0), at(100, 100), at(0, 100)}, {}};
  for (int i = 0; i < 15; ++i) {
    for (int j = 0; j < 15; ++j) {
      const double x = 6.5 * i + 3.3 + 0.01 * j, y = 6.5 * j + 3.1 + 0.013 * i;
      ground.holes.push_back({at(x, y - 1.7), at(x - 2.1, y), at(x, y + 1.9), at(x + 2.3, y)});
    }
  }
  return ground;
}

TEST(TiledChartTriangles, AGroundWithAHolePerBuildingKeepsItsCornersAndItsArea) {
  const Polygon3 ground = sloping_ground_with_holes();
  const glm::dvec3 normal = glm::normalize(glm::dvec3(-0.3, -0.2, 1.0));
  const std::optional<ChartTriangles> tiled = tiled_chart_triangles(ground, normal);
  ASSERT_TRUE(tiled);

  // Its own corners, exactly, and more: the crossings of the tiles' cut lines.
  std::set<std::tuple<double, double, double>> corners;
  for (const glm::dvec3& c : tiled->corners) corners.insert({c.x, c.y, c.z});
  std::size_t own = 0;
  auto expect_kept = [&](const Loop3& loop) {
    for (const glm::dvec3& c : loop) {
      EXPECT_TRUE(corners.count({c.x, c.y, c.z})) << c.x << ", " << c.y << ", " << c.z;
      ++own;
    }
  };
  expect_kept(ground.outer);
  for (const Loop3& hole : ground.holes) expect_kept(hole);
  EXPECT_GT(corners.size(), own);
  // Every corner on the plane, within the rounding of its dropped coordinate.
  for (const glm::dvec3& c : tiled->corners) {
    EXPECT_NEAR(c.z, 0.3 * c.x + 0.2 * c.y + 7.0, 1e-12 * 100.0);
  }

  // The triangles turn as the outer loop does and fill the ground's chart exactly, up to
  // the rounding of the crossings.
  const PlaneChart chart = chart_facing(normal);
  ASSERT_EQ(chart.dropped_axis, 2);
  double sum = 0.0;
  for (const clipper::Triangle& t : tiled->triangles) {
    const clipper::Loop2 triangle{tiled->flat[t[0]], tiled->flat[t[1]], tiled->flat[t[2]]};
    EXPECT_GE(clipper::signed_area(triangle), 0.0);
    sum += clipper::signed_area(triangle);
  }
  const double exact = test::exact_area({chart.flatten(ground)});
  EXPECT_NEAR(sum, exact, 1e-12 * exact);
  // The whole polygon, triangulated in one piece, for comparison: the same area.
  const std::optional<ChartTriangles> whole = chart_triangles(ground, normal);
  ASSERT_TRUE(whole);
  EXPECT_EQ(whole->corners.size(), own);
}

TEST(TiledChartTriangles, APolygonOfFewCornersGetsChartTrianglesTriangles) {
  Polygon3 square{{{0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}},
                  {{{0.5, 0.5, 1}, {0.5, 1, 1}, {1, 1, 1}}}};
  const std::optional<ChartTriangles> tiled = tiled_chart_triangles(square, {0, 0, 1});
  const std::optional<ChartTriangles> whole = chart_triangles(square, {0, 0, 1});
  ASSERT_TRUE(tiled && whole);
  EXPECT_EQ(tiled->corners, whole->corners);
  EXPECT_EQ(tiled->triangles, whole->triangles);
}

}  // namespace
}  // namespace shadowgen::hsr
