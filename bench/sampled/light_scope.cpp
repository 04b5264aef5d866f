#include "bench/sampled/light_scope.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>

#include "hsr/area.h"
#include "shadowgen/shadows/light_views.h"

namespace shadowgen::bench {

glm::dvec3 towards_light(const Light& light, const glm::dvec3& p) {
  return light.type == LightType::kDirectional ? -light.direction : light.position - p;
}

LightScope light_scope(const Scene& scene, const Light& light) {
  LightScope scope;
  scope.lo = glm::dvec3(std::numeric_limits<double>::infinity());
  scope.hi = -scope.lo;
  for (const Face& face : scene.faces) {
    if (face.parts.size() != 1 || !face.parts[0].holes.empty() || face.parts[0].outer.size() < 3) {
      throw std::invalid_argument("sampled estimators take single convex faces: " + face.id);
    }
    ConvexFace f;
    f.loop = face.parts[0].outer;
    const glm::dvec3 n = glm::cross(f.loop[1] - f.loop[0], f.loop[2] - f.loop[0]);
    f.normal = glm::normalize(n);
    f.area = hsr::area(face.parts[0]);
    const bool present = light.type == LightType::kDirectional || !light.range ||
                         distance_to_polygon(light.position, face.parts[0],
                                             hsr::plane_of(face.parts[0])) <= light.range->end;
    const double facing = light.type == LightType::kDirectional
                              ? -glm::dot(f.normal, light.direction)
                              : glm::dot(f.normal, light.position - f.loop[0]);
    scope.present.push_back(present);
    scope.receives.push_back(present && facing > 0.0);
    if (present) {
      for (const glm::dvec3& v : f.loop) {
        scope.lo = glm::min(scope.lo, v);
        scope.hi = glm::max(scope.hi, v);
      }
    }
    scope.faces.push_back(std::move(f));
  }
  return scope;
}

}  // namespace shadowgen::bench
