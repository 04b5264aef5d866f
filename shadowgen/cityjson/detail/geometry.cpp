#include "detail/geometry.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "detail/geometry_templates.h"

namespace shadowgen::cityjson::detail {
namespace {

struct Semantics {
  std::vector<std::string> types;
  std::optional<JsonValue> values;
};

// "semantics": {"surfaces": [{"type": ...}, ...], "values": ...}. A semantic surface may
// carry any attributes besides its "type" (and "parent", "children"), so its other keys
// draw no warning.
Semantics read_semantics(const JsonValue& value) {
  JsonObject object = value.object();
  Semantics out;
  const JsonArray surfaces = object.get("surfaces").array();
  out.types.reserve(surfaces.size());
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    JsonObject surface = surfaces.at(i).object();
    out.types.push_back(surface.get("type").string());
  }
  out.values = object.get("values");
  object.finish();
  return out;
}

// "transformationMatrix" and the reference point as a placement of template `index`.
TemplatePlacement read_placement(JsonObject& object, const GeometryVertices& vertices,
                                 const GeometryTemplates& templates) {
  TemplatePlacement out;
  const JsonValue template_value = object.get("template");
  out.template_index = template_value.index();
  if (out.template_index >= templates.templates.size()) {
    template_value.fail("template index " + std::to_string(out.template_index) +
                        " is out of range: geometry-templates has " +
                        std::to_string(templates.templates.size()) + " templates");
  }
  const JsonValue boundaries = object.get("boundaries");
  if (!boundaries.is_array() || boundaries.array().size() != 1) {
    boundaries.fail(
        "a GeometryInstance's boundaries are one vertex index (its reference point) in an "
        "array");
  }
  const JsonValue reference_value = boundaries.array().at(0);
  const std::size_t reference = reference_value.index();
  if (reference >= vertices.range.count) {
    reference_value.fail("vertex index " + std::to_string(reference) +
                         " is out of range: " + vertices.range.owner + " " +
                         std::to_string(vertices.range.count) + " vertices");
  }
  const JsonValue matrix_value = object.get("transformationMatrix");
  if (!matrix_value.is_array() || matrix_value.array().size() != 16) {
    matrix_value.fail("expected 16 numbers (a 4 x 4 matrix, row by row), found " +
                      (matrix_value.is_array()
                           ? std::to_string(matrix_value.array().size()) + " values"
                           : matrix_value.describe()));
  }
  const JsonArray matrix = matrix_value.array();
  double m[4][4];
  for (std::size_t i = 0; i < 16; ++i) m[i / 4][i % 4] = matrix.at(i).number();
  if (m[3][0] != 0.0 || m[3][1] != 0.0 || m[3][2] != 0.0 || m[3][3] != 1.0) {
    matrix_value.fail("the last row must be 0, 0, 0, 1: a template is placed by an affine map");
  }
  // A template vertex off by at most h_j on axis j moves, placed, by at most
  // Σ_j |m_ij| h_j on axis i.
  const glm::dvec3 h = templates.vertices.half_step;
  glm::dvec3 placed_half_step(0.0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      out.linear[c][r] = m[r][c];  // glm is column-major: linear[column][row]
      placed_half_step[r] += std::abs(m[r][c]) * h[c];
    }
  }
  out.offset = glm::dvec3(m[0][3], m[1][3], m[2][3]) + (*vertices.points)[reference];
  out.rounding = vertices.rounding + glm::length(placed_half_step);
  return out;
}

}  // namespace

Geometry read_geometry(const JsonValue& value, const GeometryVertices& vertices,
                       const GeometryTemplates* templates, bool in_template) {
  JsonObject object = value.object();
  Geometry out;
  const JsonValue type_value = object.get("type");
  const std::string type_name = type_value.string();
  const std::optional<GeometryType> type = geometry_type(type_name);
  if (!type) {
    type_value.fail("unknown geometry type '" + type_name + "' (CityJSON's are " +
                    geometry_type_names() + ")");
  }
  out.type = *type;

  if (out.type == GeometryType::kGeometryInstance) {
    if (in_template) type_value.fail("a geometry template cannot itself be a GeometryInstance");
    if (templates == nullptr) {
      object.get("template")
          .fail("a GeometryInstance needs the file's geometry-templates, and it has none");
    }
    out.placement = read_placement(object, vertices, *templates);
    out.lod = templates->templates[out.placement->template_index].lod;
    object.finish();
    return out;
  }

  out.lod = read_lod(object.get("lod"));
  const JsonValue boundaries = object.get("boundaries");
  std::optional<Semantics> semantics;
  if (const std::optional<JsonValue> s = object.find("semantics")) semantics = read_semantics(*s);
  // Appearances do not change where a surface is.
  object.has("material");
  object.has("texture");
  object.finish();
  if (!bounds_surfaces(out.type)) return out;
  out.surfaces =
      read_surfaces(out.type, boundaries, vertices.range, semantics ? &*semantics->values : nullptr,
                    semantics ? semantics->types.size() : 0);
  if (semantics) out.semantic_types = std::move(semantics->types);
  return out;
}

}  // namespace shadowgen::cityjson::detail
