#pragma once

// A binary glTF 2.0 file (the glTF 2.0 specification, section 4.4 "GLB File Format
// Specification") of flat-coloured meshes, as the viewer page reads it (viewer_model.h):
// the 12-byte header, the JSON chunk padded with spaces and the binary chunk padded with
// zeros, each to 4 bytes. Each mesh is one primitive, with its own material and node.

#include <cstdint>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

namespace shadowgen::detail {

struct GlbMesh {
  std::string name;
  bool lines = false;                  // LINES (pairs of vertices), else TRIANGLES
  std::vector<float> positions;        // x, y, z per vertex, glTF's axes, relative to the node
  std::vector<float> faces;            // per vertex, the _FACE attribute; empty: none
  std::vector<std::uint32_t> indices;  // the triangles' or lines' vertices; empty: in order
  glm::dvec3 colour{0.0};              // sRGB, each channel in [0, 1]
  nlohmann::json node_extras;          // the node's extras; null: none
};

// The file. Every mesh has at least one vertex (whole triangles or lines) and indexes only
// its vertices, else std::invalid_argument; no mesh at all gives a file of one empty scene, without
// a binary chunk. Every node is translated by `translation`. Over 4 GiB, std::length_error.
// Materials are unlit (KHR_materials_unlit), double-sided, their baseColorFactor the colour in
// linear sRGB (as glTF's factors are), named as their mesh.
std::string glb_file(std::span<const GlbMesh> meshes, const glm::dvec3& translation);

}  // namespace shadowgen::detail
