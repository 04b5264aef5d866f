#include "detail/geometry_templates.h"

namespace shadowgen::cityjson::detail {

GeometryTemplates read_geometry_templates(const JsonValue& value) {
  JsonObject object = value.object();
  GeometryTemplates out;
  out.vertices = read_vertices(object.get("vertices-templates"), nullptr);
  const GeometryVertices vertices{&out.vertices.points,
                                  {out.vertices.points.size(), "vertices-templates has"},
                                  out.vertices.rounding()};
  const JsonArray templates = object.get("templates").array();
  out.templates.reserve(templates.size());
  for (std::size_t i = 0; i < templates.size(); ++i) {
    out.templates.push_back(read_geometry(templates.at(i), vertices, nullptr, true));
  }
  object.finish();
  return out;
}

}  // namespace shadowgen::cityjson::detail
