#include "detail/site_entry.h"

#include <array>
#include <optional>
#include <string>

#include "shadowgen/model/input_error.h"
#include "shadowgen/model/site_ranges.h"

namespace shadowgen::scene::detail {
namespace {

constexpr const char* kSceneSite = "the scene's site";

double number_within(const JsonValue& value, const NumberRange& range) {
  const double number = value.number();
  if (const std::optional<std::string> problem = range_problem(number, range)) {
    value.fail(*problem);
  }
  return number;
}

struct SiteKey {
  const char* name;
  std::optional<double> SourceSite::*member;
  NumberRange (*range)();
};

const std::array<SiteKey, 5>& site_keys() {
  static const std::array<SiteKey, 5> keys{{
      {"latitude_deg", &SourceSite::latitude_deg, latitude_range},
      {"longitude_deg", &SourceSite::longitude_deg, longitude_range},
      {"utc_offset_h", &SourceSite::utc_offset_h, utc_offset_range},
      {"elevation_m", &SourceSite::elevation_m, elevation_range},
      {"north_axis_deg", &SourceSite::north_axis_deg, north_axis_range},
  }};
  return keys;
}

}  // namespace

SourceSite read_site_keys(const JsonValue& value) {
  JsonObject object = value.object();
  SourceSite keys;
  for (const SiteKey& key : site_keys()) {
    if (const std::optional<JsonValue> member = object.find(key.name)) {
      keys.*key.member = number_within(*member, key.range());
    }
  }
  object.finish();
  keys.from = kSceneSite;
  return keys;
}

MergedSite merge_site(const std::vector<SiteGiver>& givers) {
  SourceSite merged;
  std::array<std::string, 5> from;
  for (const SiteGiver& giver : givers) {
    if (giver.whole && (merged.latitude_deg || merged.longitude_deg || merged.utc_offset_h)) {
      continue;
    }
    for (std::size_t k = 0; k < site_keys().size(); ++k) {
      const SiteKey& key = site_keys()[k];
      const std::optional<double>& given = giver.keys.*key.member;
      if (!given || merged.*key.member) continue;
      if (const std::optional<std::string> problem = range_problem(*given, key.range())) {
        throw InputError(giver.file, "", giver.keys.from + ": " + key.name + ": " + *problem);
      }
      merged.*key.member = given;
      from[k] = giver.keys.from;
    }
  }
  MergedSite result;
  const bool complete = merged.latitude_deg && merged.longitude_deg && merged.utc_offset_h;
  if (complete) {
    result.site =
        Site{*merged.latitude_deg, *merged.longitude_deg, merged.elevation_m.value_or(0.0),
             *merged.utc_offset_h, merged.north_axis_deg.value_or(0.0)};
    return result;
  }
  // Said as the scene's own site would say it when only the scene gives any of the three.
  std::string given, missing;
  bool only_scene = true;
  for (std::size_t k = 0; k < 3; ++k) {
    const SiteKey& key = site_keys()[k];
    if (merged.*key.member) {
      given += std::string(given.empty() ? "" : "; ") + key.name + " from " + from[k];
      only_scene = only_scene && from[k] == kSceneSite;
    } else if (missing.empty()) {
      missing = key.name;
    }
  }
  if (given.empty()) return result;
  result.incomplete = "missing '" + missing + "'";
  if (!only_scene) result.incomplete += " (" + given + "; no file gives " + missing + ")";
  return result;
}

SiteGiver site_giver_of(const Weather& weather) {
  SourceSite keys;
  keys.latitude_deg = weather.site.latitude_deg;
  keys.longitude_deg = weather.site.longitude_deg;
  keys.utc_offset_h = weather.site.utc_offset_h;
  keys.elevation_m = weather.site.elevation_m;
  keys.from = "the weather file's LOCATION";
  return {std::move(keys), weather.file, true};
}

}  // namespace shadowgen::scene::detail
