#include "shadowgen/scene/database_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "clipper/clip.h"
#include "detail/coordinate_range.h"
#include "detail/face_builder.h"
#include "detail/group_entry.h"
#include "detail/indexed_polygons.h"
#include "detail/json_entities.h"
#include "detail/lit_checks.h"
#include "detail/site_entry.h"
#include "detail/sun_hours_checks.h"
#include "hsr/area.h"
#include "hsr/collinearity.h"
#include "hsr/parallel.h"
#include "hsr/plane_chart.h"
#include "shadowgen/database/database_format.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_reader.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/instant_blocks.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/sun/civil_time.h"

namespace shadowgen {
namespace {

namespace key = database::key;

// Shards a run may be cut into: far more than any scheduler runs at once.
constexpr std::size_t kMaxShards = 1'000'000;

class DatabaseParser {
 public:
  DatabaseParser(const std::filesystem::path& path, const ReadOptions& options,
                 std::vector<std::string>& warnings)
      : path_(path), file_(path.string()), options_(options), warnings_(warnings) {}

  // Faces come last in a database as written (shadowgen/output/database.h), and make
  // nearly all of it: each is read as soon as the parser has it and its tree dropped, so
  // reading holds the scene and one face's tree, never the whole document's tree
  // (several times the text). The members before "faces" (the header) are read at its
  // first element. JSON objects are unordered, though: where a member of the header
  // comes after "faces" (a file arranged by hand), the faces streamed were read too
  // early (as exact where the method comes later, whole where the shard does), so what
  // reading them threw waits for the end of this pass, and they are read again in a
  // second pass, with the header this pass found after them (read_faces_after). Where
  // the format, the lights or the views come after "faces", no face is read in this
  // pass at all. Either way reading holds one face's tree at a time; the cost is a
  // second parse. Read from a file, the text itself is never held whole either.
  // From `text`, or where it is null from the file, read as it is parsed.
  ShadowedScene run(const std::string* text) {
    ShadowedScene shadowed;
    shadowed.scene.file = file_;
    std::optional<JsonObject> top;
    bool skipping = false;          // a member the header needs comes after the faces
    std::exception_ptr too_early;   // what reading the header or a face threw in this pass
    std::vector<bool> header_then;  // the header's members before the first face
    const std::size_t warnings_before = warnings_.size();
    const auto take = [&](const JsonValue& root, const JsonValue& face) {
      if (!top && !skipping) {
        header_then = header_present(root);
        skipping = !header_then[kFormat] || !header_then[kLights] || !header_then[kViews];
        if (!skipping) {
          top.emplace(root.object());
          guarded(too_early, [&] { read_header(*top, shadowed); });
        }
      }
      if (!skipping && !too_early) guarded(too_early, [&] { read_face(face, shadowed); });
      return true;  // dropped: read, or left for the second pass
    };
    std::optional<std::ifstream> in;
    std::optional<JsonDocument> document;
    parse(text, take, in, document);
    const JsonValue root = document->root();
    if (!root.is_object()) {
      root.fail("a shadowed database is a JSON object; found " + root.describe());
    }
    if (skipping || (top && header_present(root) != header_then)) {
      shadowed = {};
      warnings_.resize(warnings_before);
      return DatabaseParser(path_, options_, warnings_).read_faces_after(root, text);
    }
    if (too_early) std::rethrow_exception(too_early);
    if (!top) {  // no face
      top.emplace(root.object());
      read_header(*top, shadowed);
    }
    return finished(*top, std::move(shadowed));
  }

 private:
  // Runs `read`, keeping what it throws as bad input in `error` instead.
  template <class Read>
  static void guarded(std::exception_ptr& error, const Read& read) {
    try {
      read();
    } catch (const InputError&) {
      error = std::current_exception();
    }
  }

  // Parses the database, from `text` or where it is null from the file (opened in `in`),
  // into `document`, handing each face to `take` as it comes.
  void parse(const std::string* text, const JsonDocument::ElementTaker& take,
             std::optional<std::ifstream>& in, std::optional<JsonDocument>& document) const {
    const JsonSource source{file_, options_.strict, &warnings_};
    if (text != nullptr) {
      document.emplace(*text, source, key::kFaces, take);
    } else {
      in.emplace(open_input_file(path_));
      document.emplace(*in, source, key::kFaces, take);
    }
  }

  // The second pass: the header from `first`, the root of a first pass that read every
  // member but the faces, then the faces as this pass parses them.
  ShadowedScene read_faces_after(const JsonValue& first, const std::string* text) {
    ShadowedScene shadowed;
    JsonObject top = first.object();
    read_header(top, shadowed);
    const auto take = [&](const JsonValue&, const JsonValue& face) {
      read_face(face, shadowed);
      return true;
    };
    std::optional<std::ifstream> in;
    std::optional<JsonDocument> document;
    parse(text, take, in, document);
    return finished(top, std::move(shadowed));
  }

