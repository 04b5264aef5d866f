#pragma once

// The labels that name a node's faces ("<label>/<k>"), unique over a file although glTF's
// node names need not be: a node's name, or its index as text when it has none; a node
// whose label an earlier node already took is labelled "<label>#<index>" (its index in
// the file's nodes). Should that be taken too (an earlier node literally named so), the
// file is refused naming both nodes.

#include <tiny_gltf.h>

#include <cstddef>
#include <string>
#include <unordered_map>

namespace shadowgen::gltf::detail {

class NodeLabels {
 public:
  // The label of node `index` of `model`, taken for it; InputError naming `file` as above.
  std::string take(const tinygltf::Model& model, std::size_t index, const std::string& file);

 private:
  std::unordered_map<std::string, std::size_t> owners_;  // label -> node
};

// The node's name, or its index as text when it has none (FaceOrigin::object).
std::string node_name(const tinygltf::Model& model, std::size_t index);

}  // namespace shadowgen::gltf::detail
