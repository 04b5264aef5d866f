#include "detail/gltf_model.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "shadowgen/output/gltf_space.h"

namespace shadowgen::output::detail {
namespace {

// glTF's codes (glTF 2.0, 3.6.2 and 3.7.2): component types, targets, primitive mode.
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUnsignedInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kArrayBuffer = TINYGLTF_TARGET_ARRAY_BUFFER;
constexpr int kElementArrayBuffer = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
constexpr int kTriangles = TINYGLTF_MODE_TRIANGLES;
constexpr int kLines = TINYGLTF_MODE_LINE;

constexpr const char* kUnlit = "KHR_materials_unlit";

// Puts the extras into the JSON tinygltf wrote: its own extras (tinygltf::Value) write an
// empty list as null, and cost several copies of every number of a large table. The
// binary form's JSON chunk is replaced, padded with spaces to 4 bytes as the GLB wants
// (glTF 2.0, 4.4.3), its binary chunk kept as tinygltf wrote it.
template <typename AddExtras>
std::string with_extras(const std::string& written, GltfForm form, AddExtras add_extras) {
  const auto dump = [](const nlohmann::json& json) {
    // Face ids of mesh files may hold bytes that are not UTF-8: replaced, not refused.
    return json.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  if (form == GltfForm::kText) {
    nlohmann::json json = nlohmann::json::parse(written);
    add_extras(json);
    return dump(json) + '\n';
  }
  const auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(written.at(at + k));
    return v;
  };
  const auto put_u32 = [](std::string& out, std::uint64_t v) {
    if (v > std::numeric_limits<std::uint32_t>::max()) {
      throw std::length_error("glTF export: a binary file of 4 GiB or more");
    }
    for (int k = 0; k < 4; ++k) out += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  // The header (magic, version, length), then the JSON chunk (length, "JSON", text).
  const std::size_t json_length = u32(12);
  nlohmann::json json = nlohmann::json::parse(written.substr(20, json_length));
  add_extras(json);
  std::string text = dump(json);
  text.append((4 - text.size() % 4) % 4, ' ');
  const std::string rest = written.substr(20 + json_length);
  std::string out = written.substr(0, 8);
  put_u32(out, 12 + 8 + std::uint64_t{text.size()} + rest.size());
  put_u32(out, text.size());
  out += written.substr(16, 4);
  out += text;
  out += rest;
  return out;
}

nlohmann::json pieces_json(const GltfPieces& pieces) {
  nlohmann::json out = {
      {"face", pieces.face}, {"first_triangle", pieces.first_triangle}, {"area", pieces.area}};
  if (!pieces.hours.empty()) out["hours"] = pieces.hours;
  return out;
}

// Every mesh's positions and indices, each kind in one buffer view: two views for the
// file, not two per mesh (a scene of many light sets has thousands of meshes).
struct MeshData {
  std::vector<float> positions;        // x, y, z relative to the origin, in glTF's axes
  std::vector<std::uint32_t> indices;  // 3 per triangle, into each mesh's own positions
  std::vector<float> faces;            // per triangle meshes' vertex, its face (_FACE)
  struct Span {
    std::size_t first_vertex = 0, vertices = 0, first_index = 0, count = 0;
    std::vector<double> least, most;  // of the float32 positions, as glTF's min and max
  };
  std::vector<Span> spans;  // per mesh written

  // The positions of `points` as one span, without indices.
  Span& add_positions(std::span<const glm::dvec3> points, const glm::dvec3& origin) {
    Span span;
    span.first_vertex = positions.size() / 3;
    span.vertices = points.size();
    span.first_index = indices.size();
    span.least.assign(3, std::numeric_limits<double>::infinity());
    span.most.assign(3, -std::numeric_limits<double>::infinity());
    for (const glm::dvec3& p : points) {
      const glm::dvec3 q = gltf_axes(p - origin);
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<float>(q[c]);
        positions.push_back(v);
        span.least[c] = std::min(span.least[c], static_cast<double>(v));
        span.most[c] = std::max(span.most[c], static_cast<double>(v));
      }
    }
    spans.push_back(std::move(span));
    return spans.back();
  }

  void add(const GltfMesh& mesh, const glm::dvec3& origin) {
    Span& span = add_positions(mesh.positions(), origin);
    span.count = mesh.indices().size();
    indices.insert(indices.end(), mesh.indices().begin(), mesh.indices().end());
    for (const std::size_t f : mesh.vertex_faces()) faces.push_back(static_cast<float>(f));
  }
};

// Appends `values` to the buffer as a buffer view (4-byte aligned, as every component here
// is 4 bytes) and returns the view's index.
template <typename T>
int add_view(tinygltf::Model& model, const std::vector<T>& values, int target, int stride) {
  static_assert(sizeof(T) == 4);
  std::vector<unsigned char>& data = model.buffers.front().data;
  const std::size_t bytes = values.size() * sizeof(T);
  if (bytes >= std::numeric_limits<std::uint32_t>::max() - data.size()) {
    throw std::length_error("glTF export: a buffer of 4 GiB or more");
  }
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = bytes;
  view.byteStride = static_cast<std::size_t>(stride);
  view.target = target;
  data.resize(data.size() + bytes);
  std::memcpy(data.data() + view.byteOffset, values.data(), bytes);
  model.bufferViews.push_back(std::move(view));
  return static_cast<int>(model.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& model, int view, std::size_t byte_offset, int component, int type,
                 std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = byte_offset;
  accessor.componentType = component;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(std::move(accessor));
  return static_cast<int>(model.accessors.size() - 1);
}

tinygltf::Material material_of(const GltfMaterial& m) {
  tinygltf::Material material;
  material.name = m.name;
  material.pbrMetallicRoughness.baseColorFactor = {linear_from_srgb(m.colour.r),
                                                   linear_from_srgb(m.colour.g),
                                                   linear_from_srgb(m.colour.b), 1.0};
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 1.0;
  material.doubleSided = true;
  material.extensions.emplace(kUnlit, tinygltf::Value(tinygltf::Value::Object()));
  return material;
}

}  // namespace

std::string gltf_file(const std::vector<GltfMaterial>& materials,
                      std::span<const glm::dvec3> outline_points, const glm::dvec3& origin,
                      const nlohmann::json& scene_extras, GltfForm form,
                      const GltfOptions& options) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "shadowgen";
  model.extensionsUsed.push_back(kUnlit);
  model.buffers.emplace_back();

