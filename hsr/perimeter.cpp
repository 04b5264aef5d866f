#include "hsr/perimeter.h"

#include <cstddef>

#include "hsr/vector_length.h"

namespace shadowgen::hsr {

double perimeter(const Loop3& loop) {
  double sum = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    sum += stable_length(loop[(i + 1) % loop.size()] - loop[i]);
  }
  return sum;
}

double perimeter(const Polygon3& polygon) {
  double sum = perimeter(polygon.outer);
  for (const Loop3& hole : polygon.holes) sum += perimeter(hole);
  return sum;
}

}  // namespace shadowgen::hsr