  // The checks once every member is read: no unknown key at the top, the lit polygons and
  // the sun hours (checked with every face read); the groups, whose patterns must match
  // faces, wherever they stand.
  ShadowedScene finished(JsonObject& top, ShadowedScene shadowed) const {
    (void)top.get(key::kFaces).array();
    if (const std::optional<JsonValue> groups = top.find(key::kGroups)) {
      shadowed.scene.groups = detail::read_groups(*groups, shadowed.scene.faces);
    }
    top.finish();
    check_lit(shadowed);
    check_sun_hours(shadowed);
    return shadowed;
  }

  // The members read before the faces, in this order: which of them the root has.
  static constexpr const char* kHeader[] = {key::kFormat, key::kShard, key::kMethod,
                                            key::kLights, key::kViews, key::kSunPaths,
                                            key::kSite};
  static constexpr std::size_t kFormat = 0, kLights = 3, kViews = 4;  // required ones in it
  static std::vector<bool> header_present(const JsonValue& root) {
    std::vector<bool> present;
    if (!root.is_object()) return present;
    JsonObject object = root.object();  // a look only: this one is never finished
    for (const char* key : kHeader) present.push_back(object.has(key));
    return present;
  }

  // Everything but the faces: the format, the shard, the lights and views, the sun paths.
  void read_header(JsonObject& top, ShadowedScene& shadowed) {
    const JsonValue format = top.get(key::kFormat);
    const std::optional<database::Layout> layout = database::layout_of(format.string());
    if (!layout) {
      format.fail("unsupported format '" + format.string() + "'; this reader reads '" +
                  std::string(database::kIndexedFormat) + "' and '" +
                  std::string(database::kInlineFormat) + "'");
    }
    layout_ = *layout;
    if (const std::optional<JsonValue> shard = top.find(key::kShard)) {
      shadowed.shard = read_shard(*shard);
    }
    if (const std::optional<JsonValue> method = top.find(key::kMethod)) {
      shadowed.method = read_method(*method);
      if (shadowed.shard && !shadowed.method.exact()) {
        method->fail("a shard is made by the exact method only");
      }
    }
    if (const std::optional<JsonValue> site = top.find(key::kSite)) {
      shadowed.scene.site = read_site(*site);
    }
    const JsonArray lights = top.get(key::kLights).array();
    detail::IdRegistry light_ids;
    for (std::size_t i = 0; i < lights.size(); ++i) {
      shadowed.scene.lights.push_back(
          detail::read_light(lights.at(i), light_ids, detail::Source::kDatabase));
      light_index_.emplace(shadowed.scene.lights.back().id, i);
    }
    const JsonArray views = top.get(key::kViews).array();
    detail::IdRegistry view_ids;
    for (std::size_t i = 0; i < views.size(); ++i) {
      shadowed.scene.views.push_back(
          detail::read_view(views.at(i), view_ids, detail::Source::kDatabase));
    }
    if (const std::optional<JsonValue> paths = top.find(key::kSunPaths)) {
      read_sun_paths(*paths, shadowed);
    }
    for (const SunPathHours& path : shadowed.sun_paths) {
      shadowed.scene.sun_paths.push_back({path.id, path.step_min, path.from, path.to});
    }
    if (!shadowed.method.exact()) {
      for (const SunPathHours& path : shadowed.sun_paths) {
        if (path.regions_kept || path.lit_polygons_kept) {
          top.get(key::kSunPaths)
              .fail("sun path '" + one_line(path.id) +
                    "': a sampled method keeps lit areas alone: \"regions\" "
                    "and \"instant_polygons\" must be \"dropped\"");
        }
      }
    }
    shadowed.lit = LitTable(0, shadowed.scene.lights.size(), kept_lights(shadowed));
    if (!shadowed.method.exact()) {
      shadowed.estimated_lit_area.resize(shadowed.scene.lights.size());
      instant_.assign(shadowed.scene.lights.size(), 0);
      for (const SunPathHours& path : shadowed.sun_paths) {
        for (const std::size_t l : path.instants) instant_[l] = 1;
      }
    }
  }

