#pragma once

// A face's plane while the face is built (face_builder.h): a chart for a loop without a
// normal, orthonormal coordinates on a plane, and how far a face's vertices lie from its
// best-fit plane.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "clipper/polygon.h"
#include "hsr/plane_chart.h"
#include "hsr/polygon3.h"

namespace shadowgen::scene::detail {

// A chart for a loop whose Newell normal came out zero (its signed areas cancel, as in a
// figure-eight, or underflow): any chart in which it is not collinear; validation then
// finds what is wrong with it.
hsr::PlaneChart chart_without_normal(const hsr::Loop3& loop);

// Orthonormal coordinates on the plane through `origin` with unit normal n, oriented so
// that a loop counter-clockwise seen from the side n points to stays counter-clockwise.
// The coordinates are rounded (a construction, unlike a chart).
class PlaneFrame {
 public:
  PlaneFrame(const glm::dvec3& origin, const glm::dvec3& n) : origin_(origin) {
    const glm::dvec3 a = glm::abs(n);
    const glm::dvec3 axis = a.x <= a.y && a.x <= a.z ? glm::dvec3(1, 0, 0)
                            : a.y <= a.z             ? glm::dvec3(0, 1, 0)
                                                     : glm::dvec3(0, 0, 1);
    u_ = glm::normalize(glm::cross(n, axis));
    v_ = glm::cross(n, u_);
  }

  clipper::Loop2 project(const hsr::Loop3& loop) const {
    clipper::Loop2 out;
    out.reserve(loop.size());
    for (const glm::dvec3& p : loop) {
      const glm::dvec3 d = p - origin_;
      out.push_back({glm::dot(d, u_), glm::dot(d, v_)});
    }
    return out;
  }

  // The point of the plane at frame coordinates q.
  glm::dvec3 lift(const clipper::Point2& q) const { return origin_ + q.x * u_ + q.y * v_; }

 private:
  glm::dvec3 origin_, u_, v_;
};

// How far a face is from planar.
struct Planarity {
  double deviation = 0.0;  // largest distance of a vertex from the best-fit plane
  double extent = 0.0;     // largest side of the bounding box
};

// Distances are taken relative to the outer loop's first vertex, so a face far from the
// origin is measured as precisely as one at it.
Planarity planarity(const hsr::Polygon3& polygon, const glm::dvec3& normal);

}  // namespace shadowgen::scene::detail
