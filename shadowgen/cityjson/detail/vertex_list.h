#pragma once

// The vertices a CityJSON geometry's boundaries index, placed in real coordinates, with
// how far their written precision lets each of them stray (SourceFace::vertex_rounding).
//
// CityJSON stores a vertex as integers and a top-level "transform" (CityJSON 2.0
// specification, "Transform Object"): real coordinate = scale × v + translate, axis by
// axis. Each real coordinate is then a multiple of its axis's scale away from the
// translation, so the point the writer meant lies within half a step of it per axis: a
// vertex within |scale| / 2, the Euclidean norm of the three half steps (0.866 mm for the
// common 1 mm scale). CityJSON 1.0 allowed files without a transform, whose vertices are
// real numbers as written: there the step is that of the most decimals any coordinate of
// the list is written with (the shortest decimal form that reads back to the same double),
// 10^-d for d decimals, and a vertex lies within √3 × 10^-d / 2. A list written in whole
// numbers claims no more than that: 0.866 for a metre.

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

struct VertexTransform {
  glm::dvec3 scale{1.0};
  glm::dvec3 translate{0.0};
};

// `transform`: { "scale": [3 numbers, each above 0], "translate": [3 numbers] }.
VertexTransform read_transform(const JsonValue& value);

struct VertexList {
  std::vector<glm::dvec3> points;  // real coordinates
  // How far each coordinate may stray, axis by axis: half a step (see above).
  glm::dvec3 half_step{0.0};

  // How far each vertex may stray, as a distance: |half_step|.
  double rounding() const;
};

// A "vertices" array of [x, y, z], placed by `transform` when there is one (its half step
// then the transform's, scale / 2), otherwise as written (10^-d / 2 on each axis, d the
// most decimals any coordinate of the list is written with; 0 for an empty list).
VertexList read_vertices(const JsonValue& value, const VertexTransform* transform);

}  // namespace shadowgen::cityjson::detail
