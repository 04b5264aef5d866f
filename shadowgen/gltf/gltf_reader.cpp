#include "shadowgen/gltf/gltf_reader.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <optional>

#include "detail/accessor_data.h"
#include "detail/feature_warnings.h"
#include "detail/gltf_file.h"
#include "detail/node_labels.h"
#include "detail/node_walk.h"
#include "detail/primitive_triangles.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::gltf {
namespace {

using detail::AccessorData;
using detail::Place;

// glTF's +y up turned to the scene's +z up: (x, y, z) -> (x, -z, y), a rotation by 90
// degrees about x (determinant +1), so it turns no face over.
glm::dvec3 z_up(const glm::dvec3& p) { return {p.x, -p.z, p.y}; }

std::string text_of(const glm::dvec3& p) {
  std::string text = "(";
  for (int c = 0; c < 3; ++c) {
    if (c > 0) text += ", ";
    append_shortest(text, p[c]);
  }
  return text + ")";
}

bool finite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// What a node's world matrix does to its mesh: the matrix, whether it mirrors (its
// linear part's determinant is negative), and how much it may stretch a vector (the
// Frobenius norm of its linear part, at least its spectral norm).
struct Placement {
  glm::dmat4 world;
  bool mirrored = false;
  double stretch = 0.0;

  explicit Placement(const glm::dmat4& m) : world(m) {
    const glm::dmat3 linear(m);
    mirrored = glm::determinant(linear) < 0.0;
    double sum = 0.0;
    for (int c = 0; c < 3; ++c) {
      for (int r = 0; r < 3; ++r) sum += linear[c][r] * linear[c][r];
    }
    stretch = std::sqrt(sum);
  }
};

// The positions of a primitive: a VEC3 accessor of floats, or, where the file uses
// KHR_mesh_quantization, of the integer types that extension allows.
void check_positions(const AccessorData& positions, bool quantized, const Place& place) {
  if (positions.type() != TINYGLTF_TYPE_VEC3) place.fail(positions.label() + " is not VEC3");
  const int type = positions.component_type();
  if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) return;
  const bool integer =
      type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
      type == TINYGLTF_COMPONENT_TYPE_SHORT || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  if (integer && quantized) return;
  place.fail(positions.label() + " has components of type " + detail::component_type_name(type) +
             (integer ? ": glTF 2.0 positions are FLOAT, integers only with "
                        "KHR_mesh_quantization, which the file does not use"
                      : ": glTF 2.0 positions are FLOAT"));
}

