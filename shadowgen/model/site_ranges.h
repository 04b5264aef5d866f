#pragma once

// The ranges of a site's values (Site, shadowgen/model/scene.h; docs/scene-format.md,
// "The site"), where the sun's position is computed (shadowgen/sun/sun_position.h):
//
// - latitude -90 to 90 and longitude -180 to 180 degrees: NREL SPA's stated ranges (Reda
//   and Andreas 2008; spa.h);
// - UTC offset -14 to 14 hours: the world's time zones, UTC-12 to UTC+14, within SPA's
//   -18 to 18;
// - elevation -6,500,000 to 11,000 m: from SPA's stated lower bound to the top of the
//   troposphere of the standard atmosphere (ISO 2533). Refraction is Saemundsson's for an
//   observer under the air of a standard atmosphere (1010 hPa, 10 °C); above the
//   troposphere most of that air lies below the observer, and the topocentric parallax of
//   ever higher sites, not refraction, takes the sun wherever it likes (at 1e300 m,
//   89.99997° up);
// - north axis -360 to 360 degrees: SPA's range for its azimuth rotation; a turn either
//   way, so that an angle beyond is a mistake, not a direction.
//
// A weather file's LOCATION keeps its own, narrower ranges where EnergyPlus states them
// (shadowgen/weather/epw_reader.h).

#include "shadowgen/model/number_range.h"

namespace shadowgen {

NumberRange latitude_range();
NumberRange longitude_range();
NumberRange utc_offset_range();
NumberRange elevation_range();
NumberRange north_axis_range();

}  // namespace shadowgen
