#pragma once

// The local standard time of a sun path's instant, at which reports over sun paths read a
// weather file.

#include <string>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/sun/civil_time.h"

namespace shadowgen::output::detail {

// The time of `light`, an instant of `path`; InputError naming `weather_file` where the
// light has none.
sun::CivilTime instant_time(const Light& light, const SunPathHours& path,
                            const std::string& weather_file);

}  // namespace shadowgen::output::detail
