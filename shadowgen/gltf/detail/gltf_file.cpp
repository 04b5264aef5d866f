#include "detail/gltf_file.h"

#include <algorithm>
#include <array>
#include <climits>
#include <exception>
#include <optional>
#include <string_view>

#include "detail/glb_layout.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::gltf::detail {
namespace {

// Extensions a file may require that change no geometry, so that its faces read the same
// without them: materials, textures, lights, metadata. KHR_mesh_quantization is read.
bool read_past(std::string_view extension) {
  static constexpr std::array<std::string_view, 8> kNames = {
      kMeshQuantization,  "KHR_texture_transform", "KHR_texture_basisu", "EXT_texture_webp",
      "EXT_texture_avif", "KHR_lights_punctual",   "KHR_xmp_json_ld",    "MSFT_texture_dds"};
  return extension.starts_with("KHR_materials_") ||
         std::find(kNames.begin(), kNames.end(), extension) != kNames.end();
}

// What an extension that moves or compresses geometry does, for the message refusing it.
std::string refused_extension(std::string_view extension) {
  if (extension == "KHR_draco_mesh_compression") return "Draco-compressed meshes";
  if (extension == "EXT_meshopt_compression" || extension == "KHR_meshopt_compression") {
    return "meshoptimizer-compressed buffers";
  }
  if (extension == "EXT_mesh_gpu_instancing") return "meshes instanced per node";
  return "an extension shadowgen does not know";
}

// What the JSON says before tinygltf reads it: checked as every shadowgen JSON input is
// (repeated keys, numbers beyond a double), the extensions required, and how many
// buffers tinygltf will read from files (so that the file reads after theirs, images,
// are refused).
struct BufferFile {
  std::size_t index = 0;        // in the file's buffers
  std::size_t byte_length = 0;  // its byteLength
};

struct JsonFacts {
  std::vector<BufferFile> buffer_files;  // the buffers read from files, in order
  bool quantized_positions = false;
};

JsonFacts check_json(std::string_view json, const std::string& file,
                     std::vector<std::string>& warnings) {
  JsonDocument document(json, {.file = file, .strict = false, .warnings = &warnings});
  if (!document.root().is_object()) {
    document.root().fail("expected an object, found " + document.root().describe());
  }
  JsonObject top = document.root().object();
  JsonObject asset = top.get("asset").object();
  const JsonValue version = asset.get("version");
  const std::string version_text = version.string();
  if (!version_text.starts_with("2.")) {
    version.fail("'" + version_text + "': shadowgen reads glTF 2.0");
  }
  JsonFacts facts;
  if (std::optional<JsonValue> required = top.find("extensionsRequired")) {
    JsonArray list = required->array();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string name = list.at(i).string();
      if (!read_past(name)) {
        list.at(i).fail("the file requires '" + name + "' (" + refused_extension(name) +
                        "), which shadowgen does not read");
      }
    }
  }
  if (std::optional<JsonValue> used = top.find("extensionsUsed")) {
    JsonArray list = used->array();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string name = list.at(i).string();
      if (name == kMeshQuantization) facts.quantized_positions = true;
      if (name == "EXT_mesh_gpu_instancing") {
        list.at(i).warn(
            "'EXT_mesh_gpu_instancing' is not read: a node's mesh is placed once, at the "
            "node, without its instances");
      }
    }
  }
  if (std::optional<JsonValue> buffers = top.find("buffers")) {
    JsonArray list = buffers->array();
    for (std::size_t i = 0; i < list.size(); ++i) {
      JsonObject buffer = list.at(i).object();
      if (std::optional<JsonValue> uri = buffer.find("uri")) {
        const std::string text = uri->string();
        if (tinygltf::IsDataURI(text)) continue;
        // tinygltf would take any other data: URI for a file's name.
        if (text.starts_with("data:")) {
          uri->fail(
              "a data: URI of a buffer is base64, of media type application/octet-stream or "
              "application/gltf-buffer (the specification's), which this one is not");
        }
        facts.buffer_files.push_back({i, buffer.get("byteLength").index()});
      }
    }
  }
  return facts;
}