  // "method": {"name": "rays" | "shadow-map" | "exact", "samples": N, "resolution": R}
  // (samples for a sampled method, resolution for the shadow map alone).
  static Method read_method(const JsonValue& value) {
    JsonObject entry = value.object();
    const JsonValue name = entry.get(key::kMethodName);
    const std::optional<MethodKind> kind = method_kind(name.string());
    if (!kind) name.fail("unknown method '" + name.string() + "' (exact, rays, shadow-map)");
    Method method{*kind};
    if (!method.exact()) {
      const JsonValue samples = entry.get(key::kSamples);
      if (samples.index() < 1 || samples.index() > std::size_t{kMaxSamples}) {
        samples.fail("expected sample points per face from 1 to " + std::to_string(kMaxSamples));
      }
      method.samples = static_cast<int>(samples.index());
    }
    if (method.kind == MethodKind::kShadowMap) {
      const JsonValue resolution = entry.get(key::kResolution);
      if (resolution.index() < 1 || resolution.index() > std::size_t{kMaxResolution}) {
        resolution.fail("expected texels per side from 1 to " + std::to_string(kMaxResolution));
      }
      method.resolution = static_cast<int>(resolution.index());
    }
    entry.finish();
    return method;
  }

  // Per light, whether faces may list its lit polygons: not for the instants of a path
  // whose instant polygons were dropped (only their lit areas are kept), and for no light
  // of a sampled method.
  static std::vector<bool> kept_lights(const ShadowedScene& shadowed) {
    std::vector<bool> kept(shadowed.scene.lights.size(), shadowed.method.exact());
    for (const SunPathHours& path : shadowed.sun_paths) {
      if (path.lit_polygons_kept) continue;
      for (const std::size_t l : path.instants) kept[l] = false;
    }
    return kept;
  }

  // "shard": {"index": K, "count": N}, 1 <= K <= N.
  static ShardPlace read_shard(const JsonValue& value) {
    JsonObject entry = value.object();
    const JsonValue index = entry.get(key::kShardIndex), count = entry.get(key::kShardCount);
    if (count.index() < 1 || count.index() > kMaxShards) {
      count.fail("expected a number of shards from 1 to " + std::to_string(kMaxShards));
    }
    if (index.index() < 1 || index.index() > count.index()) {
      index.fail("expected a shard from 1 to the count, " + std::to_string(count.index()));
    }
    entry.finish();
    return {index.index() - 1, count.index()};
  }

  // A sun path's "from" and "to", in seconds on the path's clock.
  static std::pair<std::int64_t, std::int64_t> read_span(JsonObject& entry, SunPathHours& path) {
    std::int64_t seconds[2] = {0, 0};
    std::string* texts[2] = {&path.from, &path.to};
    const char* keys[2] = {"from", "to"};
    for (int i = 0; i < 2; ++i) {
      const JsonValue value = entry.get(keys[i]);
      *texts[i] = value.string();
      const std::optional<sun::CivilTime> time = sun::parse_civil_time(*texts[i]);
      if (!time) value.fail("expected a local time YYYY-MM-DDTHH:MM (seconds optional)");
      seconds[i] = sun::seconds_since_1970(*time);
    }
    if (seconds[1] < seconds[0]) entry.get(key::kTo).fail("must not be before 'from'");
    return {seconds[0], seconds[1]};
  }

  // "site": the scene's keys in their ranges (detail/site_entry.h), latitude, longitude
  // and the offset required, elevation and north axis 0 where left out.
  static Site read_site(const JsonValue& value) {
    const SourceSite keys = detail::read_site_keys(value);
    const char* missing = !keys.latitude_deg    ? "latitude_deg"
                          : !keys.longitude_deg ? "longitude_deg"
                          : !keys.utc_offset_h  ? "utc_offset_h"
                                                : nullptr;
    if (missing != nullptr) value.fail(std::string("missing '") + missing + "'");
    return {*keys.latitude_deg, *keys.longitude_deg, keys.elevation_m.value_or(0.0),
            *keys.utc_offset_h, keys.north_axis_deg.value_or(0.0)};
  }

