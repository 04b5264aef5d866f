#include "shadowgen/output/energyplus_sky_report.h"

#include <vector>

#include "detail/csv_fields.h"
#include "detail/energyplus_surface_names.h"

namespace shadowgen {

std::string energyplus_sky_csv(const Scene& scene, const sky::EnergyPlusSkyShading& shading) {
  const std::vector<std::string> names = output::detail::energyplus_surface_names(scene);
  std::string out = "surface_name,dif_shdg_ratio_iso_sky,dif_shdg_ratio_horiz";
  out += shading.fine ? ",sky_shading_ratio\n" : "\n";
  for (std::size_t f = 0; f < names.size(); ++f) {
    out += names[f];
    out += ',';
    output::detail::append_csv_number(
        out, sky::shading_ratio(shading.with_iso_sky[f], shading.without_iso_sky[f]));
    out += ',';
    output::detail::append_csv_number(
        out, sky::shading_ratio(shading.with_horizon[f], shading.without_horizon[f]));
    if (shading.fine) {
      out += ',';
      output::detail::append_csv_number(out, sky::fine_shading_ratio(*shading.fine, f));
    }
    out += '\n';
  }
  return out;
}

void require_energyplus_surface_names(const Scene& scene) {
  (void)output::detail::energyplus_surface_names(scene);
}

}  // namespace shadowgen
