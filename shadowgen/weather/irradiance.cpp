#include "shadowgen/weather/irradiance.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "detail/hour_text.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::weather {
namespace {

std::tuple<int, int, int> key(const WeatherHour& hour) { return {hour.month, hour.day, hour.hour}; }

}  // namespace

const WeatherHour* weather_hour_at(const Weather& weather,
                                   const sun::CivilTime& local_standard_time) {
  const std::vector<WeatherHour>& hours = weather.hours;
  if (hours.empty()) return nullptr;
  const sun::CivilTime& t = local_standard_time;
  const std::tuple<int, int, int> wanted{t.month, t.day, t.hour + 1};
  // The rows run hour by hour over a year at most (epw_reader.h): in order, but for one
  // turn of the year at most, after which every row comes before the first in the year.
  const auto first = key(hours.front());
  const auto turn = std::partition_point(
      hours.begin(), hours.end(), [&](const WeatherHour& hour) { return key(hour) >= first; });
  const auto begin = wanted >= first ? hours.begin() : turn;
  const auto end = wanted >= first ? turn : hours.end();
  const auto found = std::lower_bound(
      begin, end, wanted, [](const WeatherHour& hour, const auto& k) { return key(hour) < k; });
  return found != end && key(*found) == wanted ? &*found : nullptr;
}

const WeatherHour& weather_hour_needed(const Weather& weather,
                                       const sun::CivilTime& local_standard_time) {
  const WeatherHour* hour = weather_hour_at(weather, local_standard_time);
  if (hour == nullptr) {
    const sun::CivilTime& t = local_standard_time;
    throw InputError(weather.file, "",
                     "no " + detail::hour_text(t.month, t.day, t.hour + 1) + " for " +
                         sun::civil_text(t) + " (local standard time; the year is not matched)");
  }
  return *hour;
}

double radiation_wh_m2(const Weather& weather, const sun::CivilTime& local_standard_time,
                       Radiation which) {
  const WeatherHour& hour = weather_hour_needed(weather, local_standard_time);
  const auto& [value, what] = [&]() -> std::pair<const std::optional<double>&, const char*> {
    switch (which) {
      case Radiation::kGlobalHorizontal:
        return {hour.global_horizontal_wh_m2, "global horizontal radiation"};
      case Radiation::kDiffuseHorizontal:
        return {hour.diffuse_horizontal_wh_m2, "diffuse horizontal radiation"};
      case Radiation::kDirectNormal:
        break;
    }
    return {hour.direct_normal_wh_m2, "direct normal radiation"};
  }();
  if (!value) {
    throw InputError(weather.file, "",
                     "line " + std::to_string(hour.line) + ": the " + what + " of " +
                         detail::hour_text(hour) +
                         " is marked missing (9999 or more, or negative), and " +
                         sun::civil_text(local_standard_time) + " needs it");
  }
  return *value;
}

double direct_normal_wh_m2(const Weather& weather, const sun::CivilTime& local_standard_time) {
  return radiation_wh_m2(weather, local_standard_time, Radiation::kDirectNormal);
}

}  // namespace shadowgen::weather
