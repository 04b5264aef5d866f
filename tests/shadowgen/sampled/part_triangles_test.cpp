// A part as triangles: concave parts and parts with holes are covered exactly, on the
// part's own vertices and in its plane.

#include "shadowgen/sampled/part_triangles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "hsr/area.h"

namespace shadowgen::sampled {
namespace {

// An L in z = 0: [0,10]² less [5,10]², area 75, front side up.
hsr::Polygon3 l_shape() {
  return {{{0, 0, 0}, {10, 0, 0}, {10, 5, 0}, {5, 5, 0}, {5, 10, 0}, {0, 10, 0}}, {}};
}

TEST(PartTriangles, ConcavePartIsCoveredByItsArea) {
  const PartTriangles t = part_triangles(l_shape());
  EXPECT_EQ(t.triangles.size(), 4u);  // a hexagon: n − 2
  EXPECT_DOUBLE_EQ(t.area, 75.0);
  EXPECT_DOUBLE_EQ(t.triangle_area(), 75.0);
  EXPECT_EQ(t.normal, glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.magnitude, 10.0);
  // No triangle reaches into the missing corner: their centroids all lie in the L.
  for (const Triangle3& tri : t.triangles) {
    const glm::dvec3 c = (tri.a + tri.b + tri.c) / 3.0;
    EXPECT_FALSE(c.x > 5.0 && c.y > 5.0) << c.x << " " << c.y;
  }
}

TEST(PartTriangles, HolesAreLeftOutAndTiltedPlanesKept) {
  // A square 4 × 4 with a 2 × 2 hole, tilted about the x axis by 30 degrees.
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const auto at = [&](double x, double y) { return glm::dvec3(x, y * c, y * s); };
  const hsr::Polygon3 part{{at(0, 0), at(4, 0), at(4, 4), at(0, 4)},
                           {{at(1, 1), at(1, 3), at(3, 3), at(3, 1)}}};
  const PartTriangles t = part_triangles(part);
  EXPECT_NEAR(t.triangle_area(), 12.0, 1e-12);
  EXPECT_NEAR(t.area, hsr::area(part), 1e-12);
  const glm::dvec3 normal(0, -s, c);
  EXPECT_NEAR(glm::length(t.normal - normal), 0.0, 1e-12);
  for (const Triangle3& tri : t.triangles) {
    for (const glm::dvec3& v : {tri.a, tri.b, tri.c}) {
      EXPECT_NEAR(glm::dot(v, normal), 0.0, 1e-12);  // on the part's plane
    }
    // Nothing over the hole: a centroid in it would have 1 < x < 3 and 1 < y < 3.
    const glm::dvec3 m = (tri.a + tri.b + tri.c) / 3.0;
    const double y = glm::dot(m, glm::dvec3(0, c, s));
    EXPECT_FALSE(m.x > 1.0 && m.x < 3.0 && y > 1.0 && y < 3.0);
  }
}

TEST(PartTriangles, PartWithoutAreaHasNoTriangles) {
  const PartTriangles t = part_triangles({{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {}});
  EXPECT_TRUE(t.triangles.empty());
  EXPECT_EQ(t.area, 0.0);
  EXPECT_EQ(t.normal, glm::dvec3(0.0));
}

}  // namespace
}  // namespace shadowgen::sampled