  // "sun_paths": each path's instants are the lights whose "sun" names it, in order: each
  // at a time on the path's steps from "from" to "to", after the one before it. A path
  // may have none (the sun below the horizon at every step: a polar night).
  void read_sun_paths(const JsonValue& value, ShadowedScene& shadowed) {
    const JsonArray paths = value.array();
    detail::IdRegistry ids;
    for (std::size_t i = 0; i < paths.size(); ++i) {
      JsonObject entry = paths.at(i).object();
      SunPathHours path;
      path.id = detail::read_claimed_id(entry, ids, "sun path");
      const JsonValue step = entry.get(key::kStepMin);
      path.step_min = static_cast<int>(std::min<std::size_t>(step.index(), 1'000'001));
      if (path.step_min <= 0) step.fail("a sun path needs a positive step_min");
      const auto [from, to] = read_span(entry, path);
      const JsonValue kept = entry.get(key::kInstantPolygons);
      if (kept.string() != key::kKept && kept.string() != key::kDropped) {
        kept.fail("expected 'kept' or 'dropped'");
      }
      path.lit_polygons_kept = kept.string() == key::kKept;
      if (shadowed.shard && path.lit_polygons_kept) {
        kept.fail(
            "a shard keeps its instants' lit areas alone: \"instant_polygons\" must be "
            "\"dropped\" (generate --instants does not take --keep-instants)");
      }
      if (const std::optional<JsonValue> regions = entry.find(key::kRegions)) {
        if (regions->string() != key::kDropped) regions->fail("expected 'dropped' (or no key)");
        path.regions_kept = false;
      }
      const std::int64_t step_s = std::int64_t{path.step_min} * 60;
      std::int64_t before = 0;  // the time of the path's instant before
      for (std::size_t l = 0; l < shadowed.scene.lights.size(); ++l) {
        const std::optional<SunInstant>& sun = shadowed.scene.lights[l].sun;
        if (!sun || sun->sun_id != path.id) continue;
        const std::string instant =
            "light '" + one_line(shadowed.scene.lights[l].id) + "' of this path";
        if (sun->step_min != path.step_min) {
          step.fail(instant + " stands for " + std::to_string(sun->step_min) +
                    " minutes, the path says " + std::to_string(path.step_min));
        }
        const std::optional<sun::CivilTime> time = sun::parse_civil_time(sun->time);
        if (!time) {
          entry.value().fail(instant + " is at '" + one_line(sun->time) +
                             "', not a local time YYYY-MM-DDTHH:MM (seconds optional)");
        }
        const std::int64_t at = sun::seconds_since_1970(*time);
        if (at < from || at > to) {
          entry.get(key::kTo).fail(instant + " is at " + sun->time + ", outside its span from " +
                                   path.from + " to " + path.to);
        }
        if ((at - from) % step_s != 0) {
          step.fail(instant + " is at " + sun->time + ", not on one of its " +
                    std::to_string(path.step_min) + "-minute steps from " + path.from);
        }
        if (!path.instants.empty() && at <= before) {
          const Light& last = shadowed.scene.lights[path.instants.back()];
          entry.value().fail(instant + " is at " + sun->time + ", " +
                             (at == before ? "the time" : "before the time") + " of light '" +
                             one_line(last.id) + "' before it (" + last.sun->time +
                             "): a path's instants come in time order, one per step");
        }
        before = at;
        path.instants.push_back(l);
      }
      entry.finish();
      if (shadowed.shard) {
        const IndexRun own = shard_instants(path.instants.size(), *shadowed.shard);
        path.shard_first = own.first;
        path.shard_last = own.last;
      }
      path_values_.emplace_back();
      shadowed.sun_paths.push_back(std::move(path));
    }
  }

  // One lit area per instant of `path` (in a shard, per instant of its own), none negative.
  static std::vector<double> read_instant_areas(const JsonValue& value, const SunPathHours& path,
                                                bool shard) {
    const JsonArray areas = value.array();
    const std::size_t expected = shard ? path.shard_last - path.shard_first : path.instants.size();
    if (areas.size() != expected) {
      value.fail("expected one lit area per instant of the " +
                 std::string(shard ? "shard's part of the " : "") + "path (" +
                 std::to_string(expected) + "), found " + std::to_string(areas.size()));
    }
    std::vector<double> out;
    out.reserve(areas.size());
    for (std::size_t k = 0; k < areas.size(); ++k) {
      out.push_back(areas.at(k).number());
      if (out.back() < 0.0) areas.at(k).fail("a lit area must not be negative");
    }
    return out;
  }

  // sun_hours.<path>.part_lit_area on a face of several parts: per part, one lit area per
  // instant.
  static void read_part_lit_areas(JsonObject& sum, const Face& face, SunPathHours& path,
                                  bool shard) {
    std::vector<std::vector<double>>& on_parts = path.part_lit_area.emplace_back();
    if (face.parts.size() < 2) return;
    const JsonValue parts_value = sum.get(key::kPartLitArea);
    const JsonArray parts = parts_value.array();
    if (parts.size() != face.parts.size()) {
      parts_value.fail("expected one list of lit areas per part of the face (" +
                       std::to_string(face.parts.size()) + "), found " +
                       std::to_string(parts.size()));
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
      on_parts.push_back(read_instant_areas(parts.at(i), path, shard));
    }
  }

