#include "tests/support/gltf_file.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <glm/geometric.hpp>
#include <iterator>

namespace shadowgen::test {
namespace {

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);  // little-endian, as the machine is
  return v;
}

std::vector<unsigned char> base64(const std::string& text, std::vector<std::string>& errors) {
  static const std::string kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> out;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t v = kAlphabet.find(c);
    if (v == std::string::npos) {
      errors.push_back("not base64");
      return {};
    }
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 0xff));
    }
  }
  return out;
}

// The bytes of accessor `a`, checked to lie in the buffer; empty on an error.
const unsigned char* accessor_bytes(GltfFile& file, int a, int component_type, const char* type,
                                    std::size_t& count) {
  const nlohmann::json& accessor = file.json.at("accessors").at(a);
  if (accessor.at("componentType") != component_type || accessor.at("type") != type) {
    file.errors.push_back("accessor " + std::to_string(a) + " is not " + type);
    return nullptr;
  }
  const nlohmann::json& view = file.json.at("bufferViews").at(accessor.at("bufferView").get<int>());
  const std::size_t in_view = accessor.value("byteOffset", std::size_t{0});
  const std::size_t offset = view.value("byteOffset", std::size_t{0}) + in_view;
  count = accessor.at("count").get<std::size_t>();
  const std::size_t element = std::string(type) == "VEC3" ? 12 : 4;
  if (view.value("byteStride", element) != element) {
    file.errors.push_back("accessor " + std::to_string(a) + " is not tightly packed");
    return nullptr;
  }
  const std::size_t size = count * element;
  if (offset + size > file.buffer.size() ||
      in_view + size > view.at("byteLength").get<std::size_t>()) {
    file.errors.push_back("accessor " + std::to_string(a) + " runs past its buffer");
    return nullptr;
  }
  return file.buffer.data() + offset;
}

std::vector<glm::dvec3> vec3s(GltfFile& file, int a) {
  std::size_t count = 0;
  const unsigned char* bytes = accessor_bytes(file, a, 5126, "VEC3", count);
  std::vector<glm::dvec3> out;
  if (bytes == nullptr) return out;
  for (std::size_t i = 0; i < count; ++i) {
    float v[3];
    std::memcpy(v, bytes + 12 * i, 12);
    out.emplace_back(v[0], v[1], v[2]);
  }
  return out;
}

const nlohmann::json& primitive(GltfFile& file, std::size_t mesh) {
  return file.json.at("meshes").at(mesh).at("primitives").at(0);
}

}  // namespace

GltfFile parse_gltf(const std::string& bytes) {
  GltfFile file;
  std::string json_text;
  if (bytes.size() >= 12 && bytes.compare(0, 4, "glTF") == 0) {
    if (u32(bytes, 4) != 2 || u32(bytes, 8) != bytes.size()) {
      file.errors.push_back("a GLB header not of version 2 or not its length");
      return file;
    }
    std::size_t at = 12;
    while (at + 8 <= bytes.size()) {
      const std::uint32_t length = u32(bytes, at), type = u32(bytes, at + 4);
      if (at + 8 + length > bytes.size()) {
        file.errors.push_back("a chunk runs past the file");
        return file;
      }
      if (type == 0x4E4F534A) json_text = bytes.substr(at + 8, length);
      if (type == 0x004E4942) {
        file.buffer.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at + 8),
                           bytes.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
      }
      at += 8 + length;
    }
  } else {
    json_text = bytes;
  }
  try {
    file.json = nlohmann::json::parse(json_text);
  } catch (const std::exception& e) {
    file.errors.push_back(std::string("JSON: ") + e.what());
    return file;
  }
  if (file.json.contains("buffers") && file.json["buffers"].size() > 0) {
    const nlohmann::json& buffer = file.json["buffers"][0];
    if (buffer.contains("uri")) {
      const std::string uri = buffer["uri"];
      const std::string prefix = "data:application/octet-stream;base64,";
      if (uri.compare(0, prefix.size(), prefix) != 0) {
        file.errors.push_back("a buffer URI that is not an embedded one");
      } else {
        file.buffer = base64(uri.substr(prefix.size()), file.errors);
      }
    }
    if (file.buffer.size() < buffer.at("byteLength").get<std::size_t>()) {
      file.errors.push_back("a buffer shorter than its byteLength");
    }
  }
  return file;
}

