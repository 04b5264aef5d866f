#pragma once

// One Geometry Object of a city object or of "geometry-templates" (CityJSON 2.0
// specification, "Geometry Objects", "Geometry templates"), read whole: its type,
// level of detail, surfaces and their semantic types; for a GeometryInstance, the
// template it places and how.
//
// A GeometryInstance ("Geometry templates") places template "template" of
// "geometry-templates": each of the template's vertices v (in "vertices-templates", real
// coordinates never touched by the file's transform) goes to M · (v, 1) + r, M the 4 × 4
// "transformationMatrix" given row by row (16 numbers, row-major, applied to the column
// vector (x, y, z, 1)), r the reference point, the one vertex of the file's own list in
// the instance's "boundaries". M must be affine (last row 0, 0, 0, 1). Its level of
// detail is the template's.

#include <cstddef>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "detail/geometry_type.h"
#include "detail/lod.h"
#include "detail/surfaces.h"
#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

struct GeometryTemplates;

// Where a GeometryInstance puts its template: template vertex v at linear · v + offset.
struct TemplatePlacement {
  std::size_t template_index = 0;
  glm::dmat3 linear{1.0};
  glm::dvec3 offset{0.0};  // the matrix's translation plus the reference point
  // How far a placed vertex may stray: the reference point's rounding, plus the
  // template vertices' as the matrix moves them: off by h_j on axis j, a template vertex
  // lands off by at most Σ_j |m_ij| h_j on axis i, a distance the norm of those.
  double rounding = 0.0;
};

struct Geometry {
  GeometryType type = GeometryType::kMultiSurface;
  Lod lod;
  // The surfaces (empty for a GeometryInstance, whose surfaces are its template's, and
  // for MultiPoint and MultiLineString) and the semantic surfaces' types they index.
  std::vector<Surface> surfaces;
  std::vector<std::string> semantic_types;
  std::optional<TemplatePlacement> placement;  // a GeometryInstance's
};

// The vertex list a geometry's indices refer to, with its name for messages and its
// rounding (VertexList::rounding).
struct GeometryVertices {
  const std::vector<glm::dvec3>* points = nullptr;
  VertexRange range;
  double rounding = 0.0;
};

// Reads `value`, a Geometry Object. `templates` (null when the file has none) resolves a
// GeometryInstance, which a template itself may not be (`in_template`). Fails at the
// value at fault: a type CityJSON does not define, boundaries or semantics not nested as
// the type says, an index out of range (vertex, template, semantic surface), a
// transformationMatrix that is not 16 numbers of an affine map.
Geometry read_geometry(const JsonValue& value, const GeometryVertices& vertices,
                       const GeometryTemplates* templates, bool in_template);

}  // namespace shadowgen::cityjson::detail