  // faces[i].sun_hours: every sun path's lit areas and sun-hours regions on this face.
  void read_sun_hours(JsonObject& entry, const Face& face, ShadowedScene& shadowed) {
    if (shadowed.sun_paths.empty()) return;
    JsonObject sums = entry.get(key::kSunHours).object();
    for (std::size_t p = 0; p < shadowed.sun_paths.size(); ++p) {
      SunPathHours& path = shadowed.sun_paths[p];
      JsonObject sum = sums.get(path.id).object();
      const bool shard = shadowed.shard.has_value();
      path.lit_area.push_back(read_instant_areas(sum.get(key::kLitArea), path, shard));
      read_part_lit_areas(sum, face, path, shard);
      if (!path.regions_kept) {  // lit areas alone
        sum.finish();
        path_values_[p].push_back(sum.value().place());
        continue;
      }
      if (shard) {
        path.nodes.push_back(read_nodes(sum.get(key::kNodes), path, *shadowed.shard));
        sum.finish();
        path_values_[p].push_back(sum.value().place());
        continue;
      }
      const JsonValue regions_value = sum.get(key::kRegions);
      const JsonArray regions = regions_value.array();
      std::vector<SunHoursRegion>& out = path.regions.emplace_back();
      for (std::size_t r = 0; r < regions.size(); ++r) {
        JsonObject region = regions.at(r).object();
        const JsonValue hours = region.get(key::kHours);
        const double count = std::round(hours.number() * 60.0 / path.step_min);
        if (!(count >= 0.0 && count <= static_cast<double>(path.instants.size()) &&
              count * path.step_min / 60.0 == hours.number())) {
          hours.fail("expected a whole number of the path's " + std::to_string(path.step_min) +
                     "-minute instants, from 0 to " + std::to_string(path.instants.size()));
        }
        if (!out.empty() && !(out.back().hours < hours.number())) {
          hours.fail("regions must come in increasing hours");
        }
        out.push_back({hours.number(), read_lit(region.get(key::kPolygons), face)});
        region.finish();
      }
      sum.finish();
      path_values_[p].push_back(sum.value().place());
    }
    sums.finish();
  }

  // A shard's "nodes" on one face: nodes of the path's tree covering the shard's blocks,
  // in order (model/instant_blocks.h); their pieces are checked against the face where
  // they are joined (FaceSunHours).
  static std::vector<SunHoursNode> read_nodes(const JsonValue& value, const SunPathHours& path,
                                              const ShardPlace& shard) {
    const IndexRun blocks =
        shard_blocks(block_count(path.instants.size()), shard.index, shard.count);
    const JsonArray nodes = value.array();
    std::vector<SunHoursNode> out;
    std::size_t next = blocks.first;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      JsonObject node = nodes.at(i).object();
      const JsonValue block = node.get(key::kBlock), level = node.get(key::kLevel);
      const std::size_t span = level.index() < 32 ? std::size_t{1} << level.index() : 0;
      if (span == 0 || block.index() != next || block.index() % span != 0 ||
          span > blocks.last - next) {
        node.value().fail("expected the tree's node that starts at block " + std::to_string(next) +
                          " of the shard's blocks " + std::to_string(blocks.first) + " to " +
                          std::to_string(blocks.last));
      }
      next += span;
      SunHoursNode& read = out.emplace_back();
      read.first_block = block.index();
      read.level = static_cast<unsigned>(level.index());
      const JsonArray parts = node.get(key::kParts).array();
      for (std::size_t k = 0; k < parts.size(); ++k) {
        JsonObject part = parts.at(k).object();
        SunHoursPieces::Part& p = read.sums.parts.emplace_back();
        p.part = part.get(key::kPart).index();
        const JsonArray counts = part.get(key::kCounts).array();
        for (std::size_t c = 0; c < counts.size(); ++c) {
          JsonObject count = counts.at(c).object();
          SunHoursPieces::Count& n = p.counts.emplace_back();
          n.count = count.get(key::kCount).index();
          const JsonArray pieces = count.get(key::kPieces).array();
          for (std::size_t q = 0; q < pieces.size(); ++q) {
            JsonObject piece = pieces.at(q).object();
            clipper::PolygonWithHoles2& polygon = n.pieces.emplace_back();
            polygon.outer = read_chart_loop(piece.get(key::kOuter));
            const JsonArray holes = piece.get(key::kHoles).array();
            for (std::size_t h = 0; h < holes.size(); ++h) {
              polygon.holes.push_back(read_chart_loop(holes.at(h)));
            }
            piece.finish();
          }
          count.finish();
        }
        part.finish();
      }
      node.finish();
    }
    if (next != blocks.last) {
      value.fail("the nodes end at block " + std::to_string(next) + ", the shard's blocks at " +
                 std::to_string(blocks.last));
    }
    return out;
  }

  // [[x, y], ...]: a loop in a part's chart, three points at least.
  static clipper::Loop2 read_chart_loop(const JsonValue& value) {
    const JsonArray points = value.array();
    if (points.size() < 3) value.fail("a loop needs at least three points");
    clipper::Loop2 loop;
    loop.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const JsonArray xy = points.at(i).array();
      if (xy.size() != 2) points.at(i).fail("expected a point [x, y]");
      loop.push_back({xy.at(0).number(), xy.at(1).number()});
    }
    return loop;
  }

