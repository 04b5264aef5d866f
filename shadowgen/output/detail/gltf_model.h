#pragma once

// The glTF file of the export (shadowgen/output/gltf_export.h, its layout and axes) from
// its materials, each with its mesh and extras, written by tinygltf: the one place the
// output room speaks glTF.

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "detail/gltf_mesh.h"
#include "shadowgen/output/gltf_export.h"

namespace shadowgen::output::detail {

struct GltfMaterial {
  std::string name;
  glm::dvec3 colour{0.0};  // sRGB, each channel in [0, 1]
  nlohmann::json extras;   // the material's extras (an object)
  GltfMesh mesh;           // no mesh is written for an empty one
};

// The file's bytes: `materials` in order, each with a node and a mesh where it has
// triangles; the root node at `origin` (scene coordinates); the pieces' columns as the
// meshes' extras; `scene_extras` (an object) as the scene's. With options.face_attribute,
// the vertices' faces as _FACE; with options.outlines, `outline_points` (pairs, scene
// coordinates) as a mesh of lines. Throws std::length_error for a buffer of 4 GiB or more.
std::string gltf_file(const std::vector<GltfMaterial>& materials,
                      std::span<const glm::dvec3> outline_points, const glm::dvec3& origin,
                      const nlohmann::json& scene_extras, GltfForm form,
                      const GltfOptions& options);

}  // namespace shadowgen::output::detail
