#include "hsr/area.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "hsr/collinearity.h"

namespace shadowgen::hsr {

namespace {

// Half the length of Newell's vector: the area of a planar loop whatever its orientation
// in space. The sums run relative to the loop's first vertex, so far from the origin the
// products do not cancel. A loop whose vertices are collinear (decided exactly) has area
// exactly 0, not the rounding noise the sums would leave.
double loop_area(const Loop3& loop) {
  const std::size_t n = loop.size();
  if (n < 3 || all_collinear(loop)) return 0.0;
  const glm::dvec3 o = loop[0];
  glm::dvec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 a = loop[i] - o;
    const glm::dvec3 b = loop[(i + 1) % n] - o;
    normal.x += (a.y - b.y) * (a.z + b.z);
    normal.y += (a.z - b.z) * (a.x + b.x);
    normal.z += (a.x - b.x) * (a.y + b.y);
  }
  return 0.5 * glm::length(normal);
}

}  // namespace

double area(const Polygon3& polygon) {
  double a = loop_area(polygon.outer);
  for (const Loop3& hole : polygon.holes) a -= loop_area(hole);
  // Holes lie inside the outer loop, so only rounding can take the difference below 0.
  return std::max(a, 0.0);
}

double area(std::span<const Polygon3> polygons) {
  double sum = 0.0;
  for (const Polygon3& p : polygons) sum += area(p);
  return sum;
}

}  // namespace shadowgen::hsr
