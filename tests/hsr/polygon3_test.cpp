// Newell's vector and the plane of a polygon: exact where the vertices make it so, and
// within a rounding of the exact one where the sums of Newell's formula cancel.

#include "hsr/polygon3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "clipper/predicates.h"
#include "hsr/area.h"
#include "tests/support/cgal_oracle.h"

namespace shadowgen::hsr {
namespace {

using glm::dvec3;

TEST(Newell, TwiceTheVectorArea) {
  const dvec3 o(1e8, -1e8, 5e7);
  const Loop3 square{o, o + dvec3(0, 3, 0), o + dvec3(0, 3, 2), o + dvec3(0, 0, 2)};
  EXPECT_EQ(newell_vector(square), dvec3(12.0, 0.0, 0.0));
  EXPECT_EQ(area(Polygon3{square, {}}), 6.0);
  EXPECT_EQ(plane_of({square, {}}).normal, dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(newell_vector({o, o + dvec3(1, 0, 0)}), dvec3(0.0));
}

// Component `axis` of (b − a) × (c − a), exactly (CGAL), rounded once: twice the signed
// area of the triangle projected onto the other two coordinates, in cyclic order.
double exact_cross_component(const Loop3& t, int axis) {
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const clipper::Loop2 flat{{t[0][i], t[0][j]}, {t[1][i], t[1][j]}, {t[2][i], t[2][j]}};
  const double twice = 2.0 * test::exact_area_of_pieces({{flat, {}}});
  const auto turn = clipper::orient2d(flat[0], flat[1], flat[2]);
  return turn == clipper::Orientation::kClockwise ? -twice : twice;
}

// Face m/2 of an STL file from the reader fuzzer (tests/fuzz/corpus/readers/
// stl-tiny-face-sun-lit-polygon-outside-it): a triangle 2.5e-9 long and 2.0e-19 wide, of
// area 2.5e-28. Newell's sums, relative to its first vertex, added products up to 1.4e-18
// that cancel down to components of 1e-28: the normal came out 5.6e-7 off, and the
// triangle's corners up to 9.7e-17 off its own plane, 480 times its width. The sun's lit
// polygon, cast back onto that plane, lay almost wholly beside the face, and the database
// did not read back.
TEST(NewellRegression, TinySliverTriangleFromAnStlFileKeepsItsPlane) {
  const Loop3 sliver{{7.712771084050275e-33, 1.500320291015192e-19, 1.54266521753543e-19},
                     {1.9485136302663304e-19, 1.517254229117801e-19, 8.769040185656443e-33},
                     {2.34101604768e-09, 5.829789984090894e-10, 5.827747173725584e-10}};
  const dvec3 exact(exact_cross_component(sliver, 0), exact_cross_component(sliver, 1),
                    exact_cross_component(sliver, 2));
  // Each component is the exact one rounded once, so within 2^-52 of it (and the oracle's
  // own rounding, as much again).
  const dvec3 newell = newell_vector(sliver);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(newell[axis], exact[axis], 0x1p-51 * std::fabs(exact[axis])) << "axis " << axis;
  }
  // The area is half the vector's length: within a few roundings of the exact one.
  const double exact_area = 0.5 * std::sqrt(glm::dot(exact, exact));
  EXPECT_NEAR(area(Polygon3{sliver, {}}), exact_area, 0x1p-49 * exact_area);
  // Every corner on the plane within the rounding of dot products at the triangle's
  // magnitude, 2.3e-9.
  const Plane3 plane = plane_of({sliver, {}});
  for (const dvec3& v : sliver) {
    EXPECT_LE(std::fabs(plane.signed_distance(v)), 0x1p-48 * sliver[2].x) << v.x;
  }
}

}  // namespace
}  // namespace shadowgen::hsr
