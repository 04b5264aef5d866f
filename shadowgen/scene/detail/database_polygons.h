#pragma once

// A database face's polygons: its parts, checked as a scene's face is, and its lit
// polygons for one light, in either layout of the format (shadowgen/database/
// database_format.h).

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "face_builder.h"
#include "hsr/polygon3.h"
#include "shadowgen/database/database_format.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

// A part gets the checks a scene's face gets (strict: a part is planar, it was written
// from a face already split into planar parts; planar within twice the face's vertex
// rounding, as the scene reader took a model's face: `source`, of kind kPolygon). A part
// without area is kept as it is, as the scene reader keeps a degenerate face; it warned
// when it read it. A problem fails at `at`; warnings are appended to `warnings`.
hsr::Polygon3 checked_database_part(hsr::Polygon3 polygon, const JsonValue& at,
                                    const FaceSource& source, std::vector<std::string>& warnings);

// How a face's lit polygons are written: the format's layout and, in the indexed one, the
// face's shared vertices (read_face_vertices).
struct LitLayout {
  database::Layout layout;
  const std::vector<glm::dvec3>& vertices;
};

// lit['id']: the polygons, each on the part its "part" key names. Without the key (a
// database written before parts were recorded) a polygon lies on the part whose plane
// is nearest to its outer vertices, the first of equals.
// In the indexed layout, loops of indices into the face's vertices (indexed_polygons.h),
// "part" required on a face of several parts.
std::vector<LitPolygon> read_database_lit(const JsonValue& value, const Face& face,
                                          const LitLayout& layout);

}  // namespace shadowgen::scene::detail
