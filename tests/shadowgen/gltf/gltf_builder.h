#pragma once

// glTF 2.0 files written for tests, from the specification: binary data laid out in one
// buffer (each piece a buffer view, 4-byte aligned), accessors over it, and the JSON
// around them, as a .gltf whose buffer is a base64 data URI or an external file, or as a
// .glb (12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with zeros).
//
//   GltfBuilder b;
//   int positions = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
//   std::string text = b.gltf_embedded(R"("scenes": [{"nodes": [0]}], "nodes": [...], ...)");

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadowgen::test {

// Little-endian bytes of numbers, as glTF stores them.
std::string float_bytes(const std::vector<float>& values);
std::string u16_bytes(const std::vector<std::uint16_t>& values);
std::string u32_bytes(const std::vector<std::uint32_t>& values);
std::string base64(const std::string& bytes);

class GltfBuilder {
 public:
  // A buffer view over `bytes` (appended to the buffer; `stride` 0 for none); its index.
  int view(const std::string& bytes, int stride = 0);
  // An accessor with the given members besides bufferView ("\"componentType\": 5126,
  // \"count\": 3, \"type\": \"VEC3\""); view -1 for none. Its index.
  int accessor(int view, const std::string& members);
  // A VEC3 FLOAT accessor of `points`, with its own view.
  int positions(const std::vector<glm::vec3>& points);
  // A SCALAR UNSIGNED_SHORT accessor of `indices`, with its own view.
  int indices(const std::vector<std::uint16_t>& indices);

  const std::string& buffer() const { return buffer_; }

  // The whole file's JSON: asset, `members` (scenes, nodes, meshes, ...), the buffer
  // (its "uri" member `uri_member`, e.g. "\"uri\": \"data:...\"", or "" for a .glb's),
  // buffer views and accessors.
  std::string json(const std::string& members, const std::string& uri_member) const;
  // .gltf with the buffer as a base64 data URI.
  std::string gltf_embedded(const std::string& members) const;
  // .gltf whose buffer is the file `bin_name` (write buffer() there).
  std::string gltf_external(const std::string& members, const std::string& bin_name) const;
  // .glb with the buffer in its BIN chunk.
  std::string glb(const std::string& members) const;

 private:
  std::string buffer_;
  std::vector<std::string> views_;
  std::vector<std::string> accessors_;
};

}  // namespace shadowgen::test
