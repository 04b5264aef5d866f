#include "shadowgen/output/database.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>
#include <unordered_set>
#include <utility>

#include "shadowgen/json/document.h"
#include "shadowgen/json/json_writer.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

using hsr::Loop3;
using hsr::Polygon3;
using Layout = JsonWriter::Layout;

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

void write_loop(JsonWriter& out, const Loop3& loop) {
  out.begin_array();
  for (const glm::dvec3& p : loop) out.value(p);
  out.end_array();
}

// {"outer":[...],"holes":[...]}, and "part" after them on a face of several parts.
void write_polygon(JsonWriter& out, const Polygon3& polygon,
                   std::optional<std::size_t> part = std::nullopt) {
  out.begin_object().key("outer");
  write_loop(out, polygon.outer);
  out.key("holes").begin_array();
  for (const Loop3& hole : polygon.holes) write_loop(out, hole);
  out.end_array();
  if (part) out.key("part").value(std::uint64_t{*part});
  out.end_object();
}

void write_light(JsonWriter& out, const Light& light) {
  out.begin_object().key("id").value(light.id);
  if (light.type == LightType::kDirectional) {
    out.key("type").value("directional").key("direction").value(light.direction);
  } else {
    out.key("type").value("point").key("position").value(light.position);
  }
  out.key("intensity").value(light.intensity);
  if (light.range) {
    out.key("range").begin_object();
    out.key("falloff_start").value(light.range->falloff_start);
    out.key("end").value(light.range->end);
    out.key("exponent").value(light.range->exponent);
    out.end_object();
  }
  out.end_object();
}

void write_view(JsonWriter& out, const ViewSpec& view) {
  out.begin_object().key("id").value(view.id);
  out.key("eye").value(view.eye).key("target").value(view.target).key("up").value(view.up);
  out.key("fov_deg").value(view.fov_deg).end_object();
}

void write_face(JsonWriter& out, const Face& face, const std::vector<Light>& lights,
                const std::vector<std::vector<LitPolygon>>& lit) {
  out.begin_object(Layout::kLines);
  out.key("id").value(face.id).key("source_file").value(face.source_file);
  out.key("parts").begin_array(Layout::kLines);
  for (const Polygon3& part : face.parts) write_polygon(out, part);
  out.end_array();
  out.key("lit").begin_object(Layout::kLines);
  const bool with_part = face.parts.size() > 1;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    if (lit[l].empty()) continue;
    out.key(lights[l].id).begin_array(Layout::kLines);
    for (const LitPolygon& p : lit[l]) {
      write_polygon(out, p.polygon, with_part ? std::optional(p.part) : std::nullopt);
    }
    out.end_array();
  }
  out.end_object();
  out.end_object();
}

}  // namespace

std::string database_json(const ShadowedScene& shadowed) {
  check_writable(shadowed);
  const Scene& scene = shadowed.scene;
  JsonWriter out;
  out.begin_object(Layout::kLines).key("format").value(kShadowedFormat);
  out.key("lights").begin_array(Layout::kLines);
  for (const Light& light : scene.lights) write_light(out, light);
  out.end_array();
  out.key("views").begin_array(Layout::kLines);
  for (const ViewSpec& view : scene.views) write_view(out, view);
  out.end_array();
  out.key("faces").begin_array(Layout::kLines);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    write_face(out, scene.faces[f], scene.lights, shadowed.lit[f]);
  }
  out.end_array();
  out.end_object();
  return out.take();
}

void write_database(const ShadowedScene& shadowed, const std::filesystem::path& path) {
  write_file_atomically(path, database_json(shadowed));
}

}  // namespace shadowgen
