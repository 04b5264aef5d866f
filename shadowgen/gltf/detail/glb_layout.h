#pragma once

// The container of a binary glTF file (.glb), checked before tinygltf reads it (glTF 2.0
// specification, 4.4 "Binary glTF Layout"): a 12-byte header (magic "glTF", version 2,
// the total length), then chunks of 8-byte headers (length, type) and their data, the
// first of type JSON, the second, if any, of type BIN. tinygltf 2.7 does not check that
// the BIN chunk's header and data lie inside the file, so a file that ends early is
// refused here, saying how long its header says it is.

#include <cstddef>
#include <string>
#include <string_view>

namespace shadowgen::gltf::detail {

// Whether the bytes start with the magic "glTF" of a binary file.
bool is_glb(std::string_view bytes);

struct GlbChunks {
  std::string_view json;  // the JSON chunk's data
  std::string_view bin;   // the BIN chunk's data; empty when there is none
};

// The chunks of `bytes`, which is_glb; InputError naming `file` when the layout is broken:
// "is truncated: its header gives a length of 1000 bytes, the file has 600".
GlbChunks glb_chunks(std::string_view bytes, const std::string& file);

}  // namespace shadowgen::gltf::detail
