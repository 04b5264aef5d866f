#pragma once

// Which reader a scene's meshes[] file goes to (docs/scene-format.md, "Meshes" and "Model
// files"): by content where the content says it, otherwise by extension.
//
// Content, from the file's first kSniffBytes (a regular file; a FIFO is told by its
// extension alone, since reading it consumes it):
//   - the bytes "glTF" first: binary glTF (.glb);
//   - a JSON object (first non-blank byte '{') holding the key "asset": glTF;
//     the string "CityJSON" as a "type": CityJSON, or CityJSONSeq when its first line is
//     a whole object and a "CityJSONFeature" follows (or the extension is .jsonl);
//     the key "version_identifier" (the Version object of epJSON): epJSON;
//   - a line that starts an IDF `Version` object (`Version,` or `Version;`, any case, after
//     blanks), comment lines (`!`) before it: EnergyPlus IDF.
// Otherwise the extension, case-insensitive: .obj .stl .off .ply; .idf, .epjson, .gltf,
// .glb, .jsonl (CityJSONSeq) and .json (CityJSON, when the content did not say
// otherwise); anything else goes to OpenMesh's readers (mesh_reader.h).

#include <cstddef>
#include <filesystem>
#include <string_view>

namespace shadowgen::scene::detail {

enum class SourceFormat {
  kMesh,        // OBJ, STL, OFF, PLY or another OpenMesh format: mesh_reader.h
  kEnergyPlus,  // IDF or epJSON
  kCityJson,    // CityJSON or CityJSONSeq
  kGltf,        // .gltf or .glb
};

inline constexpr std::size_t kSniffBytes = 64 * 1024;

// The format of `head`, the first bytes of a file named `file`.
SourceFormat format_of(std::string_view head, const std::filesystem::path& file);

// The same, reading the head of `file` itself (nothing for a FIFO or an unreadable file:
// its reader then says what is wrong with it).
SourceFormat format_of_file(const std::filesystem::path& file);

// How docs and messages name a format: "an EnergyPlus model", "a CityJSON file", ...
std::string_view format_name(SourceFormat format);

}  // namespace shadowgen::scene::detail
