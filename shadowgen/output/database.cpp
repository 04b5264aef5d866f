#include "shadowgen/output/database.h"

#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "shadowgen/json/document.h"
#include "shadowgen/json/json_text.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

using detail::append_json_number;
using detail::append_json_string;
using hsr::Loop3;
using hsr::Polygon3;
using Json = nlohmann::json;

// What the format cannot hold is refused before a byte is written, so that every file
// written reads back.
class WriteCheck {
 public:
  explicit WriteCheck(std::string owner) : owner_(std::move(owner)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("shadowed database: " + owner_ + ": " + what);
  }
  void finite(double value, const char* what) const {
    if (!std::isfinite(value)) fail(std::string(what) + " is not a finite number");
  }
  void finite(const glm::dvec3& v, const char* what) const {
    for (int i = 0; i < 3; ++i) finite(v[i], what);
  }
  void loop(const Loop3& loop) const {
    if (loop.size() < 3) fail("a loop has fewer than three vertices");
    for (const glm::dvec3& p : loop) finite(p, "a vertex coordinate");
  }
  void polygons(std::span<const Polygon3> polygons) const {
    for (const Polygon3& polygon : polygons) {
      loop(polygon.outer);
      for (const Loop3& hole : polygon.holes) loop(hole);
    }
  }

 private:
  std::string owner_;
};

// Faces, lights and views: each kind's ids are unique (lit details are keyed by light id).
template <class Item>
void check_unique_ids(const std::vector<Item>& items, const char* kind) {
  std::unordered_set<std::string_view> seen;
  for (const Item& item : items) {
    if (!seen.insert(item.id).second) {
      throw std::invalid_argument(std::string("shadowed database: duplicate ") + kind + " id '" +
                                  item.id + "'");
    }
  }
}

void check_writable(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene;
  check_unique_ids(scene.faces, "face");
  check_unique_ids(scene.lights, "light");
  check_unique_ids(scene.views, "view");
  if (shadowed.lit.size() != scene.faces.size()) {
    throw std::invalid_argument("shadowed database: lit details for " +
                                std::to_string(shadowed.lit.size()) + " faces, the scene has " +
                                std::to_string(scene.faces.size()));
  }
  for (const Light& light : scene.lights) {
    const WriteCheck check("light '" + light.id + "'");
    check.finite(light.direction, "direction");
    check.finite(light.position, "position");
    check.finite(light.intensity, "intensity");
    if (light.range) {
      check.finite(light.range->falloff_start, "range.falloff_start");
      check.finite(light.range->end, "range.end");
      check.finite(light.range->exponent, "range.exponent");
    }
  }
  for (const ViewSpec& view : scene.views) {
    const WriteCheck check("view '" + view.id + "'");
    check.finite(view.eye, "eye");
    check.finite(view.target, "target");
    check.finite(view.up, "up");
    check.finite(view.fov_deg, "fov_deg");
  }
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    const WriteCheck check("face '" + scene.faces[f].id + "'");
    if (scene.faces[f].parts.empty()) check.fail("the face has no parts");
    check.polygons(scene.faces[f].parts);
    if (shadowed.lit[f].size() != scene.lights.size()) {
      check.fail("lit details for " + std::to_string(shadowed.lit[f].size()) +
                 " lights, the scene has " + std::to_string(scene.lights.size()));
    }
    for (const std::vector<LitPolygon>& lit : shadowed.lit[f]) {
      for (const LitPolygon& p : lit) {
        if (p.part >= scene.faces[f].parts.size()) {
          check.fail("a lit polygon on part " + std::to_string(p.part) + " of a face of " +
                     std::to_string(scene.faces[f].parts.size()) + " parts");
        }
        check.polygons({&p.polygon, 1});
      }
    }
  }
}

void append_vec3(std::string& out, const glm::dvec3& v) {
  out += '[';
  append_json_number(out, v.x);
  out += ',';
  append_json_number(out, v.y);
  out += ',';
  append_json_number(out, v.z);
  out += ']';
}

void append_loop(std::string& out, const Loop3& loop) {
  out += '[';
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (i > 0) out += ',';
    append_vec3(out, loop[i]);
  }
  out += ']';
}

void append_polygon(std::string& out, const Polygon3& polygon) {
  out += "{\"outer\":";
  append_loop(out, polygon.outer);
  out += ",\"holes\":[";
  for (std::size_t i = 0; i < polygon.holes.size(); ++i) {
    if (i > 0) out += ',';
    append_loop(out, polygon.holes[i]);
  }
  out += "]}";
}