  // A face's "origin" (shadowgen/output/detail/origin_json.h): every member a string,
  // "format" not empty.
  static FaceOrigin read_origin(const JsonValue& value) {
    JsonObject object = value.object();
    FaceOrigin origin;
    const JsonValue format = object.get(key::kFormat);
    origin.format = format.string();
    if (origin.format.empty())
      format.fail("must name the format the face comes from, not be empty");
    origin.object = object.get("object").string();
    origin.group = object.get("group").string();
    origin.semantic = object.get("semantic").string();
    object.finish();
    return origin;
  }

  void read_face(const JsonValue& value, ShadowedScene& shadowed) {
    JsonObject entry = value.object();
    Face face;
    face.id = detail::read_id(entry);
    face_ids_.claim(face.id, "another face", entry.get("id"));
    entry.for_face(face.id);
    face.source_file = entry.get(key::kSourceFile).string();
    if (const std::optional<JsonValue> origin = entry.find(key::kOrigin))
      face.origin = read_origin(*origin);
    if (const std::optional<JsonValue> rounding = entry.find(key::kVertexRounding)) {
      face.vertex_rounding = rounding->number();
      if (!(face.vertex_rounding >= 0.0)) rounding->fail("a vertex rounding cannot be negative");
    }
    const JsonValue parts_value = entry.get(key::kParts);
    const JsonArray parts = parts_value.array();
    if (parts.empty()) parts_value.fail("a face needs at least one polygon");
    for (std::size_t k = 0; k < parts.size(); ++k) {
      JsonObject part = parts.at(k).object();
      hsr::Polygon3 polygon = detail::read_polygon(part);
      part.finish();
      face.parts.push_back(
          checked_part(std::move(polygon), part.value(), face.id, face.vertex_rounding));
    }
    if (!std::isfinite(hsr::area(face.parts))) {
      parts_value.fail("the face's area is not a finite number (coordinates too large)");
    }
    if (layout_ == database::Layout::kIndexed) vertices_ = detail::read_face_vertices(entry);
    const std::size_t f = shadowed.lit.size();
    shadowed.lit.add_face();
    lists_of_face_.push_back(lists_.size());
    if (!shadowed.method.exact()) {
      read_estimated(entry, face, shadowed);
      read_sun_hours(entry, face, shadowed);
      entry.finish();
      shadowed.scene.faces.push_back(std::move(face));
      return;
    }
    for (const auto& [light_id, list] : entry.get(key::kLit).object().entries()) {
      const auto light = light_index_.find(light_id);
      if (light == light_index_.end()) list.fail("no light has this id");
      if (!shadowed.lit.kept(light->second)) {
        list.fail("the light is an instant of sun path '" +
                  one_line(path_of(shadowed, light->second)) +
                  "', whose instant polygons are \"dropped\": only its lit areas are kept");
      }
      // A shard keeps no instant's polygons (read_sun_paths), so a light it keeps is no
      // instant of a path: shard 1 alone lights those, and merge takes them from it.
      if (shadowed.shard && shadowed.shard->index != 0 && !list.array().empty()) {
        list.fail("is shard " + std::to_string(shadowed.shard->index + 1) + " of " +
                  std::to_string(shadowed.shard->count) +
                  ", which holds no lit polygons: the lights that are no instant of a sun "
                  "path are lit in shard 1 alone");
      }
      shadowed.lit.at(f, light->second) = read_lit(list, face);
      lists_.push_back({light->second, list.place()});
    }
    read_sun_hours(entry, face, shadowed);
    entry.finish();
    shadowed.scene.faces.push_back(std::move(face));
  }

  // A sampled method's "lit_area": {"light id": area, ...}, one for every light that is no
  // instant of a sun path (an instant's area is in the face's "sun_hours"), each from 0 to
  // the face's area.
  void read_estimated(JsonObject& entry, const Face& face, ShadowedScene& shadowed) const {
    if (const std::optional<JsonValue> lit = entry.find(key::kLit)) {
      lit->fail("a database made by the " + std::string(method_name(shadowed.method.kind)) +
                " method holds lit areas (\"lit_area\"), not lit polygons");
    }
    const JsonValue areas_value = entry.get(key::kLitArea);
    const std::size_t face_index = shadowed.scene.faces.size();
    const double face_area = hsr::area(face.parts);
    const double tolerance = detail::LitChecker(face).area_tolerance({});
    std::vector<bool> given(shadowed.scene.lights.size(), false);
    for (const auto& [light_id, value] : areas_value.object().entries()) {
      const auto light = light_index_.find(light_id);
      if (light == light_index_.end()) value.fail("no light has this id");
      const std::size_t l = light->second;
      if (instant_[l]) {
        value.fail("the light is an instant of sun path '" + one_line(path_of(shadowed, l)) +
                   "', whose lit areas are in the face's \"sun_hours\"");
      }
      const double a = value.number();
      if (a < 0.0 || a > face_area + tolerance) {
        value.fail("a lit area of " + shortest(a) + " is not between 0 and the face's area of " +
                   shortest(face_area));
      }
      std::vector<double>& column = shadowed.estimated_lit_area[l];
      column.resize(face_index + 1, 0.0);
      column[face_index] = a;
      given[l] = true;
    }
    for (std::size_t l = 0; l < given.size(); ++l) {
      if (!given[l] && !instant_[l]) {
        areas_value.fail("no lit area for light '" + one_line(shadowed.scene.lights[l].id) + "'");
      }
    }
  }