// tinygltf's file access, limited to what shadowgen reads: the buffer files, next to the
// glTF file. Images come after the buffers in tinygltf's order and are refused (tinygltf
// then keeps an image's uri and warns, which is dropped). A file's problem is kept, to
// be reported whole instead of tinygltf's wording.
struct FileAccess {
  std::string folder_prefix;  // the glTF file's folder, ending in '/'
  std::vector<BufferFile> buffer_files;
  std::size_t buffer_files_read = 0;
  std::optional<std::string> problem;
};

// Every path next to the glTF file "exists", so that read_whole_file says why one that
// is not there, or is no regular file, cannot be read; tinygltf's second try, the working
// folder, does not.
bool file_exists(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  return path.starts_with(access->folder_prefix);
}

std::string expand_file_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  auto* access = static_cast<FileAccess*>(user);
  if (access->buffer_files_read == access->buffer_files.size()) {
    if (err) *err += "not read: shadowgen reads no images";
    return false;
  }
  const BufferFile& buffer = access->buffer_files[access->buffer_files_read++];
  const std::string label = "buffers[" + std::to_string(buffer.index) + "]: file " + path;
  try {
    const std::string bytes = read_text_file(path, "glTF buffer file");
    // The specification's rule: the file holds at least byteLength bytes; those are the
    // buffer (tinygltf would want exactly as many).
    if (bytes.size() < buffer.byte_length) {
      access->problem = label + " has " + std::to_string(bytes.size()) +
                        " bytes, fewer than the buffer's byteLength of " +
                        std::to_string(buffer.byte_length);
      return false;
    }
    out->assign(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(buffer.byte_length));
    return true;
  } catch (const InputError& e) {
    access->problem = label + ": " + e.problem();
    return false;
  }
}

bool write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&,
                      void*) {
  if (err) *err += "shadowgen writes no glTF files";
  return false;
}

bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

// tinygltf's messages, one line each, joined.
std::string joined_lines(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ';');
  return text;
}

}  // namespace

GltfFile load_gltf_file(const std::filesystem::path& file, std::vector<std::string>& warnings) {
  const std::string name = file.string();
  const std::string bytes = read_text_file(file, "glTF file");
  if (bytes.size() > UINT_MAX) {
    throw InputError(name, "", "is larger than tinygltf reads (4 GiB, the most a .glb holds)");
  }
  const bool binary = is_glb(bytes);
  const std::string_view json = binary ? glb_chunks(bytes, name).json : std::string_view(bytes);
  const JsonFacts facts = check_json(json, name, warnings);

  FileAccess access;
  const std::filesystem::path parent = file.parent_path();
  const std::string folder = parent.empty() ? std::string(".") : parent.string();
  access.folder_prefix = folder;
  if (!folder.ends_with('/')) access.folder_prefix.push_back('/');
  access.buffer_files = facts.buffer_files;
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(
      {&file_exists, &expand_file_path, &read_whole_file, &write_whole_file, &access});
  loader.SetImageLoader(&skip_image, nullptr);

  GltfFile loaded;
  loaded.quantized_positions = facts.quantized_positions;
  std::string err, warn;
  bool ok = false;
  try {
    const auto size = static_cast<unsigned int>(bytes.size());
    ok = binary ? loader.LoadBinaryFromMemory(&loaded.model, &err, &warn,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              size, folder, tinygltf::REQUIRE_VERSION)
                : loader.LoadASCIIFromString(&loaded.model, &err, &warn, bytes.data(), size, folder,
                                             tinygltf::REQUIRE_VERSION);
  } catch (const std::exception& e) {  // tinygltf's own checks throw in places (vector::at)
    err = e.what();
  }
  if (access.problem) throw InputError(name, "", *access.problem);
  if (!ok) throw InputError(name, "", "not a readable glTF file: " + joined_lines(err));
  return loaded;
}

}  // namespace shadowgen::gltf::detail
