#include "shadowgen/output/sun_instants.h"

#include <glm/geometric.hpp>

#include "detail/csv_fields.h"

namespace shadowgen {

std::string sun_instants_csv(const Scene& scene, CsvIds ids) {
  std::string out =
      "light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,"
      "direction_z\n";
  for (const Light& light : scene.lights) {
    if (!light.sun) continue;
    const SunInstant& sun = *light.sun;
    detail::append_csv_field(out, sun.sun_id, ids);
    out += ',';
    detail::append_csv_field(out, light.id, ids);
    out += ',' + sun.time + ',' + std::to_string(sun.step_min);
    // A sun's direction is scaled into [0.5, 1) (Light::direction): its length is near 1.
    const glm::dvec3 unit = glm::normalize(light.direction);
    for (const double value : {sun.azimuth_deg, sun.elevation_deg, unit.x, unit.y, unit.z}) {
      out += ',';
      detail::append_csv_number(out, value);
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
