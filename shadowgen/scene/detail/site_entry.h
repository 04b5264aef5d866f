#pragma once

// A scene's "site" (docs/scene-format.md, "Site and sun path"): `latitude_deg`,
// `longitude_deg` and `utc_offset_h` required, `elevation_m` and `north_axis_deg`
// optional (0). Each must be finite; latitude within [-90, 90], longitude within
// [-180, 180], the offset within [-14, 14] hours (the world's time zones, UTC-12 to
// UTC+14); otherwise an InputError naming the member's path.

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::detail {

Site read_site(const JsonValue& value);

}  // namespace shadowgen::detail
