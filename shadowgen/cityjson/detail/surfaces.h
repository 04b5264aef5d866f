#pragma once

// The surfaces a geometry's "boundaries" hold, in the order the file gives them (solids in
// order, their shells in order, their surfaces in order), each with its semantic surface
// when "semantics" gives one (CityJSON 2.0 specification, "Semantics of geometric
// primitives": "values" nests as the boundaries do, down to one index into "surfaces" or
// null per surface, and null at any level stands for no semantics below it).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "detail/geometry_type.h"
#include "shadowgen/json/json_reader.h"

namespace shadowgen::cityjson::detail {

struct Surface {
  // The exterior ring, then the holes: indices into the geometry's vertex list.
  std::vector<std::vector<std::size_t>> rings;
  std::optional<std::size_t> semantic;  // an index into semantics.surfaces
};

// The vertex list the indices refer to, for their range check: its size, and how messages
// name it ("the file has", "the feature has", "vertices-templates has").
struct VertexRange {
  std::size_t count = 0;
  std::string owner;
};

// The surfaces of `boundaries` for a `type` that bounds_surfaces (not a GeometryInstance).
// `semantic_values` (semantics.values) may be null; `semantic_count` is the number of
// semantic surfaces its indices refer to. Fails, at the value at fault, when the
// boundaries do not nest as `type` says, a ring is empty or a surface has no ring, a
// vertex index is out of `vertices`, or the values do not nest as the boundaries or
// index past the semantic surfaces.
std::vector<Surface> read_surfaces(GeometryType type, const JsonValue& boundaries,
                                   const VertexRange& vertices, const JsonValue* semantic_values,
                                   std::size_t semantic_count);

}  // namespace shadowgen::cityjson::detail
