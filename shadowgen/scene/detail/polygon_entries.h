#pragma once

// A scene's "polygons" entries, each a face (docs/scene-format.md): read one by one from
// the document, or from their own texts (cut_array_member's elements) in parallel chunks.
// Either way a polygon is read by the same steps, in the same order: its id, then (the id
// claimed by the caller) its loops, its unknown keys and the face's checks (face_builder.h).

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

// polygons[i]'s id: a non-empty string without '/' (mesh face ids use it).
std::string read_polygon_id(JsonObject& entry, const std::string& file);

// The rest of polygons[i], its id read and claimed: its loops as a checked face. Unknown
// keys are warned of through the entry's document (an error under `strict`); the face's
// own warnings (face_builder.h) are appended to `face_warnings`.
Face read_polygon_face(JsonObject& entry, const std::string& id, const std::string& file,
                       bool strict, std::vector<std::string>& face_warnings);

struct PolygonsRead {
  std::vector<Face> faces;                              // [polygon]
  std::vector<std::string> warnings;                    // the entries' unknown keys, in order
  std::vector<std::vector<std::string>> face_warnings;  // [polygon]: read_polygon_face's
};

// The polygons whose texts are `texts` (polygons[0] first), each parsed on its own as the
// element it is (paths `polygons[i]`) and read by read_polygon_id and read_polygon_face,
// in chunks spread over the calling task arena's threads; results in order whatever the
// threads. Ids are not claimed: the caller claims them in order. Where polygons fail, the
// failure of the first is thrown (as reading them in order would meet it first among
// them; what reading the whole document in order would meet first, a clash of ids or a
// syntax error elsewhere, is the caller's to find).
PolygonsRead read_polygon_texts(std::span<const std::string_view> texts, const std::string& file,
                                bool strict);

}  // namespace shadowgen::scene::detail