std::vector<GltfTriangle> mesh_triangles(GltfFile& file, std::size_t mesh) {
  const nlohmann::json& p = primitive(file, mesh);
  std::vector<GltfTriangle> triangles;
  if (p.value("mode", 4) != 4) {
    file.errors.push_back("a primitive not of TRIANGLES");
    return triangles;
  }
  const std::vector<glm::dvec3> positions = vec3s(file, p.at("attributes").at("POSITION"));
  std::size_t count = 0;
  const unsigned char* bytes = accessor_bytes(file, p.at("indices"), 5125, "SCALAR", count);
  if (bytes == nullptr) return triangles;
  for (std::size_t t = 0; t + 3 <= count; t += 3) {
    GltfTriangle triangle;
    for (std::size_t k = 0; k < 3; ++k) {
      std::uint32_t index = 0;
      std::memcpy(&index, bytes + 4 * (t + k), 4);
      if (index >= positions.size()) {
        file.errors.push_back("an index past the positions");
        return triangles;
      }
      triangle[k] = positions[index];
    }
    triangles.push_back(triangle);
  }
  return triangles;
}

std::vector<double> mesh_scalars(GltfFile& file, std::size_t mesh, const std::string& attribute) {
  const nlohmann::json& attributes = primitive(file, mesh).at("attributes");
  std::vector<double> out;
  if (!attributes.contains(attribute)) {
    file.errors.push_back("mesh " + std::to_string(mesh) + " has no " + attribute);
    return out;
  }
  std::size_t count = 0;
  const unsigned char* bytes = accessor_bytes(file, attributes[attribute], 5126, "SCALAR", count);
  if (bytes == nullptr) return out;
  for (std::size_t i = 0; i < count; ++i) {
    float v = 0.0f;
    std::memcpy(&v, bytes + 4 * i, 4);
    out.push_back(v);
  }
  return out;
}

std::vector<std::array<glm::dvec3, 2>> mesh_lines(GltfFile& file, std::size_t mesh) {
  const nlohmann::json& p = primitive(file, mesh);
  std::vector<std::array<glm::dvec3, 2>> lines;
  if (p.value("mode", 4) != 1 || p.contains("indices")) {
    file.errors.push_back("a primitive not of LINES without indices");
    return lines;
  }
  const std::vector<glm::dvec3> positions = vec3s(file, p.at("attributes").at("POSITION"));
  for (std::size_t i = 0; i + 1 < positions.size(); i += 2) {
    lines.push_back({positions[i], positions[i + 1]});
  }
  return lines;
}

glm::dvec3 mesh_translation(GltfFile& file, std::size_t mesh) {
  const nlohmann::json& nodes = file.json.at("nodes");
  // The path from the node holding the mesh up to a root.
  std::vector<std::size_t> parent(nodes.size(), nodes.size());
  std::size_t holder = nodes.size();
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    for (const auto& child : nodes[n].value("children", nlohmann::json::array())) {
      parent.at(child.get<std::size_t>()) = n;
    }
    if (nodes[n].value("mesh", -1) == static_cast<int>(mesh)) holder = n;
  }
  glm::dvec3 t(0.0);
  if (holder == nodes.size()) {
    file.errors.push_back("no node holds mesh " + std::to_string(mesh));
    return t;
  }
  for (std::size_t n = holder; n != nodes.size(); n = parent[n]) {
    if (nodes[n].contains("rotation") || nodes[n].contains("scale") ||
        nodes[n].contains("matrix")) {
      file.errors.push_back("a node with more than a translation");
    }
    if (nodes[n].contains("translation")) {
      const auto& v = nodes[n]["translation"];
      t += glm::dvec3(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    }
  }
  return t;
}

double triangle_area(const GltfTriangle& t) {
  return 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
}

std::map<std::string, double> material_areas(GltfFile& file) {
  std::map<std::string, double> areas;
  if (!file.json.contains("meshes")) return areas;
  for (std::size_t m = 0; m < file.json["meshes"].size(); ++m) {
    if (primitive(file, m).value("mode", 4) == 1) continue;  // lines
    const int material = primitive(file, m).at("material");
    const std::string name = file.json.at("materials").at(material).at("name");
    double area = 0.0;
    for (const GltfTriangle& t : mesh_triangles(file, m)) area += triangle_area(t);
    areas[name] += area;
  }
  return areas;
}

void keep_for_validator(const std::string& bytes, const std::string& extension) {
  const char* folder = std::getenv("SHADOWGEN_GLTF_KEEP");
  if (folder == nullptr || *folder == '\0') return;
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string stem =
      test == nullptr ? "file" : std::string(test->test_suite_name()) + "." + test->name();
  for (char& c : stem) {
    if (c == '/') c = '-';
  }
  for (int n = 1;; ++n) {
    const std::filesystem::path path =
        std::filesystem::path(folder) / (stem + "-" + std::to_string(n) + extension);
    if (std::filesystem::exists(path)) continue;
    std::ofstream(path, std::ios::binary) << bytes;
    return;
  }
}

void keep_file_for_validator(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  keep_for_validator(std::string(std::istreambuf_iterator<char>(in), {}),
                     file.extension().string());
}

}  // namespace shadowgen::test
