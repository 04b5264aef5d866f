#pragma once

// The site a CityJSON file's CRS gives (docs/cityjson.md, "The site"): at the middle of
// the bounding box of the faces' vertices, in the CRS, through PROJ (shadowgen/geo). A CRS
// that gives none (geographic, unknown to PROJ, axes not east and north) or a middle
// outside its area of use is a warning.

#include <string>

#include "detail/city_objects.h"
#include "shadowgen/model/source_model.h"

namespace shadowgen::cityjson::detail {

// Sets model.site, or appends a warning, for `crs` ("EPSG:7415") at the middle of
// `bounds` (nothing for empty bounds).
void derive_site(const std::string& crs, const Bounds& bounds, const std::string& file,
                 SourceModel& model);

}  // namespace shadowgen::cityjson::detail
