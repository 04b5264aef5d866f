#include "detail/site_entry.h"

#include <optional>
#include <string>
#include <string_view>

namespace shadowgen::detail {
namespace {

double number_within(const JsonValue& value, double low, double high, std::string_view unit) {
  const double number = value.number();
  if (number < low || number > high) {
    value.fail("must lie between " + std::to_string(static_cast<int>(low)) + " and " +
               std::to_string(static_cast<int>(high)) + std::string(unit));
  }
  return number;
}

}  // namespace

Site read_site(const JsonValue& value) {
  JsonObject object = value.object();
  Site site;
  site.latitude_deg = number_within(object.get("latitude_deg"), -90.0, 90.0, " degrees");
  site.longitude_deg = number_within(object.get("longitude_deg"), -180.0, 180.0, " degrees");
  site.utc_offset_h = number_within(object.get("utc_offset_h"), -14.0, 14.0, " hours");
  if (const std::optional<JsonValue> elevation = object.find("elevation_m")) {
    site.elevation_m = elevation->number();
  }
  if (const std::optional<JsonValue> north = object.find("north_axis_deg")) {
    site.north_axis_deg = north->number();
  }
  object.finish();
  return site;
}

}  // namespace shadowgen::detail
