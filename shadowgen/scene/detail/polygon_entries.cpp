#include "detail/polygon_entries.h"

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

#include "detail/face_builder.h"
#include "detail/json_entities.h"
#include "hsr/parallel.h"
#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {
namespace {

// Polygons per task: a city's polygon (a wall, a roof) takes a few microseconds to parse
// and check, so a chunk is far above the cost of a task and far below a thread's share
// of a large scene.
constexpr std::size_t kPolygonsPerChunk = 256;

// Where a polygon's element stands in the document: the root object, then the array.
constexpr std::size_t kElementDepth = 2;

}  // namespace

std::string read_polygon_id(JsonObject& entry, const std::string& file) {
  std::string id = read_id(entry);
  if (id.find('/') != std::string::npos) {
    throw InputError(file, id, "a polygon id must not contain '/' (mesh face ids use it)");
  }
  return id;
}

Face read_polygon_face(JsonObject& entry, const std::string& id, const std::string& file,
                       bool strict, std::vector<std::string>& face_warnings) {
  entry.for_face(id);
  hsr::Polygon3 polygon = read_polygon(entry);
  entry.finish();
  return build_face(std::move(polygon), {id, file, FaceKind::kPolygon}, strict, face_warnings);
}

PolygonsRead read_polygon_texts(std::span<const std::string_view> texts, const std::string& file,
                                bool strict) {
  const std::size_t chunks = (texts.size() + kPolygonsPerChunk - 1) / kPolygonsPerChunk;
  std::vector<PolygonsRead> read(chunks);
  hsr::for_each_in_parallel(chunks, [&](std::size_t c) {
    PolygonsRead& out = read[c];
    const std::size_t first = c * kPolygonsPerChunk;
    const std::size_t last = std::min(texts.size(), first + kPolygonsPerChunk);
    for (std::size_t i = first; i < last; ++i) {
      const JsonDocument document(texts[i], {file, strict, &out.warnings},
                                  "polygons[" + std::to_string(i) + "]", kElementDepth);
      JsonObject entry = document.root().object();
      const std::string id = read_polygon_id(entry, file);
      out.face_warnings.emplace_back();
      out.faces.push_back(read_polygon_face(entry, id, file, strict, out.face_warnings.back()));
    }
  });
  PolygonsRead all;
  all.faces.reserve(texts.size());
  all.face_warnings.reserve(texts.size());
  for (PolygonsRead& chunk : read) {
    std::move(chunk.faces.begin(), chunk.faces.end(), std::back_inserter(all.faces));
    std::move(chunk.warnings.begin(), chunk.warnings.end(), std::back_inserter(all.warnings));
    std::move(chunk.face_warnings.begin(), chunk.face_warnings.end(),
              std::back_inserter(all.face_warnings));
  }
  return all;
}

}  // namespace shadowgen::scene::detail
