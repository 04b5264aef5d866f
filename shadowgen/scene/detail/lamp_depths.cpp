#include "detail/lamp_depths.h"

#include <cstddef>
#include <string>
#include <vector>

#include "hsr/polygon_distance.h"
#include "numbers.h"
#include "shadowgen/model/coordinate_range.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {

void check_lamp_depths(const Scene& scene) {
  std::vector<hsr::Polygon3> parts;
  std::vector<hsr::Plane3> planes;
  std::vector<std::size_t> face_of;
  for (const Light& light : scene.lights) {
    if (light.type != LightType::kPoint) continue;
    if (parts.empty()) {  // once, for the first point light
      for (std::size_t f = 0; f < scene.faces.size(); ++f) {
        for (const hsr::Polygon3& part : scene.faces[f].parts) {
          parts.push_back(part);
          planes.push_back(hsr::plane_of(part));
          face_of.push_back(f);
        }
      }
    }
    const hsr::DepthSpan depths = hsr::depth_span(light.position, parts, planes);
    if (depths.nearest_polygon >= parts.size()) continue;  // sees nothing
    if (lamp_depths_supported(depths.nearest, depths.farthest)) continue;
    const Face& face = scene.faces[face_of[depths.nearest_polygon]];
    throw InputError(face.source_file, face.id,
                     "light '" + light.id + "' is " + shortest(depths.nearest) +
                         " from this face and " + shortest(depths.farthest) +
                         " from the farthest vertex, a ratio of " +
                         short_number(depths.nearest / depths.farthest, 3) +
                         ": a point light's nearest face must be at least 1.19e-135 of that "
                         "(the supported range of depths)");
  }
}

}  // namespace shadowgen::scene::detail
