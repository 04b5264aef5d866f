#include "detail/model_site.h"

#include "shadowgen/geo/projected_site.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen::cityjson::detail {

void derive_site(const std::string& crs, const Bounds& bounds, const std::string& file,
                 SourceModel& model) {
  if (bounds.empty) return;
  const glm::dvec3 middle = 0.5 * (bounds.low + bounds.high);
  try {
    geo::ProjectedSite site = geo::projected_site(crs, middle.x, middle.y);
    model.site = std::move(site.site);
    if (!site.caution.empty()) {
      model.warnings.push_back(one_line(file + ": metadata.referenceSystem: " + site.caution +
                                        ": are these real coordinates of that CRS?"));
    }
  } catch (const geo::CrsError& e) {
    model.warnings.push_back(
        one_line(file + ": metadata.referenceSystem: no site from it: " + e.what()));
  }
}

}  // namespace shadowgen::cityjson::detail