  tinygltf::Node root;
  root.name = "shadowgen";
  const glm::dvec3 translation = gltf_axes(origin);
  root.translation = {translation.x, translation.y, translation.z};
  model.nodes.push_back(std::move(root));

  MeshData data;
  for (const GltfMaterial& m : materials) {
    if (!m.mesh.empty()) data.add(m.mesh, origin);
  }
  const bool outlines = options.outlines && !outline_points.empty();
  if (outlines) data.add_positions(outline_points, origin);
  // Vertex views shared by several accessors state their stride ("Buffers and Buffer
  // Views"); a view of indices has none.
  const int positions = data.spans.empty() ? -1 : add_view(model, data.positions, kArrayBuffer, 12);
  const int indices =
      data.indices.empty() ? -1 : add_view(model, data.indices, kElementArrayBuffer, 0);
  const int faces = options.face_attribute && !data.faces.empty()
                        ? add_view(model, data.faces, kArrayBuffer, 4)
                        : -1;
  std::size_t next = 0;
  for (const GltfMaterial& m : materials) {
    model.materials.push_back(material_of(m));
    if (m.mesh.empty()) continue;
    const MeshData::Span& span = data.spans[next++];
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = add_accessor(model, positions, 12 * span.first_vertex,
                                                    kFloat, TINYGLTF_TYPE_VEC3, span.vertices);
    model.accessors.back().minValues = span.least;
    model.accessors.back().maxValues = span.most;
    if (faces >= 0) {
      primitive.attributes["_FACE"] = add_accessor(model, faces, 4 * span.first_vertex, kFloat,
                                                   TINYGLTF_TYPE_SCALAR, span.vertices);
    }
    primitive.indices = add_accessor(model, indices, 4 * span.first_index, kUnsignedInt,
                                     TINYGLTF_TYPE_SCALAR, span.count);
    primitive.material = static_cast<int>(model.materials.size() - 1);
    primitive.mode = kTriangles;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(std::move(primitive));
    model.meshes.push_back(std::move(mesh));

    tinygltf::Node node;
    node.name = m.name;
    node.mesh = static_cast<int>(model.meshes.size() - 1);
    model.nodes.push_back(std::move(node));
    model.nodes.front().children.push_back(static_cast<int>(model.nodes.size() - 1));
  }
  if (outlines) {
    const MeshData::Span& span = data.spans.back();
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = add_accessor(model, positions, 12 * span.first_vertex,
                                                    kFloat, TINYGLTF_TYPE_VEC3, span.vertices);
    model.accessors.back().minValues = span.least;
    model.accessors.back().maxValues = span.most;
    primitive.mode = kLines;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(std::move(primitive));
    model.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.name = "outlines";
    node.mesh = static_cast<int>(model.meshes.size() - 1);
    model.nodes.push_back(std::move(node));
    model.nodes.front().children.push_back(static_cast<int>(model.nodes.size() - 1));
  }
  // A buffer must hold at least one byte: a model without triangles has none.
  if (model.buffers.front().data.empty()) model.buffers.clear();

  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false,
                                /*writeBinary=*/form == GltfForm::kBinary);
  return with_extras(std::move(out).str(), form, [&](nlohmann::json& json) {
    json["scenes"][0]["extras"] = scene_extras;
    std::size_t mesh = 0;
    for (std::size_t m = 0; m < materials.size(); ++m) {
      if (!materials[m].extras.is_null()) json["materials"][m]["extras"] = materials[m].extras;
      if (materials[m].mesh.empty()) continue;
      json["meshes"][mesh++]["extras"] = {{"pieces", pieces_json(materials[m].mesh.pieces())}};
    }
  });
}

}  // namespace shadowgen::output::detail
