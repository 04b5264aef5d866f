#pragma once

// CityJSON lets Extensions add members anywhere, named with a leading "+" (CityJSON 2.0
// specification, "Extensions": "+census" at the root, "+colour" on a city object):
// they are not unknown keys.

#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

// JsonObject::finish(), the keys starting with "+" counted as known.
void finish_allowing_extension_keys(JsonObject& object);

}  // namespace shadowgen::cityjson::detail
