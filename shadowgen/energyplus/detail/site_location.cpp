#include "detail/site_location.h"

#include <optional>

#include "detail/object_fields.h"
#include "shadowgen/model/number_range.h"

namespace shadowgen::energyplus::detail {
namespace {

double within(const ObjectFields& site, std::string_view key, const NumberRange& range) {
  const double value = site.number(key, 0.0);
  if (const std::optional<std::string> problem = range_problem(value, range)) {
    site.fail(key, *problem);
  }
  return value;
}

}  // namespace

SourceSite read_site(const std::vector<InputObject>& objects, const std::string& file) {
  SourceSite out;
  for (const InputObject& object : objects) {
    if (object.spec->kind != ObjectKind::kSiteLocation) continue;
    const ObjectFields site(object, file);
    if (!out.from.empty()) site.fail("a second Site:Location object: EnergyPlus allows one");
    out.latitude_deg = within(site, "latitude", {.low = -90.0, .high = 90.0, .unit = " degrees"});
    out.longitude_deg =
        within(site, "longitude", {.low = -180.0, .high = 180.0, .unit = " degrees"});
    out.utc_offset_h = within(site, "time_zone", {.low = -12.0, .high = 14.0, .unit = " hours"});
    out.elevation_m = within(site, "elevation",
                             {.low = -300.0, .high = 8900.0, .high_excluded = true, .unit = " m"});
    out.north_axis_deg = 0.0;
    out.from = "Site:Location '" + object.name + "'";
  }
  return out;
}

}  // namespace shadowgen::energyplus::detail
