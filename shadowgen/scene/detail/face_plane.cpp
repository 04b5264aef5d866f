#include "face_plane.h"

#include <algorithm>
#include <cmath>

#include "clipper/predicates.h"

namespace shadowgen::scene::detail {

hsr::PlaneChart chart_without_normal(const hsr::Loop3& loop) {
  for (int axis : {2, 0, 1}) {
    const hsr::PlaneChart chart{axis};
    const clipper::Point2 a = chart(loop[0]);
    for (std::size_t i = 1; i < loop.size(); ++i) {
      const clipper::Point2 b = chart(loop[i]);
      if (b == a) continue;
      for (std::size_t j = i + 1; j < loop.size(); ++j) {
        if (clipper::orient2d(a, b, chart(loop[j])) != clipper::Orientation::kCollinear) {
          return chart;
        }
      }
      break;
    }
  }
  return {};
}

Planarity planarity(const hsr::Polygon3& polygon, const glm::dvec3& normal) {
  const glm::dvec3 o = polygon.outer[0];
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& p : polygon.outer) centroid += p - o;
  centroid /= static_cast<double>(polygon.outer.size());
  Planarity result;
  glm::dvec3 lo = o;
  glm::dvec3 hi = o;
  auto visit = [&](const hsr::Loop3& loop) {
    for (const glm::dvec3& p : loop) {
      result.deviation = std::max(result.deviation, std::abs(glm::dot(normal, (p - o) - centroid)));
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  visit(polygon.outer);
  for (const hsr::Loop3& hole : polygon.holes) visit(hole);
  const glm::dvec3 size = hi - lo;
  result.extent = std::max({size.x, size.y, size.z});
  return result;
}

}  // namespace shadowgen::scene::detail
