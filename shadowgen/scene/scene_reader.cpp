#include "shadowgen/scene/scene_reader.h"

#include <array>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "detail/face_builder.h"
#include "shadowgen/model/input_error.h"
#include "detail/mesh_reader.h"

namespace shadowgen {

namespace {

// Only a direction's direction matters (the spec: it need not be unit length). Scaled by
// a power of two, which is exact, so that its largest component lies in [0.5, 1): then
// 1e-300 or 1e300 long directions neither underflow nor overflow in dot products.
glm::dvec3 power_of_two_scaled(const glm::dvec3& v) {
  const double largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  int exponent = 0;
  std::frexp(largest, &exponent);
  return {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
}

using nlohmann::json;

constexpr std::string_view kFormat = "shadowgen-scene/1";

// ---- JSON text -------------------------------------------------------------------------

// Line and column (1-based, columns in bytes) of the byte at `offset` (0-based).
std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t offset) {
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i < std::min(offset, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

// Replays a failed parse to learn where it failed: nlohmann's SAX interface reports the
// byte position of every error, number overflow included (which json::parse reports as an
// out_of_range error without a position).
class ErrorLocator final : public nlohmann::json_sax<json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const json::exception& error) override {
    position_ = position;
    last_token_ = last_token;
    id_ = error.id;
    what_ = error.what();
    return false;
  }

  // "line L, column C: what went wrong".
  std::string describe(std::string_view text) const {
    std::size_t offset = position_ > 0 ? position_ - 1 : 0;  // position counts bytes read
    std::string what;
    if (id_ == 406) {  // number overflow: point at the number's start
      offset = position_ >= last_token_.size() ? position_ - last_token_.size() : 0;
      what = "the number " + last_token_ + " is out of the range of a double";
    } else {
      // nlohmann's text: "[json.exception.parse_error.101] parse error at line 2,
      // column 4: syntax error while parsing ..."; keep what follows the position.
      what = what_;
      const std::size_t column = what.find(", column ");
      const std::size_t colon = column == std::string::npos ? column : what.find(": ", column);
      if (colon != std::string::npos) {
        what = what.substr(colon + 2);
      } else if (const std::size_t bracket = what.find("] "); bracket != std::string::npos) {
        what = what.substr(bracket + 2);
      }
    }
    const auto [line, column] = line_column(text, offset);
    return "line " + std::to_string(line) + ", column " + std::to_string(column) +
           ": invalid JSON: " + what;
  }

 private:
  std::size_t position_ = 0;
  std::string last_token_;
  int id_ = 0;
  std::string what_;
};

// ---- Where a value sits, for messages --------------------------------------------------

// "file: face 'id': subject: path: problem", each part only when known.
class Where {
 public:
  explicit Where(const std::string& file) : file_(&file) {}

  Where face(std::string id) const {
    Where w(*file_);
    w.face_id_ = std::move(id);
    return w;
  }
  Where subject(std::string subject) const {
    Where w(*file_);
    w.subject_ = std::move(subject);
    return w;
  }
  Where key(std::string_view key) const {
    Where w = *this;
    if (!w.path_.empty()) w.path_ += '.';
    w.path_ += key;
    return w;
  }
  Where at(std::size_t index) const {
    Where w = *this;
    w.path_ += "[" + std::to_string(index) + "]";
    return w;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    std::string what;
    if (!subject_.empty()) what += subject_ + ": ";
    if (!path_.empty()) what += path_ + ": ";
    throw InputError(*file_, face_id_, what + problem);
  }

