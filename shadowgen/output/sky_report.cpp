#include "shadowgen/output/sky_report.h"

#include "detail/csv_fields.h"

namespace shadowgen {

std::string sky_view_factor_csv(const Scene& scene, const sky::SkyExposure& exposure, CsvIds ids) {
  std::string out = "face_id,area,sky_view_factor,ground_view_factor\n";
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    output::detail::append_csv_field(out, scene.faces[f].id, ids);
    for (const double v :
         {exposure.area[f], sky::sky_view_factor(exposure, f), exposure.ground_view_factor[f]}) {
      out += ',';
      output::detail::append_csv_number(out, v);
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
