#pragma once

// The nodes of a glTF file's scene with their world matrices (glTF 2.0 specification,
// 3.5 "Scenes" and 3.5.2/3.5.3 "Transformations"): the scene is the file's `scene`, else
// scene 0 (the specification leaves the choice to the reader when `scene` is not given);
// a file without scenes is refused, as the specification makes it a library of entities
// with nothing placed. From each root node in the scene's order, depth first, children in
// order; a node's world matrix is its parent's times its own, its own either `matrix`
// (16 numbers, column-major as glTF stores it) or T·R·S from `translation`, `rotation`
// (a quaternion x, y, z, w, normalised) and `scale`. All in double.
//
// Refused, naming the node: an index out of range, a node reached twice (glTF's nodes are
// disjoint trees: a cycle or a node with two parents would place its faces twice or
// without end), a matrix whose last row is not 0 0 0 1 (not affine, which the
// specification's decomposable TRS matrices are), a rotation of zero length, arrays of
// the wrong size.

#include <tiny_gltf.h>

#include <cstddef>
#include <glm/mat4x4.hpp>
#include <string>
#include <vector>

namespace shadowgen::gltf::detail {

struct PlacedNode {
  std::size_t node = 0;  // its index in the file's nodes
  glm::dmat4 world{1.0};
};

// The scene's nodes in the order above; InputError naming `file` as above.
std::vector<PlacedNode> walk_scene(const tinygltf::Model& model, const std::string& file);

// "node 'roof' (3)", or "node 3" for one without a name.
std::string node_subject(const tinygltf::Model& model, std::size_t node);

}  // namespace shadowgen::gltf::detail
