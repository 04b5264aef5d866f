#pragma once

// A CityJSON file (one CityJSON object) read whole: its header (cityjson_header.h), its
// "vertices" and its "CityObjects" (city_objects.h), the site from its CRS (model_site.h).

#include <string>
#include <string_view>

#include "shadowgen/model/source_model.h"

namespace shadowgen::cityjson::detail {

// `text` is the file's; `file` names it in messages. Throws InputError.
SourceModel read_cityjson_text(std::string_view text, const std::string& file,
                               const SourceOptions& options);

}  // namespace shadowgen::cityjson::detail
