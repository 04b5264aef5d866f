#pragma once

// A scene's "site" (docs/scene-format.md, "Site and sun path"): `latitude_deg`,
// `longitude_deg` and `utc_offset_h` required, `elevation_m` and `north_axis_deg`
// optional (0). Each must lie in its range (shadowgen/model/site_ranges.h: latitude -90
// to 90, longitude -180 to 180 degrees, the offset -14 to 14 hours, elevation -6,500,000
// to 11,000 m, north axis -360 to 360 degrees); otherwise an InputError naming the
// member's path.

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::detail {

Site read_site(const JsonValue& value);

}  // namespace shadowgen::detail
