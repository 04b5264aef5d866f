#include "shadowgen/shadows/light_views.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "hsr/polygon_distance.h"
#include "shadowgen/model/coordinate_range.h"

namespace shadowgen {

std::vector<hsr::View> light_views(const Light& light, std::span<const hsr::Polygon3> polygons,
                                   std::span<const hsr::Plane3> planes, const glm::dvec3& centre) {
  if (light.type == LightType::kDirectional) {
    return {hsr::View::orthographic(light.direction, centre)};
  }
  const glm::dvec3& eye = light.position;
  const hsr::DepthSpan depths = hsr::depth_span(eye, polygons, planes);
  if (!std::isfinite(depths.nearest)) return {};
  // Half the smallest depth any polygon point can have in a frustum, so nothing is cut
  // off: a polygon 1e-12 from the lamp still occludes (a light exactly on a polygon's
  // plane is handled by that polygon being edge-on). Never below 2^-450 of the farthest
  // distance, so that image coordinates keep finite squares: the scene reader refuses a
  // light whose nearest face that floor would cut (shadowgen/model/coordinate_range.h).
  const double near = lamp_near_distance(depths.nearest, depths.farthest);

  static const std::array<glm::dvec3, 6> kAxes = {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
                                                  glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                                  glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
  std::vector<hsr::View> views;
  for (const glm::dvec3& axis : kAxes) {
    const glm::dvec3 up = std::fabs(axis.z) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    hsr::View view = hsr::View::perspective(eye, axis, up, 90.0, near);
    // Keep the frustum when some polygon is not wholly outside one of its five planes.
    const bool sees_something = std::any_of(polygons.begin(), polygons.end(), [&](const auto& p) {
      std::array<bool, 5> all_out{true, true, true, true, true};
      for (const glm::dvec3& v : p.outer) {
        const glm::dvec3 e = view.to_eye_frame(v);
        const double side[5] = {e.z - near, e.z - e.x, e.z + e.x, e.z - e.y, e.z + e.y};
        for (int s = 0; s < 5; ++s) all_out[s] = all_out[s] && side[s] < 0.0;
      }
      return std::none_of(all_out.begin(), all_out.end(), [](bool b) { return b; });
    });
    if (sees_something) views.push_back(view);
  }
  return views;
}

}  // namespace shadowgen
