#include "detail/site_entry.h"

#include <optional>
#include <string>

#include "shadowgen/model/site_ranges.h"

namespace shadowgen::detail {
namespace {

double number_within(const JsonValue& value, const NumberRange& range) {
  const double number = value.number();
  if (const std::optional<std::string> problem = range_problem(number, range)) {
    value.fail(*problem);
  }
  return number;
}

}  // namespace

Site read_site(const JsonValue& value) {
  JsonObject object = value.object();
  Site site;
  site.latitude_deg = number_within(object.get("latitude_deg"), latitude_range());
  site.longitude_deg = number_within(object.get("longitude_deg"), longitude_range());
  site.utc_offset_h = number_within(object.get("utc_offset_h"), utc_offset_range());
  if (const std::optional<JsonValue> elevation = object.find("elevation_m")) {
    site.elevation_m = number_within(*elevation, elevation_range());
  }
  if (const std::optional<JsonValue> north = object.find("north_axis_deg")) {
    site.north_axis_deg = number_within(*north, north_axis_range());
  }
  object.finish();
  return site;
}

}  // namespace shadowgen::detail