// A lit polygon: the polygon's keys, and "part" on a face of several parts.
void append_lit_polygon(std::string& out, const LitPolygon& lit, bool with_part) {
  append_polygon(out, lit.polygon);
  if (!with_part) return;
  out.pop_back();
  out += ",\"part\":";
  out += std::to_string(lit.part);
  out += '}';
}

void append_key(std::string& out, std::string_view key) {
  append_json_string(out, key);
  out += ':';
}

void append_light(std::string& out, const Light& light) {
  out += '{';
  append_key(out, "id");
  append_json_string(out, light.id);
  if (light.type == LightType::kDirectional) {
    out += ",\"type\":\"directional\",\"direction\":";
    append_vec3(out, light.direction);
  } else {
    out += ",\"type\":\"point\",\"position\":";
    append_vec3(out, light.position);
  }
  out += ",\"intensity\":";
  append_vec3(out, light.intensity);
  if (light.range) {
    out += ",\"range\":{\"falloff_start\":";
    append_json_number(out, light.range->falloff_start);
    out += ",\"end\":";
    append_json_number(out, light.range->end);
    out += ",\"exponent\":";
    append_json_number(out, light.range->exponent);
    out += '}';
  }
  out += '}';
}

void append_view(std::string& out, const ViewSpec& view) {
  out += '{';
  append_key(out, "id");
  append_json_string(out, view.id);
  out += ",\"eye\":";
  append_vec3(out, view.eye);
  out += ",\"target\":";
  append_vec3(out, view.target);
  out += ",\"up\":";
  append_vec3(out, view.up);
  out += ",\"fov_deg\":";
  append_json_number(out, view.fov_deg);
  out += '}';
}

// `[`, then each item on its own line at `indent`, then `]` on a line of its own (or
// `[]` when there are no items).
template <class Items, class AppendItem>
void append_lines(std::string& out, const Items& items, std::string_view indent,
                  AppendItem append_item) {
  out += '[';
  bool first = true;
  for (const auto& item : items) {
    out += first ? "\n" : ",\n";
    first = false;
    out += indent;
    append_item(out, item);
  }
  if (!first) {
    out += '\n';
    out += indent.substr(2);
  }
  out += ']';
}

void append_face(std::string& out, const Face& face, const std::vector<Light>& lights,
                 const std::vector<std::vector<LitPolygon>>& lit) {
  out += "{\n      \"id\": ";
  append_json_string(out, face.id);
  out += ",\n      \"source_file\": ";
  append_json_string(out, face.source_file);
  out += ",\n      \"parts\": ";
  append_lines(out, face.parts, "        ", append_polygon);
  out += ",\n      \"lit\": {";
  bool first = true;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (lit[l].empty()) continue;
    out += first ? "\n        " : ",\n        ";
    first = false;
    append_json_string(out, lights[l].id);
    out += ": ";
    const bool with_part = face.parts.size() > 1;
    append_lines(out, lit[l], "          ", [with_part](std::string& text, const LitPolygon& p) {
      append_lit_polygon(text, p, with_part);
    });
  }
  out += first ? "}" : "\n      }";
  out += "\n    }";
}

// Walks the parsed document; every complaint names the file, the face being read (if
// any) and where in it the problem is, as a path like `parts[0].outer[3]`.
class DatabaseReader {
 public:
  explicit DatabaseReader(const std::filesystem::path& path) : file_(path.string()) {}

  ShadowedScene read(const Json& root) {
    if (!root.is_object()) fail("", "the top level is not an object");
    const Json& format = member(root, "format", "");
    if (!format.is_string() || format.get_ref<const std::string&>() != kShadowedFormat) {
      fail("", "\"format\" is " + format.dump() + ", expected \"" + std::string(kShadowedFormat) +
                   "\"");
    }
    ShadowedScene shadowed;
    read_lights(array(member(root, "lights", ""), "lights"), shadowed.scene.lights);
    read_views(array(member(root, "views", ""), "views"), shadowed.scene.views);
    read_faces(array(member(root, "faces", ""), "faces"), shadowed);
    return shadowed;
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError(file_, face_, where.empty() ? what : where + ": " + what);
  }

  static std::string at(const std::string& where, std::string_view key) {
    return where.empty() ? std::string(key) : where + "." + std::string(key);
  }
  static std::string at(const std::string& where, std::size_t index) {
    return where + "[" + std::to_string(index) + "]";
  }

