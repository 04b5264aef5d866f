#include "detail/coordinate_range.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "numbers.h"

namespace shadowgen::scene::detail {

std::optional<std::string> coordinate_problem(const glm::dvec3& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (std::fabs(p[axis]) > kLargestCoordinate) {
      return "coordinate " + shortest(p[axis]) +
             " is outside the supported range (magnitude at most " +
             short_number(kLargestCoordinate, 3) + ")";
    }
  }
  return std::nullopt;
}

std::optional<std::string> vertex_problem(const hsr::Polygon3& polygon) {
  for (const glm::dvec3& p : polygon.outer) {
    if (std::optional<std::string> problem = coordinate_problem(p)) return problem;
  }
  for (const hsr::Loop3& hole : polygon.holes) {
    for (const glm::dvec3& p : hole) {
      if (std::optional<std::string> problem = coordinate_problem(p)) return problem;
    }
  }
  return std::nullopt;
}

std::optional<std::string> coordinate_problem(const hsr::Polygon3& polygon) {
  if (std::optional<std::string> problem = vertex_problem(polygon)) return problem;
  if (polygon.outer.empty()) return std::nullopt;
  glm::dvec3 lo = polygon.outer.front();
  glm::dvec3 hi = lo;
  auto visit = [&](const hsr::Loop3& loop) {
    for (const glm::dvec3& p : loop) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  visit(polygon.outer);
  for (const hsr::Loop3& hole : polygon.holes) visit(hole);
  const glm::dvec3 size = hi - lo;
  const double extent = std::max({size.x, size.y, size.z});
  if (extent > 0.0 && extent < kSmallestExtent) {
    return "its extent " + short_number(extent, 3) + " is below the supported range (at least " +
           short_number(kSmallestExtent, 3) + " unless all its vertices are one point)";
  }
  return std::nullopt;
}

}  // namespace shadowgen::scene::detail
