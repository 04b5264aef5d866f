#include "database_sun_hours.h"

#include <cmath>
#include <string>

#include "shadowgen/model/instant_blocks.h"

namespace shadowgen::scene::detail {
namespace {

namespace key = database::key;

// One lit area per instant of `path` (in a shard, per instant of its own), none negative.
std::vector<double> read_instant_areas(const JsonValue& value, const SunPathHours& path,
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
void read_part_lit_areas(JsonObject& sum, const Face& face, SunPathHours& path, bool shard) {
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

// [[x, y], ...]: a loop in a part's chart, three points at least.
clipper::Loop2 read_chart_loop(const JsonValue& value) {
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

// A shard's "nodes" on one face: nodes of the path's tree covering the shard's blocks,
// in order (model/instant_blocks.h); their pieces are checked against the face where
// they are joined (FaceSunHours).
std::vector<SunHoursNode> read_nodes(const JsonValue& value, const SunPathHours& path,
                                     const ShardPlace& shard) {
  const IndexRun blocks = shard_blocks(block_count(path.instants.size()), shard.index, shard.count);
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

}  // namespace

void read_face_sun_hours(JsonObject& entry, const Face& face, ShadowedScene& shadowed,
                         const LitLayout& layout, std::vector<std::vector<JsonPlace>>& places) {
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
      places[p].push_back(sum.value().place());
      continue;
    }
    if (shard) {
      path.nodes.push_back(read_nodes(sum.get(key::kNodes), path, *shadowed.shard));
      sum.finish();
      places[p].push_back(sum.value().place());
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
      out.push_back({hours.number(), read_database_lit(region.get(key::kPolygons), face, layout)});
      region.finish();
    }
    sum.finish();
    places[p].push_back(sum.value().place());
  }
  sums.finish();
}

}  // namespace shadowgen::scene::detail
