#pragma once

// STL, ASCII or binary: each facet becomes one face record with its own vertices (STL
// shares none), in file order, degenerate facets included. A file is binary when its size
// is exactly 84 + 50 × (the triangle count in its header), as most readers decide, even
// when its header begins with "solid"; otherwise it must be ASCII text (`solid` ...
// `facet` ... `outer loop` ... `vertex x y z` ... `endloop` ... `endfacet` ...
// `endsolid`), complete: a binary file of the wrong size (truncated) is an error, and so
// is an ASCII file that ends before `endsolid`. ASCII coordinates are read in double
// precision, binary ones are single-precision floats.

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh_reader.h"

namespace shadowgen::scene::detail {

// `bytes` is the file's content; `file` and `mesh_id` name it in InputErrors.
MeshSoup parse_stl(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id);

}  // namespace shadowgen::scene::detail
