#pragma once

// The members of a CityJSON object (CityJSON 2.0 specification, "CityJSON Object")
// that say how to read its city objects: "type" ("CityJSON"), "version" (1.0, 1.1 or 2.0,
// with or without a patch number), "transform", "metadata" (its "referenceSystem"; its
// other members are not looked into), "geometry-templates"; "extensions" and
// "appearance" are known and not looked into. The same object opens a CityJSONSeq file.

#include <optional>
#include <string>

#include "detail/geometry_templates.h"
#include "detail/vertex_list.h"
#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

struct CityJsonHeader {
  std::string version;
  std::optional<VertexTransform> transform;
  std::optional<std::string> crs;  // "EPSG:7415" (reference_system.h)
  std::optional<GeometryTemplates> templates;
};

// Reads those members of `top`; the caller reads "CityObjects" and "vertices" and
// finishes `top`. Fails on another type or version.
CityJsonHeader read_header(JsonObject& top);

}  // namespace shadowgen::cityjson::detail
