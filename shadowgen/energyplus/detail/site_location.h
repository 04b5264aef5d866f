#pragma once

// Site:Location as the scene's site: latitude (north positive), longitude (east positive),
// time zone (hours from UTC, the scene's utc_offset_h) and elevation (m), each within the
// range the IDD gives it (latitude -90 to 90, longitude -180 to 180, time zone -12 to 14,
// elevation -300 to below 8900); blank fields take the IDD's default, 0. The model's +y is
// true north, so north_axis_deg is 0. `from` is "Site:Location '<Name>'". An empty site
// when the file has no Site:Location.

#include <string>
#include <vector>

#include "detail/input_object.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::energyplus::detail {

// InputError naming `file` for a second Site:Location and for a value out of its range.
SourceSite read_site(const std::vector<InputObject>& objects, const std::string& file);

}  // namespace shadowgen::energyplus::detail
