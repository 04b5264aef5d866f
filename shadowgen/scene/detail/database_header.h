#pragma once

// The members of a shadowed database that its faces depend on, read before them
// (shadowgen/output/database.h, docs/scene-format.md): the format, the shard, the method,
// the site, the lights and views, the sun paths.

#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

#include "shadowgen/database/database_format.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen::scene::detail {

// What reading the faces needs of the header besides the shadowed scene.
struct DatabaseHeader {
  database::Layout layout = database::Layout::kIndexed;      // the format's
  std::unordered_map<std::string, std::size_t> light_index;  // light id -> index
  std::vector<char> instant;  // a sampled method's: per light, whether it is a path's instant
};

// Makes `shadowed` (keeping its scene's file) what the header's members of `top` say: its
// scene's site, lights, views and sun paths, its shard, its method (an estimate with no
// face yet, or exact) and sun paths (each path's instants the lights whose "sun" names it,
// on the path's steps, in time order), and its lit table with no face yet. A member out of
// its rules fails at its place in the file (InputError).
DatabaseHeader read_database_header(JsonObject& top, ShadowedScene& shadowed);

}  // namespace shadowgen::scene::detail
