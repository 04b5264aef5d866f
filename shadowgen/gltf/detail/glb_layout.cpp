#include "detail/glb_layout.h"

#include <bit>
#include <cstdint>
#include <cstring>

#include "shadowgen/model/input_error.h"

namespace shadowgen::gltf::detail {
namespace {

static_assert(std::endian::native == std::endian::little,
              "glTF's binary data is little-endian, read here as the machine's own");

constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;

std::uint32_t word_at(std::string_view bytes, std::size_t offset) {
  std::uint32_t word = 0;
  std::memcpy(&word, bytes.data() + offset, sizeof word);
  return word;
}

}  // namespace

bool is_glb(std::string_view bytes) { return bytes.starts_with("glTF"); }

GlbChunks glb_chunks(std::string_view bytes, const std::string& file) {
  auto refuse = [&file](const std::string& problem) -> void {
    throw InputError(file, "", "not a well-formed binary glTF file: " + problem);
  };
  if (bytes.size() < kHeaderBytes + kChunkHeaderBytes) {
    refuse("is truncated: " + std::to_string(bytes.size()) +
           " bytes, fewer than the 20 of its header and first chunk header");
  }
  const std::uint32_t version = word_at(bytes, 4);
  if (version != 2) refuse("version " + std::to_string(version) + ", not 2");
  const std::uint64_t length = word_at(bytes, 8);
  if (length != bytes.size()) {
    refuse(std::string(length > bytes.size() ? "is truncated: " : "has bytes after its end: ") +
           "its header gives a length of " + std::to_string(length) + " bytes, the file has " +
           std::to_string(bytes.size()));
  }
  GlbChunks chunks;
  std::size_t offset = kHeaderBytes;
  for (int index = 0; offset < length; ++index) {
    if (length - offset < kChunkHeaderBytes) {
      refuse("chunk " + std::to_string(index) + " at byte " + std::to_string(offset) +
             " has no room for its 8-byte header");
    }
    const std::uint64_t chunk_length = word_at(bytes, offset);
    const std::uint32_t type = word_at(bytes, offset + 4);
    offset += kChunkHeaderBytes;
    if (chunk_length > length - offset) {
      refuse("chunk " + std::to_string(index) + " gives a length of " +
             std::to_string(chunk_length) + " bytes, only " + std::to_string(length - offset) +
             " follow its header");
    }
    const std::string_view data = bytes.substr(offset, chunk_length);
    if (index == 0) {
      if (type != kJsonChunk) refuse("its first chunk is not of type JSON");
      chunks.json = data;
    } else if (index == 1 && type == kBinChunk) {
      chunks.bin = data;
    } else if (index == 1) {
      // tinygltf reads the chunk after the JSON chunk as BIN, whatever the specification
      // says of chunks of unknown types (to be ignored): such a file is refused here.
      refuse("its second chunk is not of type BIN");
    }
    offset += chunk_length;
  }
  if (chunks.json.empty()) refuse("its JSON chunk is empty");
  return chunks;
}

}  // namespace shadowgen::gltf::detail
