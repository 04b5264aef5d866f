#include "hsr/polygon3.h"

#include <glm/geometric.hpp>

#include "clipper/predicates.h"
#include "hsr/vector_length.h"

namespace shadowgen::hsr {

double Plane3::signed_distance(const glm::dvec3& p) const { return glm::dot(normal, p) - offset; }

namespace {

// (b − a) × (c − a), each component the 2D determinant of one coordinate projection,
// (y, z), (z, x) and (x, y), taken exactly and rounded once (clipper::orient2d_value):
// relative error below 2^-52.
glm::dvec3 exact_cross(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  using clipper::Point2;
  return {clipper::orient2d_value(Point2{a.y, a.z}, Point2{b.y, b.z}, Point2{c.y, c.z}),
          clipper::orient2d_value(Point2{a.z, a.x}, Point2{b.z, b.x}, Point2{c.z, c.x}),
          clipper::orient2d_value(Point2{a.x, a.y}, Point2{b.x, b.y}, Point2{c.x, c.y})};
}

}  // namespace

glm::dvec3 newell_vector(const Loop3& loop) {
  glm::dvec3 normal(0.0);
  for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
    normal += exact_cross(loop[0], loop[i], loop[i + 1]);
  }
  return normal;
}

Plane3 plane_of(const Polygon3& polygon) {
  const Loop3& loop = polygon.outer;
  Plane3 plane;
  const glm::dvec3 normal = newell_vector(loop);
  const double length = stable_length(normal);
  if (!(length > 0.0)) {
    plane.normal = glm::dvec3(0.0);
    return plane;
  }
  // The centroid relative to the first vertex too.
  const glm::dvec3 o = loop[0];
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& p : loop) centroid += p - o;
  plane.normal = normal / length;
  centroid = o + centroid / static_cast<double>(loop.size());
  plane.offset = glm::dot(plane.normal, centroid);
  return plane;
}

}  // namespace shadowgen::hsr