  const Json& member(const Json& object, const char* key, const std::string& where) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(where, std::string("missing \"") + key + "\"");
    return *it;
  }
  const Json& array(const Json& value, const std::string& where) const {
    if (!value.is_array()) fail(where, "expected an array");
    return value;
  }
  const Json& object(const Json& value, const std::string& where) const {
    if (!value.is_object()) fail(where, "expected an object");
    return value;
  }
  std::string string(const Json& value, const std::string& where) const {
    if (!value.is_string()) fail(where, "expected a string");
    return value.get<std::string>();
  }
  double number(const Json& value, const std::string& where) const {
    if (!value.is_number()) fail(where, "expected a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(where, "the number is out of range");
    return x;
  }
  glm::dvec3 vec3(const Json& value, const std::string& where) const {
    if (!value.is_array() || value.size() != 3) fail(where, "expected three numbers [x, y, z]");
    return {number(value[0], at(where, 0)), number(value[1], at(where, 1)),
            number(value[2], at(where, 2))};
  }
  Loop3 loop(const Json& value, const std::string& where) const {
    array(value, where);
    if (value.size() < 3) fail(where, "a loop needs at least three vertices");
    Loop3 loop;
    loop.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) loop.push_back(vec3(value[i], at(where, i)));
    return loop;
  }
  Polygon3 polygon(const Json& value, const std::string& where) const {
    object(value, where);
    Polygon3 polygon;
    polygon.outer = loop(member(value, "outer", where), at(where, "outer"));
    const std::string holes_at = at(where, "holes");
    const Json& holes = array(member(value, "holes", where), holes_at);
    polygon.holes.reserve(holes.size());
    for (std::size_t i = 0; i < holes.size(); ++i) {
      polygon.holes.push_back(loop(holes[i], at(holes_at, i)));
    }
    return polygon;
  }
  std::vector<Polygon3> polygons(const Json& value, const std::string& where) const {
    array(value, where);
    std::vector<Polygon3> polygons;
    polygons.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
      polygons.push_back(polygon(value[i], at(where, i)));
    }
    return polygons;
  }

  // Lit polygons of `face`: each on the part its "part" key names. Without the key (a
  // database written before parts were recorded) a polygon lies on the part whose plane
  // is nearest to its outer vertices, the first of equals.
  std::vector<LitPolygon> lit_polygons(const Json& value, const std::string& where,
                                       const Face& face) const {
    array(value, where);
    std::vector<LitPolygon> out;
    out.reserve(value.size());
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::string item_at = at(where, i);
      LitPolygon lit{0, polygon(value[i], item_at)};
      if (const auto part = value[i].find("part"); part != value[i].end()) {
        if (!part->is_number_unsigned() || part->get<std::size_t>() >= face.parts.size()) {
          fail(at(item_at, "part"), "expected the index of one of the face's " +
                                        std::to_string(face.parts.size()) + " parts");
        }
        lit.part = part->get<std::size_t>();
      } else if (face.parts.size() > 1) {
        lit.part = nearest_part(lit.polygon, face);
      }
      out.push_back(std::move(lit));
    }
    return out;
  }

  static std::size_t nearest_part(const Polygon3& polygon, const Face& face) {
    std::size_t best = 0;
    double best_distance = INFINITY;
    for (std::size_t k = 0; k < face.parts.size(); ++k) {
      const hsr::Plane3 plane = hsr::plane_of(face.parts[k]);
      double d = 0.0;
      for (const glm::dvec3& p : polygon.outer) d = std::max(d, std::abs(plane.signed_distance(p)));
      if (d < best_distance) {
        best_distance = d;
        best = k;
      }
    }
    return best;
  }

  // "lights[2] ('lamp')" once the id is known.
  static std::string named(const std::string& where, const std::string& id) {
    return where + " ('" + id + "')";
  }

  void read_lights(const Json& lights, std::vector<Light>& out) {
    for (std::size_t i = 0; i < lights.size(); ++i) {
      std::string where = at("lights", i);
      const Json& value = object(lights[i], where);
      Light light;
      light.id = string(member(value, "id", where), at(where, "id"));
      where = named(where, light.id);
      if (!light_index_.emplace(light.id, i).second) fail(where, "duplicate light id");
      const std::string type = string(member(value, "type", where), at(where, "type"));
      if (type == "directional") {
        light.type = LightType::kDirectional;
        light.direction = vec3(member(value, "direction", where), at(where, "direction"));
      } else if (type == "point") {
        light.type = LightType::kPoint;
        light.position = vec3(member(value, "position", where), at(where, "position"));
      } else {
        fail(at(where, "type"), "expected \"directional\" or \"point\", not \"" + type + "\"");
      }
      light.intensity = vec3(member(value, "intensity", where), at(where, "intensity"));
      if (const auto range = value.find("range"); range != value.end()) {
        const std::string range_at = at(where, "range");
        object(*range, range_at);
        LightRange r;
        r.falloff_start =
            number(member(*range, "falloff_start", range_at), at(range_at, "falloff_start"));
        r.end = number(member(*range, "end", range_at), at(range_at, "end"));
        r.exponent = number(member(*range, "exponent", range_at), at(range_at, "exponent"));
        light.range = r;
      }
      out.push_back(std::move(light));
    }
  }

  void read_views(const Json& views, std::vector<ViewSpec>& out) const {
    std::unordered_set<std::string> ids;
    for (std::size_t i = 0; i < views.size(); ++i) {
      std::string where = at("views", i);
      const Json& value = object(views[i], where);
      ViewSpec view;
      view.id = string(member(value, "id", where), at(where, "id"));
      where = named(where, view.id);
      if (!ids.insert(view.id).second) fail(where, "duplicate view id");
      view.eye = vec3(member(value, "eye", where), at(where, "eye"));
      view.target = vec3(member(value, "target", where), at(where, "target"));
      view.up = vec3(member(value, "up", where), at(where, "up"));
      view.fov_deg = number(member(value, "fov_deg", where), at(where, "fov_deg"));
      out.push_back(std::move(view));
    }
  }

  void read_faces(const Json& faces, ShadowedScene& shadowed) {
    const std::size_t light_count = shadowed.scene.lights.size();
    std::unordered_set<std::string> ids;
    shadowed.scene.faces.reserve(faces.size());
    shadowed.lit.reserve(faces.size());
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const std::string where = at("faces", i);
      const Json& value = object(faces[i], where);
      Face face;
      face.id = string(member(value, "id", where), at(where, "id"));
      face_ = face.id;  // from here on, messages name the face
      if (!ids.insert(face.id).second) fail("", "duplicate face id");
      face.source_file = string(member(value, "source_file", ""), "source_file");
      face.parts = polygons(member(value, "parts", ""), "parts");
      if (face.parts.empty()) fail("parts", "a face needs at least one polygon");

      std::vector<std::vector<LitPolygon>> lit(light_count);
      const Json& lit_value = object(member(value, "lit", ""), "lit");
      for (const auto& [light_id, polygons_value] : lit_value.items()) {
        const std::string lit_at = "lit['" + light_id + "']";
        const auto light = light_index_.find(light_id);
        if (light == light_index_.end()) fail(lit_at, "no light has this id");
        lit[light->second] = lit_polygons(polygons_value, lit_at, face);
      }
      shadowed.scene.faces.push_back(std::move(face));
      shadowed.lit.push_back(std::move(lit));
      face_.clear();
    }
  }

  std::string file_;
  std::string face_;  // the face being read, for messages
  std::unordered_map<std::string, std::size_t> light_index_;
};

}  // namespace

