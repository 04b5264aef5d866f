#pragma once

// PLY (the Stanford polygon file format), ASCII or binary in either byte order, read
// strictly and in full double precision. The header's elements are read in order, each
// with the properties it declares (char/int8 ... double/float64, and lists):
//   - `vertex` gives x, y, z (any numeric type: double keeps every bit, float converts
//     exactly, ASCII text is read as written, in double precision);
//   - `face` gives its `vertex_indices` (or `vertex_index`) list, indices from 0;
//   - other elements (edges, materials) and properties (normals, colours) are read and
//     not used.
// The body must hold exactly what the header announces: a file that ends early
// (truncated) or goes on after the last element, an ASCII element line with missing or
// extra numbers, a value out of its type's range, a negative list count or a coordinate
// that is not finite is an error, and so is a missing x, y, z or face index list. The
// header, and an ASCII body, must be text (mesh_text.h). `tristrips` elements are not
// read (an error).
//
// Face records with fewer than 3 indices are kept, and indices are not checked against
// the vertex count: the caller does both.

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh_reader.h"

namespace shadowgen::scene::detail {

// `bytes` is the file's content; `file` and `mesh_id` name it in InputErrors.
MeshSoup parse_ply(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id);

}  // namespace shadowgen::scene::detail
