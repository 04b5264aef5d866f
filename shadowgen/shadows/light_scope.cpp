#include "shadowgen/shadows/light_scope.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "detail/face_parts.h"
#include "hsr/polygon_distance.h"
#include "shadowgen/shadows/light_views.h"

namespace shadowgen {

ScenePartPlanes::ScenePartPlanes(const Scene& scene) {
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      polygons.push_back(part);
      planes.push_back(hsr::plane_of(part));
    }
    first.push_back(polygons.size());
  }
}

std::vector<PartRole> part_roles(std::span<const hsr::Polygon3> polygons,
                                 std::span<const hsr::Plane3> planes, const Light& light) {
  const std::size_t n = polygons.size();
  // A segment from the light to a receiver's point is no longer than the receiver's
  // farthest vertex from it: a part nearer than that farthest distance over all receivers
  // may occlude, one beyond it cannot.
  const bool ranged = light.type == LightType::kPoint && light.range.has_value();
  std::vector<double> distance(ranged ? n : 0);
  double reach = 0.0;  // the farthest receiver vertex from the light
  for (std::size_t i = 0; ranged && i < n; ++i) {
    distance[i] = hsr::distance_to_polygon(light.position, polygons[i], planes[i]);
    if (distance[i] > light.range->end) continue;
    for (const glm::dvec3& v : polygons[i].outer) {
      reach = std::max(reach, glm::length(v - light.position));
    }
  }
  std::vector<PartRole> roles(n, PartRole::kFacing);
  for (std::size_t i = 0; i < n; ++i) {
    if (ranged && distance[i] > light.range->end) {
      roles[i] = distance[i] <= reach ? PartRole::kOccluder : PartRole::kLeftOut;
    } else if (!shadows::detail::faces_light(planes[i], light)) {
      roles[i] = PartRole::kTurnedAway;
    }
  }
  return roles;
}

}  // namespace shadowgen
