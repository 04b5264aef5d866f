#include "detail/node_walk.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <utility>

#include "shadowgen/model/input_error.h"

namespace shadowgen::gltf::detail {
namespace {

// The node's own matrix, from `matrix` or its TRS properties.
glm::dmat4 local_matrix(const tinygltf::Node& node, const std::string& file,
                        const std::string& subject) {
  auto fail = [&](const std::string& problem) -> void {
    throw InputError(file, "", subject + ": " + problem);
  };
  auto check_size = [&](const std::vector<double>& values, std::size_t size, const char* key) {
    if (!values.empty() && values.size() != size) {
      fail(std::string("'") + key + "' has " + std::to_string(values.size()) + " numbers, not " +
           std::to_string(size));
    }
  };
  check_size(node.matrix, 16, "matrix");
  check_size(node.translation, 3, "translation");
  check_size(node.rotation, 4, "rotation");
  check_size(node.scale, 3, "scale");
  if (!node.matrix.empty()) {
    const glm::dmat4 m = glm::make_mat4(node.matrix.data());  // column-major, as glTF
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0) {
      fail("'matrix' is not affine: its last row is not 0 0 0 1");
    }
    return m;
  }
  glm::dmat4 m(1.0);
  if (!node.translation.empty()) {
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (!node.rotation.empty()) {
    glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double length = glm::length(q);
    if (!(length > 0.0) || !std::isfinite(length)) {
      fail("'rotation' is not a rotation: a quaternion of length " + std::to_string(length));
    }
    m *= glm::mat4_cast(q / length);
  }
  if (!node.scale.empty()) {
    m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  }
  return m;
}

}  // namespace

std::string node_subject(const tinygltf::Model& model, std::size_t node) {
  const std::string& name = model.nodes[node].name;
  return name.empty() ? "node " + std::to_string(node)
                      : "node '" + name + "' (" + std::to_string(node) + ")";
}

std::vector<PlacedNode> walk_scene(const tinygltf::Model& model, const std::string& file) {
  if (model.scenes.empty()) {
    throw InputError(file, "", "has no scene: a glTF file without scenes places no node");
  }
  std::size_t scene = 0;
  if (model.defaultScene != -1) {  // tinygltf's "none"
    if (model.defaultScene < 0 ||
        static_cast<std::size_t>(model.defaultScene) >= model.scenes.size()) {
      throw InputError(file, "",
                       "'scene' is " + std::to_string(model.defaultScene) + ", of " +
                           std::to_string(model.scenes.size()) + " scenes");
    }
    scene = static_cast<std::size_t>(model.defaultScene);
  }
  const std::string scene_subject = "scene " + std::to_string(scene);
  std::vector<PlacedNode> placed;
  std::vector<std::string> reached_from(model.nodes.size());  // empty: not reached yet
  // Depth first without recursion, so that a deep hierarchy cannot exhaust the stack:
  // pending holds (node, parent's world matrix, who reaches it), taken from the back.
  struct Pending {
    int node;
    glm::dmat4 parent;
    std::string from;
  };
  std::vector<Pending> pending;
  auto push_children = [&pending](const std::vector<int>& children, const glm::dmat4& parent,
                                  const std::string& from) {
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      pending.push_back({*it, parent, from});
    }
  };
  push_children(model.scenes[scene].nodes, glm::dmat4(1.0), scene_subject);
  while (!pending.empty()) {
    Pending next = std::move(pending.back());
    pending.pop_back();
    if (next.node < 0 || static_cast<std::size_t>(next.node) >= model.nodes.size()) {
      throw InputError(file, "",
                       next.from + " names node " + std::to_string(next.node) + ", of " +
                           std::to_string(model.nodes.size()));
    }
    const auto index = static_cast<std::size_t>(next.node);
    const std::string subject = node_subject(model, index);
    if (!reached_from[index].empty()) {
      throw InputError(file, "",
                       subject + " is reached twice, from " + reached_from[index] + " and from " +
                           next.from + ": glTF's nodes form disjoint trees");
    }
    reached_from[index] = next.from;
    const glm::dmat4 world = next.parent * local_matrix(model.nodes[index], file, subject);
    placed.push_back({index, world});
    push_children(model.nodes[index].children, world, subject);
  }
  return placed;
}

}  // namespace shadowgen::gltf::detail
