#include "detail/epjson_objects.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "detail/idf_objects.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/number_text.h"

namespace shadowgen::energyplus::detail {
namespace {

constexpr std::string_view kIdfOrder = "idf_order";
constexpr const char* kAxes[] = {"x", "y", "z"};

// A value as text: a string as it is, a number in its shortest form.
std::string value_text(const JsonValue& value) {
  if (value.describe() == "a string") return value.string();
  if (value.describe() == "a number") return shortest(value.number());
  value.fail("expected a number or a string, found " + value.describe());
}

void read_fields(JsonObject& fields, InputObject& object) {
  for (const FieldSpec& field : object.spec->fields) {
    const std::optional<JsonValue> value = fields.find(field.key);
    if (!value) continue;
    std::string text = value_text(*value);
    if (text.empty()) continue;
    object.fields.emplace(std::string(field.key),
                          InputField{std::move(text), 0, std::string(field.key)});
  }
}

void add_coordinate(const JsonValue& value, const std::string& label, InputObject& object) {
  object.coordinates.push_back({value_text(value), 0, label});
}

void read_vertices(JsonObject& fields, InputObject& object) {
  if (object.spec->vertices == VertexFields::kExtensible) {
    const std::optional<JsonValue> list = fields.find("vertices");
    if (!list) return;
    const JsonArray vertices = list->array();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      JsonObject vertex = vertices.at(i).object();
      for (const char* axis : kAxes) {
        const std::string key = std::string("vertex_") + axis + "_coordinate";
        const std::string label = "vertices[" + std::to_string(i) + "]." + key;
        const std::optional<JsonValue> value = vertex.find(key);
        if (!value) vertex.value().fail("missing '" + key + "'");
        add_coordinate(*value, label, object);
      }
      vertex.finish();
    }
  } else if (object.spec->vertices == VertexFields::kFourAtMost) {
    for (int i = 1; i <= 4; ++i) {
      std::size_t given = 0;
      for (const char* axis : kAxes) {
        const std::string key = "vertex_" + std::to_string(i) + "_" + axis + "_coordinate";
        const std::optional<JsonValue> value = fields.find(key);
        if (!value) continue;
        ++given;
        add_coordinate(*value, key, object);
      }
      if (given != 0 && given != 3) {
        fields.value().fail("vertex " + std::to_string(i) + " gives " + std::to_string(given) +
                            " of its 3 coordinates");
      }
    }
  }
}

struct Ordered {
  double idf_order;
  std::size_t sequence;
  InputObject object;
};

}  // namespace

std::vector<InputObject> epjson_objects(std::string_view text, const std::string& file, bool strict,
                                        std::vector<std::string>& warnings) {
  const JsonDocument document(text, {file, strict, &warnings});
  JsonObject top = document.root().object();
  std::vector<Ordered> ordered;
  for (auto& [class_name, objects_value] : top.entries()) {
    const ClassSpec* spec = find_class(class_name);
    if (spec == nullptr) continue;
    JsonObject objects = objects_value.object();
    for (auto& [name, object_value] : objects.entries()) {
      JsonObject fields = object_value.object();
      InputObject object;
      object.spec = spec;
      if (spec->named) object.name = name;
      read_fields(fields, object);
      read_vertices(fields, object);
      double idf_order = std::numeric_limits<double>::infinity();
      if (const std::optional<JsonValue> order = fields.find(kIdfOrder)) {
        idf_order = order->number();
      }
      fields.finish();
      if (spec->kind == ObjectKind::kVersion) {
        const auto version = object.fields.find("version_identifier");
        if (version != object.fields.end()) (void)checked_version(version->second, file);
      }
      ordered.push_back({idf_order, ordered.size(), std::move(object)});
    }
  }
  std::stable_sort(ordered.begin(), ordered.end(),
                   [](const Ordered& a, const Ordered& b) { return a.idf_order < b.idf_order; });
  std::vector<InputObject> out;
  out.reserve(ordered.size());
  for (Ordered& o : ordered) out.push_back(std::move(o.object));
  return out;
}

}  // namespace shadowgen::energyplus::detail
