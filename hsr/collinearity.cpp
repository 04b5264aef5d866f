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

// What walk_points found, as a count of points: only copies of the first point a, a
// second distinct point b, or a third point that is_third accepted.
enum class Walk { kOnlyA = 1, kAB = 2, kThird = 3 };

// Walks the points, skipping copies of the first, a: the first other point becomes b,
// and each later one p goes to is_third(a, b, p), the walk stopping when it says true.
template <class IsThird>
Walk walk_points(std::span<const glm::dvec3> points, IsThird is_third) {
  const glm::dvec3& a = points[0];
  const glm::dvec3* b = nullptr;
  for (const glm::dvec3& p : points) {
    if (p == a) continue;
    if (b == nullptr) {
      b = &p;
    } else if (is_third(a, *b, p)) {
      return Walk::kThird;
    }
  }
  return b == nullptr ? Walk::kOnlyA : Walk::kAB;
}

}  // namespace

int distinct_points_up_to_3(std::span<const glm::dvec3> points) {
  if (points.empty()) return 0;
  return static_cast<int>(walk_points(
      points, [](const glm::dvec3&, const glm::dvec3& b, const glm::dvec3& p) { return p != b; }));
}

bool all_collinear(std::span<const glm::dvec3> points) {
  if (points.empty()) return true;
  return walk_points(points, [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& p) {
           return !collinear3(a, b, p);
         }) != Walk::kThird;
}

}  // namespace shadowgen::hsr
