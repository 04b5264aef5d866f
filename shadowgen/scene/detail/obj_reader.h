#pragma once

// Wavefront OBJ geometry: `v` vertices and `f` (or old-style `fo`) face records, in
// double precision; every other statement (normals, texture coordinates, groups,
// materials, lines, points, free-form geometry) is skipped. Face indices may be
// negative (relative to the vertices read so far) and carry /texture/normal parts,
// which are ignored. A record with fewer than 3 indices is kept (the caller rejects it).
// The file must be text (mesh_text.h): ASCII or UTF-8, lines ending in LF, CRLF or CR.
// A vertex may carry a weight or a colour after its coordinates, numbers all.

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh_reader.h"

namespace shadowgen::scene::detail {

// `text` is the file's content; `file` and `mesh_id` name it in InputErrors.
MeshSoup parse_obj(std::string_view text, const std::filesystem::path& file,
                   const std::string& mesh_id);

}  // namespace shadowgen::scene::detail
