#pragma once

// OFF (Geomview's Object File Format), read strictly and in full double precision:
//
//   [ST][C][N][4][n]OFF [BINARY]   the header keyword (optional in text files)
//   [Ndim]                         with the n prefix; only 3 is read
//   NVertices NFaces [NEdges]      NEdges is ignored
//   x y z [w] [normal] [colour] [s t]          one vertex a line
//   k i0 i1 ... i(k-1) [colour]                one face a line, indices from 0
//
// with '#' comments. The prefixes announce what each vertex line carries after x y z: a
// homogeneous w ("4", the point is x/w y/w z/w), a normal ("N", 3 numbers), a colour ("C",
// 1 to 4 numbers), texture coordinates ("ST", 2 numbers); a face may end with a colour of
// up to 4 numbers. Everything must be there as the header announces it: a file that ends
// early (truncated) or goes on after the last face, a vertex or face line with missing or
// extra numbers, a negative count or a coordinate that is not a finite number is an error.
// Text must be ASCII or UTF-8 (mesh_text.h). The header "OFF" run together with the
// counts ("OFF8 6 0", as some collections have it) is read too.
//
// Binary OFF ("OFF BINARY"): 32-bit integers and floats, big-endian as Geomview writes
// them, or little-endian as other writers do; the one that reads the file exactly, to its
// last byte, is taken (big-endian first). Counts, then per vertex its floats as above
// (a colour is 4 floats), then per face k, k indices and a colour count and its floats.
//
// Face records with fewer than 3 indices are kept, and indices are not checked against
// the vertex count: the caller does both.

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh_reader.h"

namespace shadowgen::scene::detail {

// `bytes` is the file's content; `file` and `mesh_id` name it in InputErrors.
MeshSoup parse_off(std::string_view bytes, const std::filesystem::path& file,
                   const std::string& mesh_id);

}  // namespace shadowgen::scene::detail
