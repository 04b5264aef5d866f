#pragma once

// A face's lit polygons and sun-hours regions in the indexed layout of a shadowed
// database (shadowgen-shadowed/2, shadowgen/database/database_format.h): the face's
// shared vertices, then each polygon as loops of indices into them. The checks of the
// polygons themselves (on their part, inside it, not overlapping) are the caller's, as
// for polygons written with their coordinates.

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

// The face's "numbers" and "vertices" (none where it has neither): every index within
// "numbers", three per vertex, each vertex within the coordinate range of a scene.
std::vector<glm::dvec3> read_face_vertices(JsonObject& face);

// One lit polygon: its loops, the outer first, each an array of indices into `vertices`;
// on a face of several parts (`parts` > 1) an object {"part": k, "loops": [...]}.
LitPolygon read_indexed_lit(const JsonValue& value, const std::vector<glm::dvec3>& vertices,
                            std::size_t parts);

}  // namespace shadowgen::scene::detail
