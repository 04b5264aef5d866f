#include "hsr/vector_length.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace shadowgen::hsr {
namespace {

// The exponent of v's largest component (v not zero).
int largest_exponent(const glm::dvec3& v) {
  return std::ilogb(std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}));
}

// v · 2^-e, componentwise: std::ldexp scales exactly (but for components that the shift
// takes below the normal range, which then count for nothing beside the largest), even
// where 2^-e itself is not a double (e below -1022).
glm::dvec3 scaled_down(const glm::dvec3& v, int e) {
  return {std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
}

}  // namespace

double stable_length(const glm::dvec3& v) {
  if (v == glm::dvec3(0.0)) return 0.0;
  const int e = largest_exponent(v);
  return std::ldexp(glm::length(scaled_down(v, e)), e);
}

glm::dvec3 stable_normalize(const glm::dvec3& v) {
  if (v == glm::dvec3(0.0)) return v;
  const glm::dvec3 w = scaled_down(v, largest_exponent(v));
  return w / glm::length(w);
}

}  // namespace shadowgen::hsr
