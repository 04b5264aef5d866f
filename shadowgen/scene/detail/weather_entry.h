#pragma once

// A scene's "weather" (docs/scene-format.md, "Weather file"): the name of an EnergyPlus
// weather file, relative to the scene, read whole (shadowgen/weather/epw_reader.h). An
// InputError at the key when the file is not there; the reader's own errors name the
// weather file and its line.

#include <filesystem>

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

Weather read_weather(const JsonValue& value, const std::filesystem::path& scene_path);

// A scene's own site wins over its weather file's LOCATION. One that lies more than 0.1°
// from it in latitude or longitude, or keeps another time zone, draws a warning at
// `site_value`: the two likely disagree by mistake.
void warn_if_site_differs(const Site& site, const JsonValue& site_value, const Weather& weather);

}  // namespace shadowgen::scene::detail
