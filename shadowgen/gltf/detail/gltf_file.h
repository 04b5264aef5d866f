#pragma once

// A glTF file loaded by tinygltf (Debian's libtinygltf, 2.7) with what tinygltf leaves
// unchecked checked first: the JSON as every shadowgen input is read (a key given twice
// in an object, a number beyond a double's range: an error placed by line and column),
// the .glb container (glb_layout.h), the extensions the file requires, buffer files
// (regular files read as every input is, looked for next to the glTF file only, never in
// the working folder as tinygltf would), and images, which are never read or decoded.
// What is left to the caller: every index and bound inside the model (accessor_data.h,
// node_walk.h).

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace shadowgen::gltf::detail {

// The extension that lets positions be integers (KHR_mesh_quantization).
inline constexpr const char* kMeshQuantization = "KHR_mesh_quantization";

struct GltfFile {
  tinygltf::Model model;
  // The file's extensionsUsed lists KHR_mesh_quantization.
  bool quantized_positions = false;
};

// InputError naming `file` when it cannot be read or is not a glTF 2.0 file as above;
// tinygltf's own message is kept inside ours. Warnings ("file: what") are appended.
GltfFile load_gltf_file(const std::filesystem::path& file, std::vector<std::string>& warnings);

}  // namespace shadowgen::gltf::detail
