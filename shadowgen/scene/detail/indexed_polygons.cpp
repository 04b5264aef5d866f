#include "indexed_polygons.h"

#include <optional>
#include <string>

#include "coordinate_range.h"
#include "shadowgen/database/database_format.h"

namespace shadowgen::scene::detail {
namespace {

namespace key = database::key;

// [i, ...]: indices into a table of `size`.
std::vector<std::size_t> read_indices(const JsonValue& value, std::size_t size, const char* table) {
  const JsonArray list = value.array();
  std::vector<std::size_t> out;
  out.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) {
    const JsonValue index = list.at(k);
    out.push_back(index.index());
    if (out.back() >= size) {
      index.fail("expected the index of one of the face's " + std::to_string(size) + " " + table);
    }
  }
  return out;
}

hsr::Loop3 read_loop(const JsonValue& value, const std::vector<glm::dvec3>& vertices) {
  hsr::Loop3 loop;
  for (const std::size_t i : read_indices(value, vertices.size(), "vertices")) {
    loop.push_back(vertices[i]);
  }
  return loop;
}

}  // namespace

std::vector<glm::dvec3> read_face_vertices(JsonObject& face) {
  std::vector<glm::dvec3> vertices;
  const std::optional<JsonValue> numbers_value = face.find(key::kNumbers);
  const std::optional<JsonValue> vertices_value = face.find(key::kVertices);
  if (!numbers_value && !vertices_value) return vertices;
  if (!numbers_value || !vertices_value) {
    face.value().fail("\"numbers\" and \"vertices\" come together");
  }
  const JsonArray list = numbers_value->array();
  std::vector<double> numbers;
  numbers.reserve(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) numbers.push_back(list.at(k).number());
  const std::vector<std::size_t> triples = read_indices(*vertices_value, numbers.size(), "numbers");
  if (triples.size() % 3 != 0) {
    vertices_value->fail("expected three numbers per vertex, found " +
                         std::to_string(triples.size()) + " indices");
  }
  vertices.reserve(triples.size() / 3);
  for (std::size_t k = 0; k < triples.size(); k += 3) {
    vertices.push_back({numbers[triples[k]], numbers[triples[k + 1]], numbers[triples[k + 2]]});
    if (const std::optional<std::string> problem = coordinate_problem(vertices.back())) {
      vertices_value->fail("vertex " + std::to_string(k / 3) + ": " + *problem);
    }
  }
  return vertices;
}

LitPolygon read_indexed_lit(const JsonValue& value, const std::vector<glm::dvec3>& vertices,
                            std::size_t parts) {
  LitPolygon lit;
  std::optional<JsonObject> object;
  JsonValue loops_value = value;
  if (parts > 1) {
    object.emplace(value.object());
    const JsonValue part = object->get(key::kPart);
    lit.part = part.index();
    if (lit.part >= parts) {
      part.fail("expected the index of one of the face's " + std::to_string(parts) + " parts");
    }
    loops_value = object->get(key::kLoops);
  }
  const JsonArray loops = loops_value.array();
  if (loops.empty()) loops_value.fail("a polygon needs its outer loop");
  lit.polygon.outer = read_loop(loops.at(0), vertices);
  for (std::size_t k = 1; k < loops.size(); ++k) {
    lit.polygon.holes.push_back(read_loop(loops.at(k), vertices));
  }
  if (object) object->finish();
  return lit;
}

}  // namespace shadowgen::scene::detail