 private:
  const std::string* file_;
  std::string face_id_;
  std::string subject_;
  std::string path_;
};

std::string describe(const json& j) {
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return "a boolean";
    case json::value_t::string:
      return "a string";
    case json::value_t::array:
      return "an array";
    case json::value_t::object:
      return "an object";
    default:
      return j.is_number() ? "a number" : j.type_name();
  }
}

const json& expect_object(const json& j, const Where& where) {
  if (!j.is_object()) where.fail("expected an object, found " + describe(j));
  return j;
}

const json& expect_array(const json& j, const Where& where) {
  if (!j.is_array()) where.fail("expected an array, found " + describe(j));
  return j;
}

const json& member(const json& object, const char* key, const Where& where) {
  const auto it = object.find(key);
  if (it == object.end()) where.fail(std::string("missing '") + key + "'");
  return *it;
}

const json* optional_member(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

double number(const json& j, const Where& where) {
  if (!j.is_number()) where.fail("expected a number, found " + describe(j));
  const double value = j.get<double>();
  if (!std::isfinite(value)) where.fail("the number is not finite");
  return value;
}

std::string text(const json& j, const Where& where) {
  if (!j.is_string()) where.fail("expected a string, found " + describe(j));
  return j.get<std::string>();
}

glm::dvec3 point(const json& j, const Where& where) {
  if (!j.is_array() || j.size() != 3) {
    where.fail("expected an array of 3 numbers, found " +
               (j.is_array() ? "an array of " + std::to_string(j.size()) : describe(j)));
  }
  return {number(j[0], where.at(0)), number(j[1], where.at(1)), number(j[2], where.at(2))};
}

hsr::Loop3 loop(const json& j, const Where& where) {
  expect_array(j, where);
  hsr::Loop3 out;
  out.reserve(j.size());
  for (std::size_t i = 0; i < j.size(); ++i) out.push_back(point(j[i], where.at(i)));
  return out;
}

std::string id_of(const json& object, const Where& where) {
  std::string id = text(member(object, "id", where), where.key("id"));
  if (id.empty()) where.key("id").fail("an id must not be empty");
  return id;
}

// ---- Mesh transforms -------------------------------------------------------------------

// Row-major 4x4, applied to column vectors (x, y, z, 1); the last row gives w.
using Transform = std::array<std::array<double, 4>, 4>;

Transform transform_of(const json& j, const Where& where) {
  if (!j.is_array() || j.size() != 4) where.fail("expected 4 rows of 4 numbers");
  Transform m{};
  for (std::size_t r = 0; r < 4; ++r) {
    const json& row = j[r];
    if (!row.is_array() || row.size() != 4) where.at(r).fail("expected a row of 4 numbers");
    for (std::size_t c = 0; c < 4; ++c) m[r][c] = number(row[c], where.at(r).at(c));
  }
  return m;
}

std::string number_text(double value) {
  std::ostringstream s;
  s.precision(17);
  s << value;
  return s.str();
}

struct PlacedVertex {
  glm::dvec3 p{0.0};
  double w = 1.0;  // 0 or not finite: the transform sends the vertex to infinity
  bool finite = true;
};

PlacedVertex place(const Transform& m, const glm::dvec3& v) {
  auto row = [&](std::size_t r) { return m[r][0] * v.x + m[r][1] * v.y + m[r][2] * v.z + m[r][3]; };
  PlacedVertex out;
  out.p = glm::dvec3(row(0), row(1), row(2));
  const bool affine = m[3][0] == 0.0 && m[3][1] == 0.0 && m[3][2] == 0.0 && m[3][3] == 1.0;
  if (!affine) {
    out.w = row(3);
    if (std::isfinite(out.w) && out.w != 0.0) out.p /= out.w;
  }
  out.finite = std::isfinite(out.w) && out.w != 0.0 && std::isfinite(out.p.x) &&
               std::isfinite(out.p.y) && std::isfinite(out.p.z);
  return out;
}

// ---- The scene -------------------------------------------------------------------------

class SceneParser {
 public:
  SceneParser(const std::string& text, const std::filesystem::path& path,
              const ReadOptions& options)
      : text_(text), path_(path), file_(path.string()), options_(options) {}

  ReadResult run() {
    const json root = parse_json();
    const Where top(file_);
    if (!root.is_object()) top.fail("a scene is a JSON object; found " + describe(root));
    const std::string format = text(member(root, "format", top), top.key("format"));
    if (format != kFormat) {
      top.key("format").fail("unsupported format '" + format + "'; this reader reads '" +
                             std::string(kFormat) + "'");
    }
    check_has_faces(root, top);
    if (const json* polygons = optional_member(root, "polygons")) {
      expect_array(*polygons, top.key("polygons"));
      for (std::size_t i = 0; i < polygons->size(); ++i) {
        read_polygon((*polygons)[i], top.key("polygons").at(i));
      }
    }
    if (const json* meshes = optional_member(root, "meshes")) {
      expect_array(*meshes, top.key("meshes"));
      for (std::size_t i = 0; i < meshes->size(); ++i) {
        read_mesh_entry((*meshes)[i], top.key("meshes").at(i));
      }
    }
    if (const json* lights = optional_member(root, "lights")) {
      expect_array(*lights, top.key("lights"));
      for (std::size_t i = 0; i < lights->size(); ++i) {
        read_light((*lights)[i], top.key("lights").at(i));
      }
    }
    if (const json* views = optional_member(root, "views")) {
      expect_array(*views, top.key("views"));
      for (std::size_t i = 0; i < views->size(); ++i) {
        read_view((*views)[i], top.key("views").at(i));
      }
    }
    return std::move(result_);
  }

 private:
  // A scene has faces from "polygons", "meshes" or both (either may be empty); a
  // misspelt key must not pass for an empty scene. Other keys are extensions (the spec
  // allows new optional keys) and are ignored; they are named when neither is present.
  static void check_has_faces(const json& root, const Where& top) {
    if (root.contains("polygons") || root.contains("meshes")) return;
    static constexpr std::string_view kKnown[] = {"format", "lights", "views"};
    std::string unknown;
    for (const auto& [key, value] : root.items()) {
      if (std::find(std::begin(kKnown), std::end(kKnown), key) != std::end(kKnown)) continue;
      unknown += (unknown.empty() ? "'" : ", '") + key + "'";
    }
    std::string problem =
        "a scene needs \"polygons\" or \"meshes\" (either may be empty); neither is present";
    if (!unknown.empty()) problem += "; other keys found: " + unknown;
    top.fail(problem);
  }

  json parse_json() const {
    try {
      return json::parse(text_);
    } catch (const json::exception&) {
      ErrorLocator locator;
      json::sax_parse(text_, &locator);
      throw InputError(file_, "", locator.describe(text_));
    }
  }

  // Polygon ids and mesh ids share one namespace (a polygon id never contains '/', and a
  // mesh face id always does, so face ids are then unique too); lights and views each
  // have their own.
  void claim(std::unordered_map<std::string, std::string>& ids, const std::string& id,
             const std::string& owner, const Where& where) {
    const auto [it, fresh] = ids.emplace(id, owner);
    if (!fresh)
      where.key("id").fail("duplicate id '" + id + "' (already used by " + it->second + ")");
  }

  void read_polygon(const json& entry, const Where& where) {
    expect_object(entry, where);
    const std::string id = id_of(entry, where);
    if (id.find('/') != std::string::npos) {
      throw InputError(file_, id, "a polygon id must not contain '/' (mesh face ids use it)");
    }
    claim(face_ids_, id, "polygon '" + id + "'", where);
    const Where face = where.face(id);
    hsr::Polygon3 polygon;
    polygon.outer = loop(member(entry, "outer", face), face.key("outer"));
    if (const json* holes = optional_member(entry, "holes")) {
      expect_array(*holes, face.key("holes"));
      for (std::size_t k = 0; k < holes->size(); ++k) {
        polygon.holes.push_back(loop((*holes)[k], face.key("holes").at(k)));
      }
    }
    result_.scene.faces.push_back(detail::build_face(
        std::move(polygon), {id, file_, detail::FaceKind::kPolygon}, options_.strict, result_.warnings));
  }

  void read_mesh_entry(const json& entry, const Where& where) {
    expect_object(entry, where);
    const std::string id = id_of(entry, where);
    claim(face_ids_, id, "mesh '" + id + "'", where);
    const Where mesh = where.subject("mesh '" + id + "'");
    const std::string file = text(member(entry, "file", mesh), mesh.key("file"));
    if (file.empty()) mesh.key("file").fail("the file name is empty");
    std::optional<Transform> transform;
    if (const json* t = optional_member(entry, "transform")) {
      transform = transform_of(*t, mesh.key("transform"));
    }

    const std::filesystem::path mesh_path = (path_.parent_path() / file).lexically_normal();
    std::error_code error;
    if (!std::filesystem::is_regular_file(mesh_path, error)) {
      mesh.key("file").fail("mesh file '" + file + "' not found (looked for '" +
                            mesh_path.string() + "')");
    }
    const detail::MeshSoup soup = detail::read_mesh(mesh_path, id);
    const std::string mesh_file = mesh_path.string();
    if (soup.faces.empty()) {
      result_.warnings.push_back(
          detail::face_message(mesh_file, "", "mesh '" + id + "' has no faces"));
    }

    std::vector<PlacedVertex> placed(soup.vertices.size());
    for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
      if (transform) {
        placed[v] = place(*transform, soup.vertices[v]);
      } else {
        placed[v].p = soup.vertices[v];
      }
    }

    for (std::size_t k = 0; k < soup.faces.size(); ++k) {
      const detail::MeshFaceRecord& record = soup.faces[k];
      const std::string face_id = id + "/" + std::to_string(k);
      const std::string at_line =
          record.line > 0 ? " (line " + std::to_string(record.line) + ")" : "";
      auto fail = [&](const std::string& what) {
        throw InputError(mesh_file, face_id, what + at_line);
      };
      if (record.vertices.size() < 3) {
        fail("the face record has " + std::to_string(record.vertices.size()) +
             " vertex indices; at least 3 are needed");
      }
      hsr::Polygon3 polygon;
      polygon.outer.reserve(record.vertices.size());
      int w_sign = 0;
      for (const std::int64_t index : record.vertices) {
        if (index < 0 || static_cast<std::uint64_t>(index) >= soup.vertices.size()) {
          fail("vertex index " + std::to_string(index) + " (counting from 0) is out of range: " +
               "the file has " + std::to_string(soup.vertices.size()) + " vertices");
        }
        const PlacedVertex& v = placed[static_cast<std::size_t>(index)];
        if (!v.finite) {
          fail("the mesh transform sends vertex " + std::to_string(index) +
               " to infinity (w = " + number_text(v.w) + ")");
        }
        const int sign = v.w > 0.0 ? 1 : -1;
        if (w_sign != 0 && sign != w_sign) {
          fail(
              "the projective mesh transform splits the face across infinity (w changes sign "
              "between its vertices)");
        }
        w_sign = sign;
        polygon.outer.push_back(v.p);
      }
      result_.scene.faces.push_back(
          detail::build_face(std::move(polygon), {face_id, mesh_file, detail::FaceKind::kMeshFace},
                             options_.strict, result_.warnings));
    }
  }

  void read_light(const json& entry, const Where& where) {
    expect_object(entry, where);
    Light light;
    light.id = id_of(entry, where);
    claim(light_ids_, light.id, "another light", where);
    const Where at = where.subject("light '" + light.id + "'");
    const std::string type = text(member(entry, "type", at), at.key("type"));
    if (type == "directional") {
      light.type = LightType::kDirectional;
      light.direction = point(member(entry, "direction", at), at.key("direction"));
      if (light.direction == glm::dvec3(0.0)) at.key("direction").fail("must not be zero");
      light.direction = power_of_two_scaled(light.direction);
      if (optional_member(entry, "range") != nullptr) {
        at.key("range").fail("a range applies to point lights only");
      }
    } else if (type == "point") {
      light.type = LightType::kPoint;
      light.position = point(member(entry, "position", at), at.key("position"));
      if (const json* range = optional_member(entry, "range")) {
        light.range = read_range(*range, at.key("range"));
      }
    } else {
      at.key("type").fail("unknown light type '" + type + "' (expected 'directional' or 'point')");
    }
    if (const json* intensity = optional_member(entry, "intensity")) {
      light.intensity = point(*intensity, at.key("intensity"));
      if (light.intensity.x < 0.0 || light.intensity.y < 0.0 || light.intensity.z < 0.0) {
        at.key("intensity").fail("must not be negative");
      }
    }
    result_.scene.lights.push_back(std::move(light));
  }

  static LightRange read_range(const json& j, const Where& where) {
    expect_object(j, where);
    LightRange range;
    range.end = number(member(j, "end", where), where.key("end"));
    if (const json* start = optional_member(j, "falloff_start")) {
      range.falloff_start = number(*start, where.key("falloff_start"));
    }
    if (const json* exponent = optional_member(j, "exponent")) {
      range.exponent = number(*exponent, where.key("exponent"));
    }
    if (!(range.end > 0.0)) where.key("end").fail("must be greater than 0");
    if (range.falloff_start < 0.0) where.key("falloff_start").fail("must not be negative");
    if (range.falloff_start > range.end) {
      where.key("falloff_start").fail("must not exceed 'end'");
    }
    if (range.exponent < 0.0) where.key("exponent").fail("must not be negative");
    return range;
  }

  void read_view(const json& entry, const Where& where) {
    expect_object(entry, where);
    ViewSpec view;
    view.id = id_of(entry, where);
    claim(view_ids_, view.id, "another view", where);
    const Where at = where.subject("view '" + view.id + "'");
    view.eye = point(member(entry, "eye", at), at.key("eye"));
    view.target = point(member(entry, "target", at), at.key("target"));
    if (const json* up = optional_member(entry, "up")) view.up = point(*up, at.key("up"));
    if (const json* fov = optional_member(entry, "fov_deg")) {
      view.fov_deg = number(*fov, at.key("fov_deg"));
    }
    if (view.eye == view.target) at.fail("'eye' and 'target' must differ");
    if (view.up == glm::dvec3(0.0)) at.key("up").fail("must not be zero");
    if (glm::cross(view.target - view.eye, view.up) == glm::dvec3(0.0)) {
      at.key("up").fail("must not be parallel to the direction from 'eye' to 'target'");
    }
    if (!(view.fov_deg > 0.0 && view.fov_deg < 180.0)) {
      at.key("fov_deg").fail("must lie strictly between 0 and 180");
    }
    result_.scene.views.push_back(std::move(view));
  }

  const std::string& text_;
  const std::filesystem::path path_;
  const std::string file_;
  const ReadOptions options_;
  ReadResult result_;
  std::unordered_map<std::string, std::string> face_ids_;
  std::unordered_map<std::string, std::string> light_ids_;
  std::unordered_map<std::string, std::string> view_ids_;
};

}  // namespace

ReadResult read_scene(const std::filesystem::path& path, const ReadOptions& options) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path.string(), "", "is a directory, not a scene file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(
        path.string(), "",
        std::filesystem::exists(path, error) ? "cannot open the scene file" : "no such file");
  }
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) throw InputError(path.string(), "", "cannot read the scene file");
  return parse_scene(content.str(), path, options);
}

ReadResult parse_scene(const std::string& json_text, const std::filesystem::path& path,
                       const ReadOptions& options) {
  return SceneParser(json_text, path, options).run();
}

}  // namespace shadowgen
