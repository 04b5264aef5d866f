#include "detail/sun_light.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>

#include "shadowgen/model/number_text.h"
#include "shadowgen/sun/civil_time.h"
#include "shadowgen/sun/sun_position.h"

namespace shadowgen::scene::detail {
namespace {

// The solar position algorithm's range (shadowgen/sun/sun_position.h); the format's four
// digits already keep a year from 0.
constexpr int kLastYear = 6000;

sun::CivilTime read_time(const JsonValue& value) {
  const std::string text = value.string();
  const std::optional<sun::CivilTime> time = sun::parse_civil_time(text);
  if (!time) {
    value.fail("'" + text + "' is not a time 'YYYY-MM-DDTHH:MM' (seconds ':SS' optional)");
  }
  if (time->year > kLastYear) {
    value.fail("'" + text + "' is beyond the year " + std::to_string(kLastYear) +
               ", where the solar position algorithm ends");
  }
  return *time;
}

int read_step_min(const JsonValue& value) {
  const double step = value.number();
  if (!(step >= 1.0) || step != std::floor(step) || step > 1e9) {
    value.fail("must be a positive whole number of minutes, not " + shortest(step));
  }
  return static_cast<int>(step);
}

double radians(double degrees) { return degrees * (std::numbers::pi / 180.0); }

// The sun's place at a local standard time at the site.
sun::SunPosition sun_at(const Site& site, const sun::CivilTime& local) {
  const auto offset_s = static_cast<std::int64_t>(std::llround(site.utc_offset_h * 3600.0));
  const sun::CivilTime utc = sun::civil_time_at(sun::seconds_since_1970(local) - offset_s);
  const double year = utc.year + (utc.month - 0.5) / 12.0;
  return sun::sun_position({site.latitude_deg, site.longitude_deg, site.elevation_m},
                           sun::julian_day(utc), sun::delta_t_estimate(year));
}

// The way sunlight travels in scene axes: azimuths turn by north_axis_deg from true north
// to the scene's +y.
glm::dvec3 travel_direction(const Site& site, const sun::SunPosition& p) {
  const double azimuth = radians(p.azimuth_deg - site.north_axis_deg);
  const double elevation = radians(p.elevation_deg);
  const glm::dvec3 toward_sun{std::cos(elevation) * std::sin(azimuth),
                              std::cos(elevation) * std::cos(azimuth), std::sin(elevation)};
  return power_of_two_scaled(-toward_sun);
}

Light instant_light(std::string id, SunInstant instant, const Site& site,
                    const sun::SunPosition& p) {
  Light light;
  light.id = std::move(id);
  light.type = LightType::kDirectional;
  light.direction = travel_direction(site, p);
  instant.azimuth_deg = p.azimuth_deg;
  instant.elevation_deg = p.elevation_deg;
  light.sun = std::move(instant);
  return light;
}

class SunEntry {
 public:
  SunEntry(JsonObject& entry, IdRegistry& ids, const Site& site, std::string id)
      : entry_(entry), ids_(ids), site_(site), id_(std::move(id)) {}

  std::vector<Light> single(const JsonValue& time_value) {
    const sun::CivilTime time = read_time(time_value);
    const sun::SunPosition p = sun_at(site_, time);
    if (!(p.elevation_deg > 0.0)) {
      time_value.fail("the sun is below the horizon at " + sun::civil_text(time) +
                      " (apparent elevation " +
                      number_text(p.elevation_deg, std::chars_format::fixed, 2) + " degrees)");
    }
    return {instant_light(id_, {id_, sun::civil_text(time), 0}, site_, p)};
  }

  std::vector<Light> path(std::optional<SunPathSpan>& span) {
    const JsonValue from_value = entry_.get("from");
    const JsonValue to_value = entry_.get("to");
    const JsonValue step_value = entry_.get("step_min");
    const sun::CivilTime from = read_time(from_value);
    const sun::CivilTime to = read_time(to_value);
    const int step_min = read_step_min(step_value);
    const std::int64_t first = sun::seconds_since_1970(from);
    const std::int64_t last = sun::seconds_since_1970(to);
    if (last < first) {
      to_value.fail("must not be before 'from' (" + sun::civil_text(from) + ")");
    }
    const std::int64_t step_s = std::int64_t{step_min} * 60;
    const std::int64_t count = (last - first) / step_s + 1;
    if (count > static_cast<std::int64_t>(kMaxSunInstants)) {
      step_value.fail("the path has " + std::to_string(count) + " instants, more than the " +
                      std::to_string(kMaxSunInstants) + " a sun path may have");
    }
    span = SunPathSpan{id_, step_min, sun::civil_text(from), sun::civil_text(to)};
    std::vector<Light> lights;
    for (std::int64_t k = 0; k < count; ++k) {
      const sun::CivilTime time = sun::civil_time_at(first + k * step_s);
      const sun::SunPosition p = sun_at(site_, time);
      if (!(p.elevation_deg > 0.0)) continue;
      std::string id = id_ + "@" + sun::minute_text(time);
      ids_.claim(id, "an instant of sun path '" + id_ + "'", entry_.get("id"));
      SunInstant instant{id_, sun::civil_text(time), step_min};
      instant.path_from = sun::civil_text(from);
      instant.path_to = sun::civil_text(to);
      lights.push_back(instant_light(std::move(id), std::move(instant), site_, p));
    }
    if (lights.empty()) {
      entry_.value().warn("the sun is below the horizon at every instant of the path");
    }
    return lights;
  }

 private:
  JsonObject& entry_;
  IdRegistry& ids_;
  const Site& site_;
  const std::string id_;
};

}  // namespace

bool is_sun_light(const JsonValue& value) {
  if (!value.is_object()) return false;
  JsonObject entry = value.object();
  const std::optional<JsonValue> type = entry.find("type");
  // Anything else, a `type` that is not a string included, is read_light's to report.
  return type && type->describe() == "a string" && type->string() == "sun";
}

SunEntryRead read_sun_light(const JsonValue& value, IdRegistry& ids,
                            const std::optional<Site>& site, const std::string& site_incomplete) {
  JsonObject entry = value.object();
  std::string id = read_claimed_id(entry, ids, "light");
  (void)entry.get("type");
  if (!site && !site_incomplete.empty()) {
    entry.value().fail("a sun light needs the site, and its keys are incomplete: " +
                       site_incomplete + "; give the rest in the scene's \"site\"");
  }
  if (!site) {
    entry.value().fail(
        "a sun light needs the scene's \"site\" (latitude_deg, longitude_deg, utc_offset_h) "
        "or a \"weather\" file, and it has neither");
  }
  const std::optional<JsonValue> time = entry.find("time");
  const bool has_path = entry.has("from") || entry.has("to") || entry.has("step_min");
  if (time && has_path) {
    entry.value().fail("give either 'time' or 'from', 'to' and 'step_min', not both");
  }
  if (!time && !has_path) {
    entry.value().fail("a sun light needs 'time', or 'from', 'to' and 'step_min'");
  }
  SunEntry sun(entry, ids, *site, std::move(id));
  SunEntryRead read;
  read.lights = time ? sun.single(*time) : sun.path(read.path);
  entry.finish();
  return read;
}

}  // namespace shadowgen::scene::detail
