#include "detail/weather_entry.h"

#include <cmath>
#include <string>

#include "detail/referenced_file.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/weather/epw_reader.h"

namespace shadowgen::scene::detail {

Weather read_weather(const JsonValue& value, const std::filesystem::path& scene_path) {
  return weather::read_epw(referenced_file(value, scene_path, "weather file"));
}

void warn_if_site_differs(const Site& site, const JsonValue& site_value, const Weather& weather) {
  constexpr double kNearDeg = 0.1;
  const Site& location = weather.site;
  if (std::abs(site.latitude_deg - location.latitude_deg) <= kNearDeg &&
      std::abs(site.longitude_deg - location.longitude_deg) <= kNearDeg &&
      site.utc_offset_h == location.utc_offset_h) {
    return;
  }
  site_value.warn("differs from the LOCATION of weather file '" + weather.file + "' (latitude " +
                  shortest(location.latitude_deg) + ", longitude " +
                  shortest(location.longitude_deg) + ", time zone " +
                  shortest(location.utc_offset_h) + "); the site is used");
}

}  // namespace shadowgen::scene::detail
