#include "hsr/collinearity.h"

#include "clipper/predicates.h"

namespace shadowgen::hsr {

namespace {

using clipper::Orientation;
using clipper::Point2;

bool collinear3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return clipper::orient2d(Point2{a.x, a.y}, Point2{b.x, b.y}, Point2{c.x, c.y}) ==
             Orientation::kCollinear &&
         clipper::orient2d(Point2{a.y, a.z}, Point2{b.y, b.z}, Point2{c.y, c.z}) ==
             Orientation::kCollinear &&
         clipper::orient2d(Point2{a.z, a.x}, Point2{b.z, b.x}, Point2{c.z, c.x}) ==
             Orientation::kCollinear;
}

}  // namespace

int distinct_points_up_to_3(std::span<const glm::dvec3> points) {
  if (points.empty()) return 0;
  const glm::dvec3& a = points[0];
  const glm::dvec3* b = nullptr;
  for (const glm::dvec3& p : points) {
    if (p == a) continue;
    if (b == nullptr) {
      b = &p;
    } else if (p != *b) {
      return 3;
    }
  }
  return b == nullptr ? 1 : 2;
}

bool all_collinear(std::span<const glm::dvec3> points) {
  if (points.empty()) return true;
  const glm::dvec3& a = points[0];
  const glm::dvec3* b = nullptr;
  for (const glm::dvec3& p : points) {
    if (p == a) continue;
    if (b == nullptr) {
      b = &p;
    } else if (!collinear3(a, *b, p)) {
      return false;
    }
  }
  return true;
}

}  // namespace shadowgen::hsr