  static const std::string& path_of(const ShadowedScene& shadowed, std::size_t light) {
    for (const SunPathHours& path : shadowed.sun_paths) {
      if (std::find(path.instants.begin(), path.instants.end(), light) != path.instants.end()) {
        return path.id;
      }
    }
    throw std::logic_error("database reader: light " + std::to_string(light) + " is in no path");
  }

  // A part gets the checks a scene's face gets (strict: a part is planar, it was written
  // from a face already split into planar parts; planar within twice the face's vertex
  // rounding, as the scene reader took a model's face). A part without area is kept as it
  // is, as the scene reader keeps a degenerate face; it warned when it read it.
  hsr::Polygon3 checked_part(hsr::Polygon3 polygon, const JsonValue& at, const std::string& face_id,
                             double vertex_rounding) {
    if (const std::optional<std::string> problem = detail::coordinate_problem(polygon)) {
      at.fail(*problem);
    }
    if (polygon.outer.size() >= 3 &&
        (hsr::distinct_points_up_to_3(polygon.outer) < 3 || hsr::all_collinear(polygon.outer))) {
      if (!polygon.holes.empty()) {
        at.fail(
            "the outer loop has no area (its vertices are collinear), so no hole can lie in it");
      }
      return polygon;
    }
    std::vector<std::string> warnings;
    Face face;
    try {
      face = detail::build_face(std::move(polygon),
                                {face_id, file_, detail::FaceKind::kPolygon, vertex_rounding}, true,
                                warnings);
    } catch (const InputError& e) {
      at.fail(e.problem());
    }
    warnings_.insert(warnings_.end(), warnings.begin(), warnings.end());
    return std::move(face.parts.front());
  }

