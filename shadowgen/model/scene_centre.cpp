#include "shadowgen/model/scene_centre.h"

#include <glm/common.hpp>
#include <limits>

namespace shadowgen {

glm::dvec3 scene_centre(const Scene& scene) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      for (const glm::dvec3& p : part.outer) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
  }
  return lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
}

}  // namespace shadowgen
