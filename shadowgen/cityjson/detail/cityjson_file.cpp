#include "detail/cityjson_file.h"

#include "detail/city_objects.h"
#include "detail/cityjson_header.h"
#include "detail/extension_keys.h"
#include "detail/model_site.h"

namespace shadowgen::cityjson::detail {

SourceModel read_cityjson_text(std::string_view text, const std::string& file,
                               const SourceOptions& options) {
  SourceModel model;
  const JsonDocument document(text, {file, options.strict, &model.warnings});
  JsonObject top = document.root().object();
  const CityJsonHeader header = read_header(top);
  const VertexList vertices =
      read_vertices(top.get("vertices"), header.transform ? &*header.transform : nullptr);
  const GeometryVertices geometry_vertices{
      &vertices.points, {vertices.points.size(), "the file has"}, vertices.rounding()};
  CityObjectFaces faces(file, options);
  faces.read(top.get("CityObjects"), geometry_vertices,
             header.templates ? &*header.templates : nullptr, 0);
  finish_allowing_extension_keys(top);
  faces.finish(model.warnings);
  model.faces = std::move(faces.faces());
  if (header.crs) derive_site(*header.crs, faces.bounds(), file, model);
  return model;
}

}  // namespace shadowgen::cityjson::detail