std::string database_json(const ShadowedScene& shadowed) {
  check_writable(shadowed);
  const Scene& scene = shadowed.scene;
  std::string out;
  out += "{\n  \"format\": ";
  append_json_string(out, kShadowedFormat);
  out += ",\n  \"lights\": ";
  append_lines(out, scene.lights, "    ", append_light);
  out += ",\n  \"views\": ";
  append_lines(out, scene.views, "    ", append_view);
  out += ",\n  \"faces\": [";
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    out += f == 0 ? "\n    " : ",\n    ";
    append_face(out, scene.faces[f], scene.lights, shadowed.lit[f]);
  }
  out += scene.faces.empty() ? "]" : "\n  ]";
  out += "\n}\n";
  return out;
}

ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path) {
  Json root;
  try {
    root = Json::parse(json_text);
  } catch (const Json::exception& e) {  // a syntax error, or a number beyond double's range
    throw InputError(path.string(), "", "not valid JSON: " + detail::json_error_message(e));
  }
  return DatabaseReader(path).read(root);
}

void write_database(const ShadowedScene& shadowed, const std::filesystem::path& path) {
  write_file_atomically(path, database_json(shadowed));
}

ShadowedScene read_database(const std::filesystem::path& path) {
  return parse_database(read_text_file(path), path);
}

}  // namespace shadowgen
