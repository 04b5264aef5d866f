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

#include "detail/database_writable.h"
#include "detail/method_json.h"
#include "detail/origin_json.h"
#include "shadowgen/database/database_format.h"
#include "shadowgen/database/face_vertices.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_writer.h"
#include "shadowgen/output/atomic_file.h"

namespace shadowgen {
namespace {

using hsr::Loop3;
using hsr::Polygon3;
using Layout = JsonWriter::Layout;
namespace key = database::key;

void write_loop(JsonWriter& out, const Loop3& loop) {
  out.begin_array();
  for (const glm::dvec3& p : loop) out.value(p);
  out.end_array();
}

// {"outer":[...],"holes":[...]}, and "part" after them on a face of several parts.
void write_polygon(JsonWriter& out, const Polygon3& polygon,
                   std::optional<std::size_t> part = std::nullopt) {
  out.begin_object().key(key::kOuter);
  write_loop(out, polygon.outer);
  out.key(key::kHoles).begin_array();
  for (const Loop3& hole : polygon.holes) write_loop(out, hole);
  out.end_array();
  if (part) out.key(key::kPart).value(std::uint64_t{*part});
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
    out.key(key::kStepMin).value(std::uint64_t(light.sun->step_min));
    out.key("azimuth_deg").value(light.sun->azimuth_deg);
    out.key("elevation_deg").value(light.sun->elevation_deg).end_object();
  }
  out.end_object();
}

void write_sun_path(JsonWriter& out, const SunPathHours& path) {
  out.begin_object().key(key::kId).value(path.id);
  out.key(key::kStepMin).value(std::uint64_t(path.step_min));
  out.key(key::kFrom).value(path.from).key(key::kTo).value(path.to);
  out.key(key::kInstantPolygons).value(path.lit_polygons_kept ? key::kKept : key::kDropped);
  if (!path.regions_kept) out.key(key::kRegions).value(key::kDropped);
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
  out.key(key::kSite).begin_object().key("latitude_deg").value(site.latitude_deg);
  out.key("longitude_deg").value(site.longitude_deg).key("elevation_m").value(site.elevation_m);
  out.key("utc_offset_h").value(site.utc_offset_h);
  out.key("north_axis_deg").value(site.north_axis_deg).end_object();
}

// "groups": [{"id": "garden", "faces": ["garden*", "lawn/*"]}, ...], one group per line.
void write_groups(JsonWriter& out, const std::vector<FaceGroupSpec>& groups) {
  out.key(key::kGroups).begin_array(Layout::kLines);
  for (const FaceGroupSpec& group : groups) {
    out.begin_object().key(key::kId).value(group.id).key(key::kFaces).begin_array();
    for (const std::string& pattern : group.patterns) out.value(pattern);
    out.end_array().end_object();
  }
  out.end_array();
}

// How a face's lit polygons and regions are written: inline (/1), each with its
// coordinates, or indexed (/2), as loops of indices into the face's shared vertices,
// which FaceVertices numbered in the order the polygons are written.
class LitWriter {
 public:
  LitWriter(database::Layout layout, bool with_part) : layout_(layout), with_part_(with_part) {}

  // Numbers the vertices of every polygon the face writes, in the order it writes them
  // (lit polygons by light, then each path's regions), and writes the face's tables.
  void write_tables(JsonWriter& out, const ShadowedScene& shadowed, std::size_t f) {
    if (layout_ != database::Layout::kIndexed) return;
    database::FaceVertices table;
    const auto add = [&](std::span<const LitPolygon> lit) {
      for (const LitPolygon& p : lit) loops_.push_back(table.add(p.polygon));
    };
    if (shadowed.is_exact()) {
      for (std::size_t l = 0; l < shadowed.scene().lights.size(); ++l) add(shadowed.lit()[f][l]);
    }
    for (const SunPathHours& path : shadowed.sun_paths) {
      if (!path.regions_kept || !path.nodes.empty()) continue;
      for (const SunHoursRegion& region : path.regions[f]) add(region.polygons);
    }
    if (loops_.empty()) return;
    out.key(key::kNumbers).begin_array();
    for (const double n : table.numbers()) out.value(n);
    out.end_array().key(key::kVertices).begin_array();
    for (const std::size_t i : table.vertices()) out.value(std::uint64_t{i});
    out.end_array();
  }

