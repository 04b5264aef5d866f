#include "gltf_builder.h"

#include <cstring>

namespace shadowgen::test {
namespace {

template <class T>
std::string bytes_of(const std::vector<T>& values) {
  std::string bytes(values.size() * sizeof(T), '\0');
  if (!values.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

std::string word(std::uint32_t value) { return u32_bytes({value}); }

}  // namespace

std::string float_bytes(const std::vector<float>& values) { return bytes_of(values); }
std::string u16_bytes(const std::vector<std::uint16_t>& values) { return bytes_of(values); }
std::string u32_bytes(const std::vector<std::uint32_t>& values) { return bytes_of(values); }

std::string base64(const std::string& bytes) {
  static const char* const kDigits =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t group = 0;
    for (std::size_t j = 0; j < 3; ++j) {
      group = (group << 8) | (j < n ? static_cast<unsigned char>(bytes[i + j]) : 0u);
    }
    for (std::size_t j = 0; j < 4; ++j) {
      out += j <= n ? kDigits[(group >> (18 - 6 * j)) & 63] : '=';
    }
  }
  return out;
}

int GltfBuilder::view(const std::string& bytes, int stride) {
  while (buffer_.size() % 4 != 0) buffer_ += '\0';
  std::string v = "{\"buffer\": 0, \"byteOffset\": " + std::to_string(buffer_.size()) +
                  ", \"byteLength\": " + std::to_string(bytes.size());
  if (stride != 0) v += ", \"byteStride\": " + std::to_string(stride);
  views_.push_back(v + "}");
  buffer_ += bytes;
  return static_cast<int>(views_.size()) - 1;
}

int GltfBuilder::accessor(int view, const std::string& members) {
  std::string a = "{";
  if (view >= 0) a += "\"bufferView\": " + std::to_string(view) + ", ";
  accessors_.push_back(a + members + "}");
  return static_cast<int>(accessors_.size()) - 1;
}

int GltfBuilder::positions(const std::vector<glm::vec3>& points) {
  std::vector<float> values;
  for (const glm::vec3& p : points) values.insert(values.end(), {p.x, p.y, p.z});
  return accessor(view(float_bytes(values)),
                  "\"componentType\": 5126, \"count\": " + std::to_string(points.size()) +
                      ", \"type\": \"VEC3\"");
}

int GltfBuilder::indices(const std::vector<std::uint16_t>& values) {
  return accessor(view(u16_bytes(values)),
                  "\"componentType\": 5123, \"count\": " + std::to_string(values.size()) +
                      ", \"type\": \"SCALAR\"");
}

std::string GltfBuilder::json(const std::string& members, const std::string& uri_member) const {
  std::string text = "{\"asset\": {\"version\": \"2.0\"}, " + members;
  text += ", \"buffers\": [{" + uri_member + (uri_member.empty() ? "" : ", ") +
          "\"byteLength\": " + std::to_string(buffer_.size()) + "}]";
  auto list = [](const std::vector<std::string>& items) {
    std::string out = "[";
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? ", " : "") + items[i];
    return out + "]";
  };
  text += ", \"bufferViews\": " + list(views_) + ", \"accessors\": " + list(accessors_) + "}";
  return text;
}

std::string GltfBuilder::gltf_embedded(const std::string& members) const {
  return json(members, "\"uri\": \"data:application/octet-stream;base64," + base64(buffer_) + "\"");
}

std::string GltfBuilder::gltf_external(const std::string& members,
                                       const std::string& bin_name) const {
  return json(members, "\"uri\": \"" + bin_name + "\"");
}

std::string GltfBuilder::glb(const std::string& members) const {
  std::string json_chunk = json(members, "");
  while (json_chunk.size() % 4 != 0) json_chunk += ' ';
  std::string bin_chunk = buffer_;
  while (bin_chunk.size() % 4 != 0) bin_chunk += '\0';
  const auto total = static_cast<std::uint32_t>(12 + 8 + json_chunk.size() + 8 + bin_chunk.size());
  return "glTF" + word(2) + word(total) + word(static_cast<std::uint32_t>(json_chunk.size())) +
         "JSON" + json_chunk + word(static_cast<std::uint32_t>(bin_chunk.size())) +
         std::string("BIN\0", 4) + bin_chunk;
}

}  // namespace shadowgen::test
