#include "hsr/area.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "hsr/collinearity.h"
#include "hsr/vector_length.h"

namespace shadowgen::hsr {

namespace {

// Half the length of Newell's vector. A loop whose vertices are collinear (decided
// exactly) has area exactly 0, not the rounding noise the sums would leave.
double loop_area(const Loop3& loop) {
  if (loop.size() < 3 || all_collinear(loop)) return 0.0;
  return 0.5 * stable_length(newell_vector(loop));
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