  // lit['id']: the polygons, each on the part its "part" key names. Without the key (a
  // database written before parts were recorded) a polygon lies on the part whose plane
  // is nearest to its outer vertices, the first of equals.
  // In the indexed layout, loops of indices into the face's vertices (detail/
  // indexed_polygons.h), "part" required on a face of several parts.
  std::vector<LitPolygon> read_lit(const JsonValue& value, const Face& face) const {
    const JsonArray list = value.array();
    if (layout_ == database::Layout::kIndexed) {
      std::vector<LitPolygon> out;
      out.reserve(list.size());
      for (std::size_t k = 0; k < list.size(); ++k) {
        out.push_back(detail::read_indexed_lit(list.at(k), vertices_, face.parts.size()));
      }
      return out;
    }
    std::optional<detail::LitChecker> checker;  // only to place polygons without "part"
    std::vector<LitPolygon> out;
    out.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) {
      JsonObject object = list.at(k).object();
      LitPolygon lit{0, detail::read_polygon(object)};
      if (const std::optional<std::string> problem = detail::vertex_problem(lit.polygon)) {
        object.value().fail(*problem);
      }
      if (const std::optional<JsonValue> part = object.find(key::kPart)) {
        lit.part = part->index();
        if (lit.part >= face.parts.size()) {
          part->fail("expected the index of one of the face's " +
                     std::to_string(face.parts.size()) + " parts");
        }
      } else if (face.parts.size() > 1) {
        if (!checker) checker.emplace(face);
        lit.part = checker->nearest_part(lit.polygon);
      }
      object.finish();
      out.push_back(std::move(lit));
    }
    return out;
  }

  // The lit polygons' checks (detail/lit_checks.h), the costly part of reading a
  // database (a clip per part and light), faces in parallel; the problem reported is the
  // first in the file's order.
  void check_lit(const ShadowedScene& shadowed) const {
    const std::size_t faces = lists_of_face_.size();
    std::vector<std::optional<detail::LitProblem>> problems(lists_.size());
    std::vector<std::optional<std::string>> unsettled(lists_.size());
    hsr::for_each_in_parallel(faces, [&](std::size_t f) {
      const std::size_t end = f + 1 < faces ? lists_of_face_[f + 1] : lists_.size();
      if (lists_of_face_[f] == end) return;
      const detail::LitChecker checker(shadowed.scene.faces[f]);
      for (std::size_t k = lists_of_face_[f]; k < end; ++k) {
        try {
          problems[k] = checker.check(shadowed.lit[f][lists_[k].light]);
        } catch (const clipper::SnapRoundingError& e) {
          unsettled[k] = e.what();
        }
      }
    });
    for (std::size_t k = 0; k < lists_.size(); ++k) {
      if (unsettled[k]) not_checked(lists_[k].place, "the lit polygons", *unsettled[k]);
      if (const std::optional<detail::LitProblem>& problem = problems[k]) {
        const JsonPlace& place = lists_[k].place;
        (problem->polygon ? place.element(*problem->polygon) : place).fail(problem->what);
      }
    }
  }

  // A check whose clip did not settle its snapping (clipper/clip.h, Limit): not the
  // input's fault, and not known to be right either. The clipper's error, naming the
  // file, the face and where in it (the command line's exit code 3).
  [[noreturn]] static void not_checked(const JsonPlace& place, const std::string& what,
                                       const std::string& why) {
    throw clipper::SnapRoundingError(place.message(what + " could not be checked: " + why));
  }

  // Each face's sun-hours regions over a path, checked as one face's lit polygons are,
  // all regions together: on the face's planes, inside it, not overlapping. They must
  // also tile it: their areas sum to the face's, and Σ hours × area to the lit areas'
  // Σ × step, up to the rounding along the regions' boundaries (LitChecker::
  // area_tolerance; times the path's hours for the second sum, each instant's lit
  // boundary lying along them), and no instant's lit area exceeds the face's by more.
  // In a shard, the nodes' sums get the same checks (nodes_problem).
  void check_sun_hours(const ShadowedScene& shadowed) const {
    const std::size_t faces = shadowed.scene.faces.size();
    for (std::size_t p = 0; p < shadowed.sun_paths.size(); ++p) {
      const SunPathHours& path = shadowed.sun_paths[p];
      std::vector<std::optional<std::string>> problems(faces), unsettled(faces);
      hsr::for_each_in_parallel(faces, [&](std::size_t f) {
        const Face& face = shadowed.scene.faces[f];
        try {
          if (!shadowed.shard) {
            problems[f] = detail::sun_hours_problem(face, path, f);
            return;
          }
          if (path.regions_kept) problems[f] = detail::nodes_problem(face, path, f);
          if (!problems[f]) problems[f] = detail::lit_areas_problem(face, path, f);
        } catch (const clipper::SnapRoundingError& e) {
          unsettled[f] = e.what();
        }
      });
      for (std::size_t f = 0; f < faces; ++f) {
        if (unsettled[f]) not_checked(path_values_[p][f], "the sun-hours regions", *unsettled[f]);
        if (problems[f]) path_values_[p][f].fail(*problems[f]);
      }
    }
  }

  const std::filesystem::path path_;
  const std::string file_;
  const ReadOptions options_;
  std::vector<std::string>& warnings_;
  detail::IdRegistry face_ids_;
  std::unordered_map<std::string, std::size_t> light_index_;
  // Each face's lists of lit polygons, checked once all are read (check_lit): where each
  // face's lists start in lists_, and per list its light and where it stands in the file.
  struct LitList {
    std::size_t light;
    JsonPlace place;
  };
  std::vector<std::size_t> lists_of_face_;
  std::vector<LitList> lists_;
  std::vector<std::vector<JsonPlace>> path_values_;  // [path][face]: faces[f].sun_hours.<path>
  std::vector<char> instant_;  // a sampled method's: per light, whether it is a path's instant
  database::Layout layout_ = database::Layout::kIndexed;  // the format's
  std::vector<glm::dvec3> vertices_;  // the face being read: its shared vertices (indexed)
};

}  // namespace

ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path,
                             const ReadOptions& options, std::vector<std::string>& warnings) {
  return DatabaseParser(path, options, warnings).run(&json_text);
}

ShadowedScene read_database(const std::filesystem::path& path, const ReadOptions& options,
                            std::vector<std::string>& warnings) {
  if (path == "-") return parse_database(read_text_file(path), path, options, warnings);
  return DatabaseParser(path, options, warnings).run(nullptr);
}

ShadowedScene parse_database(const std::string& json_text, const std::filesystem::path& path) {
  std::vector<std::string> warnings;
  return parse_database(json_text, path, {}, warnings);
}

ShadowedScene read_database(const std::filesystem::path& path) {
  std::vector<std::string> warnings;
  return read_database(path, {}, warnings);
}

}  // namespace shadowgen
