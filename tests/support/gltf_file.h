#pragma once

// A plain reader of the glTF files shadowgen exports (shadowgen/output/gltf_export.h), for
// tests: independent of the writer (no tinygltf), it takes the JSON and the buffer apart
// itself, from a .glb's chunks or a .gltf's base64 data URI, and reads the triangles back
// from the bytes as the file holds them. Only what the export writes is understood:
// TRIANGLES with uint32 indices and float32 POSITION (and float32 scalar attributes), LINES
// of float32 POSITION, node translations (no rotation or scale). Anything else is an error,
// reported, not thrown.

#include <array>
#include <cstddef>
#include <filesystem>
#include <glm/vec3.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace shadowgen::test {

using GltfTriangle = std::array<glm::dvec3, 3>;

struct GltfFile {
  nlohmann::json json;
  std::vector<unsigned char> buffer;  // buffer 0; empty where there is none
  std::vector<std::string> errors;    // what could not be read
};

// A .glb's or a .gltf's bytes, told apart by the .glb's magic "glTF".
GltfFile parse_gltf(const std::string& bytes);

// The triangles of mesh `mesh`'s first primitive, in the file's coordinates relative to
// its node (the float32 positions widened to double).
std::vector<GltfTriangle> mesh_triangles(GltfFile& file, std::size_t mesh);

// The float32 SCALAR attribute `attribute` (e.g. "_FACE") of mesh `mesh`'s first
// primitive, one value per vertex, widened to double; empty (and an error) where it has none.
std::vector<double> mesh_scalars(GltfFile& file, std::size_t mesh, const std::string& attribute);

// The segments of mesh `mesh`'s first primitive, LINES without indices, each a pair of
// points in the file's coordinates relative to its node.
std::vector<std::array<glm::dvec3, 2>> mesh_lines(GltfFile& file, std::size_t mesh);

// The translation of the node holding mesh `mesh`, its parents' added: where the mesh's
// positions are relative to.
glm::dvec3 mesh_translation(GltfFile& file, std::size_t mesh);

// Area of a triangle, in double.
double triangle_area(const GltfTriangle& t);

// Per material name, the area of the triangles of the meshes drawn in it (meshes of lines
// left out).
std::map<std::string, double> material_areas(GltfFile& file);

// Saves `bytes` for the Khronos validator (web/validate_gltf.mjs) where the environment
// names a folder for them (SHADOWGEN_GLTF_KEEP, which the CTest test gltf.validator sets),
// as "<test suite>.<test name>-<n><extension>"; nothing otherwise.
void keep_for_validator(const std::string& bytes, const std::string& extension);
void keep_file_for_validator(const std::filesystem::path& file);

}  // namespace shadowgen::test
