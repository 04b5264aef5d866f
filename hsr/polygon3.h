#pragma once

// Planar 3D polygons with holes: what hidden-surface removal takes in.

#include <glm/vec3.hpp>
#include <vector>

namespace shadowgen::hsr {

using Loop3 = std::vector<glm::dvec3>;

struct Polygon3 {
  Loop3 outer;
  std::vector<Loop3> holes;
};

// The plane normal · p = offset, normal of unit length, oriented by the right-hand rule
// on the outer loop (counter-clockwise seen from the side the normal points to).
struct Plane3 {
  glm::dvec3 normal{0.0, 0.0, 1.0};
  double offset = 0.0;

  double signed_distance(const glm::dvec3& p) const;
};

// Newell's vector of a loop: twice its vector area, normal to its plane by the right-hand
// rule, of length twice its area, whatever the plane's orientation; for a slightly
// non-planar loop the normal of the least-squares plane. The sums run relative to the
// loop's first vertex, so far from the origin the products do not cancel. Zero for fewer
// than 3 vertices.
glm::dvec3 newell_vector(const Loop3& loop);

// Newell's method on the outer loop, offset through the loop's centroid: the least-squares
// fit for slightly non-planar input. A loop without area gives a zero normal.
Plane3 plane_of(const Polygon3& polygon);

}  // namespace shadowgen::hsr
