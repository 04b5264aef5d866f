#pragma once

// A scene's or a database's "groups" (docs/scene-format.md, "Groups"): an array of
// {"id": string, "faces": [face pattern, ...]}, read with the same checks from either.

#include <vector>

#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::scene::detail {

// The groups at `value`, in order. Fails, at the entry's path, where an id is missing,
// empty or given twice (`groups[1] ('garden'): duplicate id 'garden' (already used by
// another group)`), `faces` is missing or empty, or a pattern is not a string or not a
// face pattern (shadowgen/groups/face_pattern.h); and, for every pattern, where it matches
// none of `faces` (`groups[0] ('garden').faces[1]: the pattern 'gardn*' matches no face
// id`), so a scene read names the mistake before any shadow is computed.
std::vector<FaceGroupSpec> read_groups(const JsonValue& value, const std::vector<Face>& faces);

}  // namespace shadowgen::scene::detail
