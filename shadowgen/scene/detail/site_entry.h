#pragma once

// The scene's site (docs/scene-format.md, "The site"), from whoever gives its keys.
//
// A scene's "site" keys are `latitude_deg`, `longitude_deg`, `utc_offset_h`,
// `elevation_m` and `north_axis_deg`. Each must lie in its range
// (shadowgen/model/site_ranges.h: latitude -90 to 90, longitude -180 to 180 degrees, the
// offset -14 to 14 hours, elevation -6,500,000 to 11,000 m, north axis -360 to 360
// degrees); otherwise an InputError naming the member's path.
//
// Each key comes from the first that gives it, in this order: the scene's own "site", then
// the model files of its meshes[] in entry order (EnergyPlus's Site:Location, a CityJSON
// file's coordinate system through PROJ). The weather file's LOCATION gives the whole
// site, as one, and only when none of those gives any of latitude, longitude and the
// offset: its elevation is that of its own place. Latitude, longitude and the offset are
// needed together; elevation and north axis default to 0.

#include <optional>
#include <string>
#include <vector>

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::scene::detail {

// The scene's "site" keys, each optional here, each in its range.
SourceSite read_site_keys(const JsonValue& value);

// One giver of site keys: `file` names it in messages, SourceSite::from says where in it.
struct SiteGiver {
  SourceSite keys;
  std::string file;
  // Gives its keys only to a site no earlier giver placed (the weather file).
  bool whole = false;
};

struct MergedSite {
  std::optional<Site> site;  // when latitude, longitude and the offset are all given
  // When some of those three are given and not all: "missing 'utc_offset_h' (latitude_deg
  // and longitude_deg from EPSG:7415 through PROJ ...; no file gives utc_offset_h)".
  std::string incomplete;
};

// The site the givers make, each key from the first that has it. A model file's value
// out of its range is an InputError naming the file and where the value came from.
MergedSite merge_site(const std::vector<SiteGiver>& givers);

// The keys a weather file's LOCATION gives, as a giver of the whole site.
SiteGiver site_giver_of(const Weather& weather);

}  // namespace shadowgen::scene::detail
