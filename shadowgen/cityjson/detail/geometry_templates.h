#pragma once

// A file's "geometry-templates" (CityJSON 2.0 specification, "Geometry templates"):
// "templates", an array of Geometry Objects, and "vertices-templates", the vertices they
// index, in real coordinates as written (the file's transform does not apply to them;
// their rounding follows from the decimals written, vertex_list.h). A CityJSONSeq file
// gives them in its first line.

#include <vector>

#include "detail/geometry.h"
#include "detail/vertex_list.h"
#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

struct GeometryTemplates {
  std::vector<Geometry> templates;
  VertexList vertices;
};

GeometryTemplates read_geometry_templates(const JsonValue& value);

}  // namespace shadowgen::cityjson::detail
