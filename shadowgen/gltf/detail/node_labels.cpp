#include "detail/node_labels.h"

#include "detail/node_walk.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::gltf::detail {

std::string node_name(const tinygltf::Model& model, std::size_t index) {
  const std::string& name = model.nodes[index].name;
  return name.empty() ? std::to_string(index) : name;
}

std::string NodeLabels::take(const tinygltf::Model& model, std::size_t index,
                             const std::string& file) {
  std::string label = node_name(model, index);
  if (owners_.contains(label)) label.append("#").append(std::to_string(index));
  auto [it, taken] = owners_.emplace(label, index);
  if (!taken) {
    throw InputError(file, "",
                     node_subject(model, index) + " shares its name with an earlier node, and " +
                         node_subject(model, it->second) + " already has the label '" + label +
                         "' that would tell it apart");
  }
  return label;
}

}  // namespace shadowgen::gltf::detail
