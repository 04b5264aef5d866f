#include "shadowgen/output/sun_instants.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "detail/csv_fields.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen {

std::string sun_instants_csv(const Scene& scene, CsvIds ids) {
  // A path with no instant (a polar night) is a sun light all the same: its table is empty.
  const bool suns = !scene.sun_paths.empty() ||
                    std::any_of(scene.lights.begin(), scene.lights.end(),
                                [](const Light& light) { return light.sun.has_value(); });
  if (!suns) {
    throw InputError(scene.file, "",
                     "has no sun lights (a light of type \"sun\", at a time or from, to and "
                     "step_min) to list the instants of");
  }
  std::string out =
      "light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,"
      "direction_z\n";
  for (const Light& light : scene.lights) {
    if (!light.sun) continue;
    const SunInstant& sun = *light.sun;
    output::detail::append_csv_field(out, sun.sun_id, ids);
    out += ',';
    output::detail::append_csv_field(out, light.id, ids);
    out += ',' + sun.time + ',' + std::to_string(sun.step_min);
    // A sun's direction is scaled into [0.5, 1) (Light::direction): its length is near 1.
    const glm::dvec3 unit = glm::normalize(light.direction);
    for (const double value : {sun.azimuth_deg, sun.elevation_deg, unit.x, unit.y, unit.z}) {
      out += ',';
      output::detail::append_csv_number(out, value);
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