  // The polygons, one a line (/1) or all on one line (/2).
  void write(JsonWriter& out, std::span<const LitPolygon> lit) {
    if (layout_ == database::Layout::kInline) {
      out.begin_array(Layout::kLines);
      for (const LitPolygon& p : lit) {
        write_polygon(out, p.polygon, with_part_ ? std::optional(p.part) : std::nullopt);
      }
      out.end_array();
      return;
    }
    out.begin_array();
    for (const LitPolygon& p : lit) {
      if (with_part_)
        out.begin_object().key(key::kPart).value(std::uint64_t{p.part}).key(key::kLoops);
      out.begin_array();
      for (const std::vector<std::size_t>& loop : loops_.at(next_++)) {
        out.begin_array();
        for (const std::size_t i : loop) out.value(std::uint64_t{i});
        out.end_array();
      }
      out.end_array();
      if (with_part_) out.end_object();
    }
    out.end_array();
  }

  // A region a line in /2, its polygons inline; a polygon a line in /1.
  Layout region_layout() const {
    return layout_ == database::Layout::kIndexed ? Layout::kInline : Layout::kLines;
  }

 private:
  database::Layout layout_;
  bool with_part_;
  std::vector<database::IndexLoops> loops_;
  std::size_t next_ = 0;
};

void write_loop(JsonWriter& out, const clipper::Loop2& loop) {
  out.begin_array();
  for (const clipper::Point2& p : loop) out.begin_array().value(p.x).value(p.y).end_array();
  out.end_array();
}

// "nodes": [{"block": b, "level": l, "parts": [{"part": i, "counts": [{"count": c,
// "pieces": [{"outer": [[x, y], ...], "holes": [...]}]}]}]}], the pieces in their part's
// chart (SunHoursPieces).
void write_nodes(JsonWriter& out, std::span<const SunHoursNode> nodes) {
  out.key(key::kNodes).begin_array(Layout::kLines);
  for (const SunHoursNode& node : nodes) {
    out.begin_object(Layout::kLines).key(key::kBlock).value(std::uint64_t{node.first_block});
    out.key(key::kLevel)
        .value(std::uint64_t{node.level})
        .key(key::kParts)
        .begin_array(Layout::kLines);
    for (const SunHoursPieces::Part& part : node.sums.parts) {
      out.begin_object(Layout::kLines).key(key::kPart).value(std::uint64_t{part.part});
      out.key(key::kCounts).begin_array(Layout::kLines);
      for (const SunHoursPieces::Count& count : part.counts) {
        out.begin_object(Layout::kLines).key(key::kCount).value(std::uint64_t{count.count});
        out.key(key::kPieces).begin_array(Layout::kLines);
        for (const clipper::PolygonWithHoles2& piece : count.pieces) {
          out.begin_object().key(key::kOuter);
          write_loop(out, piece.outer);
          out.key(key::kHoles).begin_array();
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
                     LitWriter& lit_writer) {
  out.key(key::kSunHours).begin_object(Layout::kLines);
  for (const SunPathHours& path : paths) {
    out.key(path.id).begin_object(Layout::kLines).key(key::kLitArea).begin_array();
    for (const double a : path.lit_area[face]) out.value(a);
    out.end_array();
    if (!path.part_lit_area[face].empty()) {
      out.key(key::kPartLitArea).begin_array(Layout::kLines);
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
    out.key(key::kRegions).begin_array(Layout::kLines);
    for (const SunHoursRegion& region : path.regions[face]) {
      out.begin_object(lit_writer.region_layout()).key(key::kHours).value(region.hours);
      out.key(key::kPolygons);
      lit_writer.write(out, region.polygons);
      out.end_object();
    }
    out.end_array().end_object();
  }
  out.end_object();
}

void write_face(JsonWriter& out, const ShadowedScene& shadowed, std::size_t f,
                database::Layout layout) {
  const Face& face = shadowed.scene().faces[f];
  const std::vector<Light>& lights = shadowed.scene().lights;
  const LitTable::ConstRow lit = shadowed.lit()[f];
  out.begin_object(Layout::kLines);
  out.key(key::kId).value(face.id).key(key::kSourceFile).value(face.source_file);
  output::detail::write_origin(out, face.origin);
  if (face.vertex_rounding > 0.0) out.key(key::kVertexRounding).value(face.vertex_rounding);
  out.key(key::kParts).begin_array(Layout::kLines);
  for (const Polygon3& part : face.parts) write_polygon(out, part);
  out.end_array();
  LitWriter lit_writer(layout, face.parts.size() > 1);
  lit_writer.write_tables(out, shadowed, f);
  if (const std::optional<Estimate>& estimate = shadowed.estimate()) {
    // areas alone, of every light that is no path's instant
    out.key(key::kLitArea).begin_object();
    for (std::size_t l = 0; l < lights.size(); ++l) {
      const std::vector<double>& column = estimate->lit_area[l];
      if (!column.empty()) out.key(lights[l].id).value(column[f]);
    }
    out.end_object();
  } else {
    out.key(key::kLit).begin_object(Layout::kLines);
    for (std::size_t l = 0; l < lights.size(); ++l) {
      if (lit[l].empty()) continue;
      out.key(lights[l].id);
      lit_writer.write(out, lit[l]);
    }
    out.end_object();
  }
  if (!shadowed.sun_paths.empty()) write_sun_hours(out, f, shadowed.sun_paths, lit_writer);
  out.end_object();
}

}  // namespace

namespace {

void write_database_to(const ShadowedScene& shadowed, JsonWriter& out, database::Layout layout) {
  output::detail::check_writable(shadowed);
  const Scene& scene = shadowed.scene();
  out.begin_object(Layout::kLines).key(key::kFormat);
  out.value(layout == database::Layout::kIndexed ? database::kIndexedFormat
                                                 : database::kInlineFormat);
  if (shadowed.shard) {
    out.key(key::kShard)
        .begin_object()
        .key(key::kShardIndex)
        .value(std::uint64_t{shadowed.shard->index + 1});
    out.key(key::kCount).value(std::uint64_t{shadowed.shard->count}).end_object();
  }
  if (const std::optional<Estimate>& estimate = shadowed.estimate()) {
    output::detail::write_method(out, estimate->method);
  }
  if (scene.site) write_site(out, *scene.site);
  out.key(key::kLights).begin_array(Layout::kLines);
  for (const Light& light : scene.lights) write_light(out, light);
  out.end_array();
  out.key(key::kViews).begin_array(Layout::kLines);
  for (const ViewSpec& view : scene.views) write_view(out, view);
  out.end_array();
  if (!shadowed.sun_paths.empty()) {
    out.key(key::kSunPaths).begin_array(Layout::kLines);
    for (const SunPathHours& path : shadowed.sun_paths) write_sun_path(out, path);
    out.end_array();
  }
  if (!scene.groups.empty()) write_groups(out, scene.groups);
  out.key(key::kFaces).begin_array(Layout::kLines);
  for (std::size_t f = 0; f < scene.faces.size(); ++f) write_face(out, shadowed, f, layout);
  out.end_array();
  out.end_object();
}

}  // namespace

std::string database_json(const ShadowedScene& shadowed, database::Layout layout) {
  JsonWriter out;
  write_database_to(shadowed, out, layout);
  return out.take();
}

void write_database(const ShadowedScene& shadowed, const std::filesystem::path& path,
                    database::Layout layout) {
  // Streamed: a sun path's sums can make hundreds of megabytes of text.
  stream_file_atomically(path, [&shadowed, layout](const OutputSink& sink) {
    JsonWriter out(sink);
    write_database_to(shadowed, out, layout);
    out.finish();
  });
}

}  // namespace shadowgen
