#pragma once

// faces[i].sun_hours of a shadowed database (docs/scene-format.md, "Sun hours"): per sun
// path, one lit area per instant (per part on a face of several parts), and the sun-hours
// regions where the path keeps them, or in a shard the nodes of the path's tree
// (model/instant_blocks.h).

#include <vector>

#include "database_polygons.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

// Reads `face`'s sums over every path of `shadowed` from `entry` into the paths, the
// regions' polygons as the face's lit polygons (`layout`), and appends where each path's
// sum stands to places[p], for the checks once every face is read. The regions come in
// increasing hours, each a whole number of the path's instants; a shard's nodes cover its
// blocks in order. A problem fails at its place in the file (InputError).
void read_face_sun_hours(JsonObject& entry, const Face& face, ShadowedScene& shadowed,
                         const LitLayout& layout, std::vector<std::vector<JsonPlace>>& places);

}  // namespace shadowgen::scene::detail
