#include "detail/glb_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "shadowgen/output/gltf_space.h"

namespace shadowgen::detail {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126;                      // componentType FLOAT
constexpr int kUnsignedInt = 5125;                // componentType UNSIGNED_INT
constexpr int kArrayBuffer = 34962;               // bufferView target ARRAY_BUFFER
constexpr int kElementArrayBuffer = 34963;        // bufferView target ELEMENT_ARRAY_BUFFER
constexpr int kModeLines = 1;
constexpr int kModeTriangles = 4;

void append_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>(v >> (8 * i) & 0xff);
}

// Appends `values` (4-byte numbers, so every view stays aligned) to the binary chunk as one
// buffer view for `target`; returns its index.
template <class T>
std::size_t add_view(std::string& bin, nlohmann::json& views, const std::vector<T>& values,
                     int target) {
  static_assert(sizeof(T) == 4);
  const std::size_t offset = bin.size();
  const std::size_t bytes = values.size() * sizeof(T);
  bin.resize(offset + bytes);
  std::memcpy(bin.data() + offset, values.data(), bytes);  // glTF is little-endian, as x86
  views.push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
  return views.size() - 1;
}

}  // namespace

std::string glb_file(std::span<const GlbMesh> meshes, const glm::dvec3& translation) {
  nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}, {"generator", "shadowgen"}}},
      {"extensionsUsed", {"KHR_materials_unlit"}},
      {"scene", 0},
  };
  nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array(),
                 materials = nlohmann::json::array(), gltf_meshes = nlohmann::json::array(),
                 nodes = nlohmann::json::array(), scene_nodes = nlohmann::json::array();
  std::string bin;
  for (const GlbMesh& mesh : meshes) {
    const std::size_t vertices = mesh.positions.size() / 3;
    if (vertices == 0 || mesh.positions.size() % 3 != 0 ||
        (!mesh.faces.empty() && mesh.faces.size() != vertices)) {
      throw std::invalid_argument("glb_file: mesh '" + mesh.name + "' has no whole vertices");
    }
    std::vector<float> lo(3, std::numeric_limits<float>::infinity());
    std::vector<float> hi(3, -std::numeric_limits<float>::infinity());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], mesh.positions[i]);
      hi[i % 3] = std::max(hi[i % 3], mesh.positions[i]);
    }
    nlohmann::json attributes;
    accessors.push_back({{"bufferView", add_view(bin, views, mesh.positions, kArrayBuffer)},
                         {"componentType", kFloat},
                         {"count", vertices},
                         {"type", "VEC3"},
                         {"min", lo},
                         {"max", hi}});
    attributes["POSITION"] = accessors.size() - 1;
    if (!mesh.faces.empty()) {
      accessors.push_back({{"bufferView", add_view(bin, views, mesh.faces, kArrayBuffer)},
                           {"componentType", kFloat},
                           {"count", vertices},
                           {"type", "SCALAR"}});
      attributes["_FACE"] = accessors.size() - 1;
    }
    materials.push_back({{"name", mesh.name},
                         {"pbrMetallicRoughness",
                          {{"baseColorFactor",
                            {linear_from_srgb(mesh.colour.r), linear_from_srgb(mesh.colour.g),
                             linear_from_srgb(mesh.colour.b), 1.0}},
                           {"metallicFactor", 0.0}}},
                         {"doubleSided", true},
                         {"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}});
    nlohmann::json primitive = {{"attributes", attributes},
                                {"material", materials.size() - 1},
                                {"mode", mesh.lines ? kModeLines : kModeTriangles}};
    if (!mesh.indices.empty()) {
      if (*std::max_element(mesh.indices.begin(), mesh.indices.end()) >= vertices) {
        throw std::invalid_argument("glb_file: mesh '" + mesh.name + "' indexes no vertex");
      }
      accessors.push_back({{"bufferView", add_view(bin, views, mesh.indices, kElementArrayBuffer)},
                           {"componentType", kUnsignedInt},
                           {"count", mesh.indices.size()},
                           {"type", "SCALAR"}});
      primitive["indices"] = accessors.size() - 1;
    }
    gltf_meshes.push_back(
        {{"name", mesh.name}, {"primitives", nlohmann::json::array({primitive})}});
    nlohmann::json node = {{"name", mesh.name},
                           {"mesh", gltf_meshes.size() - 1},
                           {"translation", {translation.x, translation.y, translation.z}}};
    if (!mesh.node_extras.is_null()) node["extras"] = mesh.node_extras;
    nodes.push_back(node);
    scene_nodes.push_back(nodes.size() - 1);
  }
  gltf["scenes"] = {{{"nodes", scene_nodes}}};
  // A model without meshes (a scene of faces without area and without outlines) has no
  // buffer, which glTF wants of at least one byte, and no binary chunk.
  if (!meshes.empty()) {
    gltf["nodes"] = nodes;
    gltf["meshes"] = gltf_meshes;
    gltf["materials"] = materials;
    gltf["accessors"] = accessors;
    gltf["bufferViews"] = views;
    gltf["buffers"] = {{{"byteLength", bin.size()}}};
  }

  std::string json = gltf.dump();
  json.resize((json.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  const std::size_t length = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
  if (length > std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error("glb_file: a binary glTF holds at most 4 GiB");
  }
  std::string out;
  out.reserve(length);
  append_u32(out, kGlbMagic);
  append_u32(out, kGlbVersion);
  append_u32(out, static_cast<std::uint32_t>(length));
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  append_u32(out, kChunkJson);
  out += json;
  if (!bin.empty()) {
    append_u32(out, static_cast<std::uint32_t>(bin.size()));
    append_u32(out, kChunkBin);
    out += bin;
  }
  return out;
}

}  // namespace shadowgen::detail
