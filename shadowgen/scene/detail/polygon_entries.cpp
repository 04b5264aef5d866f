#include "detail/polygon_entries.h"

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

#include "detail/face_builder.h"
#include "detail/json_entities.h"
#include "hsr/concatenated.h"
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
  // The chunks joined in order, the faces and their warnings moved on the threads.
  PolygonsRead all;
  std::vector<std::vector<Face>> faces(chunks);
  std::vector<std::vector<std::vector<std::string>>> face_warnings(chunks);
  for (std::size_t c = 0; c < chunks; ++c) {
    faces[c] = std::move(read[c].faces);
    face_warnings[c] = std::move(read[c].face_warnings);
    std::move(read[c].warnings.begin(), read[c].warnings.end(), std::back_inserter(all.warnings));
  }
  all.faces = hsr::concatenated(std::move(faces));
  all.face_warnings = hsr::concatenated(std::move(face_warnings));
  return all;
}

}  // namespace shadowgen::scene::detail
