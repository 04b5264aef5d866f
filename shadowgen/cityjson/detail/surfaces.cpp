#include "detail/surfaces.h"

namespace shadowgen::cityjson::detail {
namespace {

// The names of the levels from the top of the boundaries down, for messages.
const char* level_name(int levels_above, int level) {
  static const char* const kNames[] = {"a solid", "a shell", "a surface", "a ring",
                                       "a vertex index"};
  return kNames[2 - levels_above + level];
}

class SurfaceReader {
 public:
  SurfaceReader(GeometryType type, const VertexRange& vertices, std::size_t semantic_count,
                std::vector<Surface>& out)
      : type_(type),
        levels_above_(levels_above_surfaces(type)),
        vertices_(vertices),
        semantic_count_(semantic_count),
        out_(out) {}

  // `elements` stand at `level` (0: the boundaries' elements); `values` are the semantic
  // values of the array holding them, null where there are none.
  void read(const JsonArray& elements, int level, const std::optional<JsonValue>& values) {
    std::optional<JsonArray> value_elements;
    if (values && !values->is_null()) {
      if (!values->is_array()) {
        values->fail("expected an array of semantic values (or null), found " + values->describe());
      }
      value_elements = values->array();
      if (value_elements->size() != elements.size()) {
        values->fail("holds " + std::to_string(value_elements->size()) +
                     " semantic values for the " + std::to_string(elements.size()) + " " +
                     plural(level) + " of the boundaries");
      }
    }
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const JsonValue element = elements.at(i);
      std::optional<JsonValue> element_values;
      if (value_elements) element_values = value_elements->at(i);
      if (level < levels_above_) {
        read(expect_array(element, level), level + 1, element_values);
      } else {
        read_surface(element, element_values);
      }
    }
  }

 private:
  void read_surface(const JsonValue& node, const std::optional<JsonValue>& value) {
    const int level = levels_above_;  // the surface's; its rings stand one below
    Surface surface;
    if (value && !value->is_null()) {
      if (value->is_array()) {
        value->fail("expected a semantic surface index (or null) for a surface, found an array");
      }
      const std::size_t index = value->index();
      if (index >= semantic_count_) {
        value->fail("semantic surface index " + std::to_string(index) +
                    " is out of range: semantics.surfaces has " + std::to_string(semantic_count_));
      }
      surface.semantic = index;
    }
    const JsonArray rings = expect_array(node, level);
    if (rings.empty()) node.fail("a surface needs an exterior ring; this one has no ring");
    surface.rings.reserve(rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      const JsonArray ring = expect_array(rings.at(r), level + 1);
      if (ring.empty()) rings.at(r).fail("a ring needs vertices; this one is empty");
      std::vector<std::size_t> indices;
      indices.reserve(ring.size());
      for (std::size_t v = 0; v < ring.size(); ++v) {
        const JsonValue index_value = ring.at(v);
        if (index_value.is_array()) wrong_depth(index_value, level + 2);
        const std::size_t index = index_value.index();
        if (index >= vertices_.count) {
          index_value.fail("vertex index " + std::to_string(index) + " is out of range: " +
                           vertices_.owner + " " + std::to_string(vertices_.count) + " vertices");
        }
        indices.push_back(index);
      }
      surface.rings.push_back(std::move(indices));
    }
    out_.push_back(std::move(surface));
  }

  // `node`, which stands at `level`, as an array of what stands at level + 1.
  JsonArray expect_array(const JsonValue& node, int level) const {
    if (!node.is_array()) wrong_depth(node, level);
    return node.array();
  }

  [[noreturn]] void wrong_depth(const JsonValue& node, int level) const {
    const std::string expected = level_name(levels_above_, level);
    const bool index = level == levels_above_ + 2;
    node.fail("expected " + expected + (index ? "" : " (an array)") + ", found " + node.describe() +
              ": a " + std::string(geometry_type_name(type_)) + "'s boundaries are " +
              boundaries_shape(type_));
  }

  std::string plural(int level) const {
    const std::string name = level_name(levels_above_, level);
    return name.substr(name.find(' ') + 1) + "s";
  }

  GeometryType type_;
  int levels_above_;
  const VertexRange& vertices_;
  std::size_t semantic_count_;
  std::vector<Surface>& out_;
};

}  // namespace

std::vector<Surface> read_surfaces(GeometryType type, const JsonValue& boundaries,
                                   const VertexRange& vertices, const JsonValue* semantic_values,
                                   std::size_t semantic_count) {
  std::vector<Surface> out;
  SurfaceReader reader(type, vertices, semantic_count, out);
  std::optional<JsonValue> values;
  if (semantic_values != nullptr) values = *semantic_values;
  if (!boundaries.is_array()) {
    boundaries.fail("expected an array of " + boundaries_shape(type) + ", found " +
                    boundaries.describe());
  }
  reader.read(boundaries.array(), 0, values);
  return out;
}

}  // namespace shadowgen::cityjson::detail