void check_indices(const AccessorData& indices, const Place& place) {
  const int type = indices.component_type();
  if (indices.type() != TINYGLTF_TYPE_SCALAR || (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                                 type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                                 type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
    place.fail(indices.label() +
               " is not a SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
}

// A vertex of a primitive placed in the scene, with how far the source's precision may
// have moved it.
struct PlacedVertex {
  glm::dvec3 point;
  double rounding = 0.0;
};

PlacedVertex place_vertex(const AccessorData& positions, std::size_t vertex,
                          const Placement& placement, const Place& place) {
  glm::dvec3 local;
  double rounding2 = 0.0;
  for (int c = 0; c < 3; ++c) {
    local[c] = positions.value(vertex, c);
    const double r = positions.rounding(local[c]);
    rounding2 += r * r;
  }
  if (!finite(local)) {
    place.fail(positions.label() + " element " + std::to_string(vertex) +
               " is not finite: " + text_of(local));
  }
  const glm::dvec3 point = z_up(glm::dvec3(placement.world * glm::dvec4(local, 1.0)));
  if (!finite(point)) {
    place.fail(positions.label() + " element " + std::to_string(vertex) + ", " + text_of(local) +
               ", placed by its node's matrix, is beyond a double's range");
  }
  return {point, placement.stretch * std::sqrt(rounding2)};
}

// A node with a mesh, as its faces are made: where it places them, what names them.
struct MeshNode {
  Placement placement;
  std::string label;    // of its face ids, "<label>/<k>"
  std::string subject;  // "node 'roof' (3)"
  FaceOrigin origin;
  std::size_t faces = 0;  // made so far: the next face's k
};

// What the reader warns of, a kind at a time.
struct Warnings {
  explicit Warnings(const std::string& file)
      : skins(file, "nodes",
              "its skin is not applied: the mesh is read unskinned, at the node's transform"),
        morph_targets(file, "primitives",
                      "morph targets are not applied: the base positions are read"),
        no_positions(file, "primitives",
                     "no POSITION attribute: the primitive draws nothing and is skipped") {}

  detail::FeatureWarnings skins, morph_targets, no_positions;
};

// Appends the faces of `primitive` as `node` places them.
void read_primitive(const detail::GltfFile& file, const tinygltf::Primitive& primitive,
                    const Place& place, MeshNode& node, Warnings& warnings, SourceModel& out) {
  const tinygltf::Model& model = file.model;
  const std::optional<detail::Topology> topology = detail::triangle_topology(primitive.mode);
  if (!topology) {
    place.fail("mode " + std::to_string(primitive.mode) + " (" + detail::mode_name(primitive.mode) +
               ") draws no faces: shadowgen reads TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN");
  }
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) {
    warnings.no_positions.add(place.subject);
    return;
  }
  if (!primitive.targets.empty()) warnings.morph_targets.add(place.subject);
  // A Draco primitive's accessors have no buffer view but where the file gives an
  // uncompressed fallback (KHR_draco_mesh_compression).
  const auto position_index = static_cast<std::size_t>(position->second);
  if (primitive.extensions.contains("KHR_draco_mesh_compression") &&
      position_index < model.accessors.size() && model.accessors[position_index].bufferView < 0) {
    place.fail(
        "its positions are Draco-compressed (KHR_draco_mesh_compression), which "
        "shadowgen does not read");
  }
  const AccessorData positions(model, position->second, "POSITION", place);
  check_positions(positions, file.quantized_positions, place);
  std::optional<AccessorData> indices;
  if (primitive.indices != -1) {  // tinygltf's "none"; another negative fails as an index
    indices.emplace(model, primitive.indices, "indices", place);
    check_indices(*indices, place);
  }
  const std::size_t sequence = indices ? indices->count() : positions.count();
  if (*topology == detail::Topology::kTriangles && sequence % 3 != 0) {
    place.fail(std::string(indices ? "its " + indices->label() + " has " : "it has ") +
               std::to_string(sequence) + (indices ? " indices" : " vertices") +
               ", not a multiple of 3 (TRIANGLES)");
  }
  auto vertex_at = [&](std::size_t position_in_sequence) {
    if (!indices) return position_in_sequence;
    const std::uint64_t vertex = indices->unsigned_value(position_in_sequence);
    if (vertex >= positions.count()) {
      place.fail(indices->label() + " element " + std::to_string(position_in_sequence) + " is " +
                 std::to_string(vertex) + ", beyond the " + std::to_string(positions.count()) +
                 " vertices of " + positions.label());
    }
    return static_cast<std::size_t>(vertex);
  };
  const std::size_t triangles = detail::triangle_count(*topology, sequence);
  for (std::size_t i = 0; i < triangles; ++i) {
    const std::array<std::size_t, 3> corners = detail::triangle_corners(*topology, i);
    std::array<PlacedVertex, 3> v;
    for (int c = 0; c < 3; ++c) {
      v[static_cast<std::size_t>(c)] = place_vertex(
          positions, vertex_at(corners[static_cast<std::size_t>(c)]), node.placement, place);
    }
    if (node.placement.mirrored) std::swap(v[1], v[2]);  // keeps the front side
    const std::string k = std::to_string(node.faces++);
    SourceFace face;
    face.id = node.label + "/" + k;
    face.polygon.outer = {v[0].point, v[1].point, v[2].point};
    face.origin = node.origin;
    face.vertex_rounding = std::max({v[0].rounding, v[1].rounding, v[2].rounding});
    face.described = node.subject + " triangle " + k;
    out.faces.push_back(std::move(face));
  }
}

}  // namespace

SourceModel read_gltf(const std::filesystem::path& file, const SourceOptions&) {
  SourceModel out;
  const std::string name = file.string();
  const detail::GltfFile loaded = detail::load_gltf_file(file, out.warnings);
  const tinygltf::Model& model = loaded.model;
  detail::NodeLabels labels;
  Warnings warnings(name);
  for (const detail::PlacedNode& placed : detail::walk_scene(model, name)) {
    const tinygltf::Node& node = model.nodes[placed.node];
    if (node.mesh == -1) continue;  // tinygltf's "none"
    const std::string subject = detail::node_subject(model, placed.node);
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= model.meshes.size()) {
      throw InputError(name, "",
                       subject + " names mesh " + std::to_string(node.mesh) + ", of " +
                           std::to_string(model.meshes.size()));
    }
    const tinygltf::Mesh& mesh = model.meshes[static_cast<std::size_t>(node.mesh)];
    MeshNode mesh_node{Placement(placed.world), labels.take(model, placed.node, name), subject,
                       FaceOrigin{"gltf", detail::node_name(model, placed.node), mesh.name, ""}};
    if (node.skin >= 0) warnings.skins.add(subject);
    const std::string mesh_subject =
        mesh.name.empty() ? "mesh " + std::to_string(node.mesh)
                          : "mesh '" + mesh.name + "' (" + std::to_string(node.mesh) + ")";
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const Place place{name, subject + ", " + mesh_subject + ", primitive " + std::to_string(p)};
      read_primitive(loaded, mesh.primitives[p], place, mesh_node, warnings, out);
    }
  }
  if (out.faces.empty()) {
    throw InputError(name, "", "places no triangle: no node of its scene has a mesh with one");
  }
  for (const detail::FeatureWarnings* kind :
       {&warnings.skins, &warnings.morph_targets, &warnings.no_positions}) {
    kind->append_to(out.warnings);
  }
  return out;
}

}  // namespace shadowgen::gltf
