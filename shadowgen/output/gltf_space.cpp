#include "shadowgen/output/gltf_space.h"

#include <cmath>

namespace shadowgen {

glm::dvec3 gltf_axes(const glm::dvec3& p) { return {p.x, p.z, -p.y}; }

double linear_from_srgb(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace shadowgen
