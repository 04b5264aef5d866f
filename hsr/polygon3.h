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
// non-planar loop the normal of the least-squares plane. Zero for fewer than 3 vertices.
//
// Taken as the sum over the fan from the first vertex, Σ (v_i − v_0) × (v_{i+1} − v_0),
// each component of each triangle's vector an exact 2D determinant rounded once
// (clipper::orient2d_value): a triangle's vector is the exact one to 2^-52 per
// component, and an n-gon's within n·2^-53 of the sum of its fan triangles' |components|,
// whatever its size, position or shape. Newell's own sums (y_i − y_j)(z_i + z_j), even
// relative to a vertex, cancel on a thin loop: on a triangle 2.5e-9 long and 2e-19 wide,
// products up to 1.4e-18 summed to components of 1e-28, and the normal came out 5.6e-7 off.
glm::dvec3 newell_vector(const Loop3& loop);

// Newell's method on the outer loop, offset through the loop's centroid: the least-squares
// fit for slightly non-planar input. A loop without area gives a zero normal.
Plane3 plane_of(const Polygon3& polygon);

}  // namespace shadowgen::hsr
