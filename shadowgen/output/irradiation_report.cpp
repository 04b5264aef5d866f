#include "shadowgen/output/irradiation_report.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "detail/csv_fields.h"
#include "detail/instant_time.h"
#include "detail/sun_paths_required.h"
#include "hsr/area.h"
#include "hsr/polygon3.h"
#include "shadowgen/sun/civil_time.h"
#include "shadowgen/weather/irradiance.h"

namespace shadowgen {
namespace {

// The direct normal radiation at each instant of `path`, read once for all faces.
std::vector<double> direct_normal_of(const ShadowedScene& shadowed, const SunPathHours& path,
                                     const Weather& weather) {
  std::vector<double> dni;
  dni.reserve(path.instants.size());
  for (const std::size_t l : path.instants) {
    const sun::CivilTime time =
        output::detail::instant_time(shadowed.scene().lights.at(l), path, weather.file);
    dni.push_back(weather::direct_normal_wh_m2(weather, time));
  }
  return dni;
}

// Per part of `face`, its unit front normal and its area.
struct PartFacing {
  glm::dvec3 normal{0.0};
  double area = 0.0;
};

std::vector<PartFacing> facings_of(const Face& face) {
  std::vector<PartFacing> out;
  for (const hsr::Polygon3& part : face.parts) {
    const glm::dvec3 n = hsr::newell_vector(part.outer);
    const double length = glm::length(n);
    out.push_back({length > 0.0 ? n / length : glm::dvec3(0.0), hsr::area(part)});
  }
  return out;
}

}  // namespace

std::vector<IrradiationRow> irradiation_rows(const ShadowedScene& shadowed,
                                             const Weather& weather) {
  output::detail::require_sun_paths(shadowed, "irradiation");
  const Scene& scene = shadowed.scene();
  std::vector<IrradiationRow> rows(scene.faces.size() * shadowed.sun_paths.size());
  std::vector<std::vector<PartFacing>> facings_per_face;  // the same for every path
  facings_per_face.reserve(scene.faces.size());
  for (const Face& face : scene.faces) facings_per_face.push_back(facings_of(face));
  for (std::size_t p = 0; p < shadowed.sun_paths.size(); ++p) {
    const SunPathHours& path = shadowed.sun_paths[p];
    const std::vector<double> dni = direct_normal_of(shadowed, path, weather);
    const double hours_per_instant = path.step_min / 60.0;
    std::vector<glm::dvec3> to_sun;
    for (const std::size_t l : path.instants) {
      to_sun.push_back(-glm::normalize(scene.lights[l].direction));
    }
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      IrradiationRow& row = rows[f * shadowed.sun_paths.size() + p];
      row.face = f;
      row.path = p;
      const std::vector<PartFacing>& facings = facings_per_face[f];
      for (const PartFacing& facing : facings) row.area += facing.area;
      for (std::size_t k = 0; k < path.instants.size(); ++k) {
        const double energy_per_area = dni[k] * hours_per_instant;
        for (std::size_t i = 0; i < facings.size(); ++i) {
          const double cosine = std::max(0.0, glm::dot(facings[i].normal, to_sun[k]));
          row.direct_wh += energy_per_area * cosine * part_lit_area(path, f, i, k);
          row.unshaded_wh += energy_per_area * cosine * facings[i].area;
        }
      }
      // The lit areas are the parts' own up to the clipper's rounding of crossings.
      row.direct_wh = std::min(row.direct_wh, row.unshaded_wh);
    }
  }
  return rows;
}

std::string irradiation_csv(const ShadowedScene& shadowed, const Weather& weather, CsvIds ids) {
  const std::vector<IrradiationRow> rows = irradiation_rows(shadowed, weather);
  std::string out =
      "face_id,sun_path,area,direct_wh,direct_wh_per_area,unshaded_direct_wh_per_area\n";
  for (const IrradiationRow& row : rows) {
    output::detail::append_csv_field(out, shadowed.scene().faces[row.face].id, ids);
    out += ',';
    output::detail::append_csv_field(out, shadowed.sun_paths[row.path].id, ids);
    const double per_area = row.area > 0.0 ? row.direct_wh / row.area : 0.0;
    const double unshaded_per_area = row.area > 0.0 ? row.unshaded_wh / row.area : 0.0;
    for (const double v : {row.area, row.direct_wh, per_area, unshaded_per_area}) {
      out += ',';
      output::detail::append_csv_number(out, v);
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
