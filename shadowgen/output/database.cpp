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

#include "detail/method_json.h"
#include "detail/origin_json.h"
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
  void loop(const clipper::Loop2& loop) const {
    if (loop.size() < 3) fail("a loop has fewer than three vertices");
    for (const clipper::Point2& p : loop) {
      finite(p.x, "a chart coordinate");
      finite(p.y, "a chart coordinate");
    }
  }
  void pieces(const SunHoursPieces& sums) const {
    for (const SunHoursPieces::Part& part : sums.parts) {
      for (const SunHoursPieces::Count& count : part.counts) {
        for (const clipper::PolygonWithHoles2& piece : count.pieces) {
          loop(piece.outer);
          for (const clipper::Loop2& hole : piece.holes) loop(hole);
        }
      }
    }
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
  check_lit_shape(shadowed, "shadowed database");
  if (!shadowed.method.exact()) {
    const WriteCheck check("a sampled method's lit areas");
    if (shadowed.estimated_lit_area.size() != scene.lights.size()) check.fail("not per light");
    for (const std::vector<double>& column : shadowed.estimated_lit_area) {
      if (!column.empty() && column.size() != scene.faces.size()) check.fail("not per face");
      for (const double a : column) check.finite(a, "a lit area");
    }
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
  for (const SunPathHours& path : shadowed.sun_paths) {
    const WriteCheck check("sun path '" + path.id + "'");
    const std::vector<std::vector<SunHoursRegion>>& regions = path.regions;
    const bool sums_shaped =
        !path.regions_kept ||
        (shadowed.shard ? path.nodes.size() == scene.faces.size() && regions.empty()
                        : regions.size() == scene.faces.size());
    if (path.lit_area.size() != scene.faces.size() || !sums_shaped) {
      check.fail("sums not shaped [face]");
    }
    const std::size_t own =
        shadowed.shard ? path.shard_last - path.shard_first : path.instants.size();
    if (path.shard_first > path.shard_last || path.shard_last > path.instants.size()) {
      check.fail("a shard's instants beyond the path's");
    }
    for (const std::size_t l : path.instants) {
      if (l >= scene.lights.size() || !scene.lights[l].sun ||
          scene.lights[l].sun->sun_id != path.id) {
        check.fail("an instant that is not a light of this path");
      }
    }
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      if (path.lit_area[f].size() != own) check.fail("lit areas not per instant");
      for (const double a : path.lit_area[f]) check.finite(a, "a lit area");
      const std::size_t parts = scene.faces[f].parts.size();
      const std::vector<std::vector<double>>& on_parts = path.part_lit_area.at(f);
      if (on_parts.size() != (parts > 1 ? parts : 0)) check.fail("part lit areas not per part");
      for (const std::vector<double>& areas : on_parts) {
        if (areas.size() != own) check.fail("part lit areas not per instant");
        for (const double a : areas) check.finite(a, "a part's lit area");
      }
      if (!path.regions_kept) continue;
      if (shadowed.shard) {
        for (const SunHoursNode& node : path.nodes[f]) check.pieces(node.sums);
        continue;
      }
      for (const SunHoursRegion& region : path.regions[f]) {
        check.finite(region.hours, "sun hours");
        for (const LitPolygon& p : region.polygons) check.polygons({&p.polygon, 1});
      }
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
  if (light.sun) {
    out.key("sun").begin_object().key("entry").value(light.sun->sun_id);
    out.key("time").value(light.sun->time);
    out.key("step_min").value(std::uint64_t(light.sun->step_min));
    out.key("azimuth_deg").value(light.sun->azimuth_deg);
    out.key("elevation_deg").value(light.sun->elevation_deg).end_object();
  }
  out.end_object();
}

void write_sun_path(JsonWriter& out, const SunPathHours& path) {
  out.begin_object().key("id").value(path.id);
  out.key("step_min").value(std::uint64_t(path.step_min));
  out.key("from").value(path.from).key("to").value(path.to);
  out.key("instant_polygons").value(path.lit_polygons_kept ? "kept" : "dropped");
  if (!path.regions_kept) out.key("regions").value("dropped");
  out.end_object();
}

void write_view(JsonWriter& out, const ViewSpec& view) {
  out.begin_object().key("id").value(view.id);
  out.key("eye").value(view.eye).key("target").value(view.target).key("up").value(view.up);
  out.key("fov_deg").value(view.fov_deg).end_object();
}

// The scene's site (docs/scene-format.md, "The site"), every key, so that a picture of the
// database can show north and a model of it where it lies.
void write_site(JsonWriter& out, const Site& site) {
  out.key("site").begin_object().key("latitude_deg").value(site.latitude_deg);
  out.key("longitude_deg").value(site.longitude_deg).key("elevation_m").value(site.elevation_m);
  out.key("utc_offset_h").value(site.utc_offset_h);
  out.key("north_axis_deg").value(site.north_axis_deg).end_object();
}

// "groups": [{"id": "garden", "faces": ["garden*", "lawn/*"]}, ...], one group per line.
void write_groups(JsonWriter& out, const std::vector<FaceGroupSpec>& groups) {
  out.key("groups").begin_array(Layout::kLines);
  for (const FaceGroupSpec& group : groups) {
    out.begin_object().key("id").value(group.id).key("faces").begin_array();
    for (const std::string& pattern : group.patterns) out.value(pattern);
    out.end_array().end_object();
  }
  out.end_array();
}

void write_lit_polygons(JsonWriter& out, std::span<const LitPolygon> lit, bool with_part) {
  out.begin_array(Layout::kLines);
  for (const LitPolygon& p : lit) {
    write_polygon(out, p.polygon, with_part ? std::optional(p.part) : std::nullopt);
  }
  out.end_array();
}

void write_loop(JsonWriter& out, const clipper::Loop2& loop) {
  out.begin_array();
  for (const clipper::Point2& p : loop) out.begin_array().value(p.x).value(p.y).end_array();
  out.end_array();
}

// "nodes": [{"block": b, "level": l, "parts": [{"part": i, "counts": [{"count": c,
// "pieces": [{"outer": [[x, y], ...], "holes": [...]}]}]}]}], the pieces in their part's
// chart (SunHoursPieces).
void write_nodes(JsonWriter& out, std::span<const SunHoursNode> nodes) {
  out.key("nodes").begin_array(Layout::kLines);
  for (const SunHoursNode& node : nodes) {
    out.begin_object(Layout::kLines).key("block").value(std::uint64_t{node.first_block});
    out.key("level").value(std::uint64_t{node.level}).key("parts").begin_array(Layout::kLines);
    for (const SunHoursPieces::Part& part : node.sums.parts) {
      out.begin_object(Layout::kLines).key("part").value(std::uint64_t{part.part});
      out.key("counts").begin_array(Layout::kLines);
      for (const SunHoursPieces::Count& count : part.counts) {
        out.begin_object(Layout::kLines).key("count").value(std::uint64_t{count.count});
        out.key("pieces").begin_array(Layout::kLines);
        for (const clipper::PolygonWithHoles2& piece : count.pieces) {
          out.begin_object().key("outer");
          write_loop(out, piece.outer);
          out.key("holes").begin_array();
          for (const clipper::Loop2& hole : piece.holes) write_loop(out, hole);
          out.end_array().end_object();
        }
        out.end_array().end_object();
      }
      out.end_array().end_object();
    }
    out.end_array().end_object();
  }
  out.end_array();
}

// "sun_hours": {"path": {"lit_area": [...], "part_lit_area": [[...], ...] (on a face of
// several parts), "regions": [{"hours": h, "polygons": [...]}]}}
void write_sun_hours(JsonWriter& out, std::size_t face, const std::vector<SunPathHours>& paths,
                     bool with_part) {
  out.key("sun_hours").begin_object(Layout::kLines);
  for (const SunPathHours& path : paths) {
    out.key(path.id).begin_object(Layout::kLines).key("lit_area").begin_array();
    for (const double a : path.lit_area[face]) out.value(a);
    out.end_array();
    if (!path.part_lit_area[face].empty()) {
      out.key("part_lit_area").begin_array(Layout::kLines);
      for (const std::vector<double>& areas : path.part_lit_area[face]) {
        out.begin_array();
        for (const double a : areas) out.value(a);
        out.end_array();
      }
      out.end_array();
    }
    if (!path.regions_kept) {  // lit areas alone
      out.end_object();
      continue;
    }
    if (!path.nodes.empty()) {
      write_nodes(out, path.nodes[face]);
      out.end_object();
      continue;
    }
    out.key("regions").begin_array(Layout::kLines);
    for (const SunHoursRegion& region : path.regions[face]) {
      out.begin_object(Layout::kLines).key("hours").value(region.hours).key("polygons");
      write_lit_polygons(out, region.polygons, with_part);
      out.end_object();
    }
    out.end_array().end_object();
  }
  out.end_object();
}

void write_face(JsonWriter& out, const ShadowedScene& shadowed, std::size_t f) {
  const Face& face = shadowed.scene.faces[f];
  const std::vector<Light>& lights = shadowed.scene.lights;
  const LitTable::ConstRow lit = shadowed.lit[f];
  out.begin_object(Layout::kLines);
  out.key("id").value(face.id).key("source_file").value(face.source_file);
  detail::write_origin(out, face.origin);
  out.key("parts").begin_array(Layout::kLines);
  for (const Polygon3& part : face.parts) write_polygon(out, part);
  out.end_array();
  const bool with_part = face.parts.size() > 1;
  if (!shadowed.method.exact()) {  // areas alone, of every light that is no path's instant
    out.key("lit_area").begin_object();
    for (std::size_t l = 0; l < lights.size(); ++l) {
      const std::vector<double>& column = shadowed.estimated_lit_area[l];
      if (!column.empty()) out.key(lights[l].id).value(column[f]);
    }
    out.end_object();
  } else {
    out.key("lit").begin_object(Layout::kLines);
    for (std::size_t l = 0; l < lights.size(); ++l) {
      if (lit[l].empty()) continue;
      out.key(lights[l].id);
      write_lit_polygons(out, lit[l], with_part);
    }
    out.end_object();
  }
  if (!shadowed.sun_paths.empty()) write_sun_hours(out, f, shadowed.sun_paths, with_part);
  out.end_object();
}

}  // namespace

namespace {

void write_database_to(const ShadowedScene& shadowed, JsonWriter& out) {
  check_writable(shadowed);
  const Scene& scene = shadowed.scene;
  out.begin_object(Layout::kLines).key("format").value(kShadowedFormat);
  if (shadowed.shard) {
    out.key("shard").begin_object().key("index").value(std::uint64_t{shadowed.shard->index + 1});
    out.key("count").value(std::uint64_t{shadowed.shard->count}).end_object();
  }
  if (!shadowed.method.exact()) detail::write_method(out, shadowed.method);
  if (scene.site) write_site(out, *scene.site);
  out.key("lights").begin_array(Layout::kLines);
  for (const Light& light : scene.lights) write_light(out, light);
  out.end_array();
  out.key("views").begin_array(Layout::kLines);
  for (const ViewSpec& view : scene.views) write_view(out, view);
  out.end_array();
  if (!shadowed.sun_paths.empty()) {
    out.key("sun_paths").begin_array(Layout::kLines);
    for (const SunPathHours& path : shadowed.sun_paths) write_sun_path(out, path);
    out.end_array();
  }
  if (!scene.groups.empty()) write_groups(out, scene.groups);
  out.key("faces").begin_array(Layout::kLines);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) write_face(out, shadowed, f);
  out.end_array();
  out.end_object();
}

}  // namespace

std::string database_json(const ShadowedScene& shadowed) {
  JsonWriter out;
  write_database_to(shadowed, out);
  return out.take();
}

void write_database(const ShadowedScene& shadowed, const std::filesystem::path& path) {
  // Streamed: a sun path's sums can make hundreds of megabytes of text.
  stream_file_atomically(path, [&shadowed](const OutputSink& sink) {
    JsonWriter out(sink);
    write_database_to(shadowed, out);
    out.finish();
  });
}

}  // namespace shadowgen
