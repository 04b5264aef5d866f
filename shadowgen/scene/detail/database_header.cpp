#include "database_header.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "json_entities.h"
#include "shadowgen/model/instant_blocks.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/sun/civil_time.h"
#include "site_entry.h"

namespace shadowgen::scene::detail {
namespace {

namespace key = database::key;

// Shards a run may be cut into: far more than any scheduler runs at once.
constexpr std::size_t kMaxShards = 1'000'000;

// "method": {"name": "rays" | "shadow-map" | "exact", "samples": N, "resolution": R}
// (samples for a sampled method, resolution for the shadow map alone).
Method read_method(const JsonValue& value) {
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
std::vector<bool> kept_lights(std::size_t lights, bool exact,
                              const std::vector<SunPathHours>& paths) {
  std::vector<bool> kept(lights, exact);
  for (const SunPathHours& path : paths) {
    if (path.lit_polygons_kept) continue;
    for (const std::size_t l : path.instants) kept[l] = false;
  }
  return kept;
}

// "shard": {"index": K, "count": N}, 1 <= K <= N.
ShardPlace read_shard(const JsonValue& value) {
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
std::pair<std::int64_t, std::int64_t> read_span(JsonObject& entry, SunPathHours& path) {
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
Site read_site(const JsonValue& value) {
  const SourceSite keys = read_site_keys(value);
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
void read_sun_paths(const JsonValue& value, const Scene& scene,
                    const std::optional<ShardPlace>& shard, std::vector<SunPathHours>& out) {
  const JsonArray paths = value.array();
  IdRegistry ids;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    JsonObject entry = paths.at(i).object();
    SunPathHours path;
    path.id = read_claimed_id(entry, ids, "sun path");
    const JsonValue step = entry.get(key::kStepMin);
    path.step_min = static_cast<int>(std::min<std::size_t>(step.index(), 1'000'001));
    if (path.step_min <= 0) step.fail("a sun path needs a positive step_min");
    const auto [from, to] = read_span(entry, path);
    const JsonValue kept = entry.get(key::kInstantPolygons);
    if (kept.string() != key::kKept && kept.string() != key::kDropped) {
      kept.fail("expected 'kept' or 'dropped'");
    }
    path.lit_polygons_kept = kept.string() == key::kKept;
    if (shard && path.lit_polygons_kept) {
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
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
      const std::optional<SunInstant>& sun = scene.lights[l].sun;
      if (!sun || sun->sun_id != path.id) continue;
      const std::string instant = "light '" + one_line(scene.lights[l].id) + "' of this path";
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
        const Light& last = scene.lights[path.instants.back()];
        entry.value().fail(instant + " is at " + sun->time + ", " +
                           (at == before ? "the time" : "before the time") + " of light '" +
                           one_line(last.id) + "' before it (" + last.sun->time +
                           "): a path's instants come in time order, one per step");
      }
      before = at;
      path.instants.push_back(l);
    }
    entry.finish();
    if (shard) {
      const IndexRun own = shard_instants(path.instants.size(), *shard);
      path.shard_first = own.first;
      path.shard_last = own.last;
    }
    out.push_back(std::move(path));
  }
}

}  // namespace

DatabaseHeader read_database_header(JsonObject& top, ShadowedScene& shadowed) {
  DatabaseHeader header;
  const JsonValue format = top.get(key::kFormat);
  const std::optional<database::Layout> layout = database::layout_of(format.string());
  if (!layout) {
    format.fail("unsupported format '" + format.string() + "'; this reader reads '" +
                std::string(database::kIndexedFormat) + "' and '" +
                std::string(database::kInlineFormat) + "'");
  }
  header.layout = *layout;
  std::optional<ShardPlace> shard;
  if (const std::optional<JsonValue> value = top.find(key::kShard)) shard = read_shard(*value);
  std::optional<Method> sampled;
  if (const std::optional<JsonValue> value = top.find(key::kMethod)) {
    const Method method = read_method(*value);
    if (!method.exact()) {
      if (shard) value->fail("a shard is made by the exact method only");
      sampled = method;
    }
  }
  Scene scene;
  scene.file = shadowed.scene().file;
  if (const std::optional<JsonValue> site = top.find(key::kSite)) scene.site = read_site(*site);
  const JsonArray lights = top.get(key::kLights).array();
  IdRegistry light_ids;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    scene.lights.push_back(read_light(lights.at(i), light_ids, Source::kDatabase));
    header.light_index.emplace(scene.lights.back().id, i);
  }
  const JsonArray views = top.get(key::kViews).array();
  IdRegistry view_ids;
  for (std::size_t i = 0; i < views.size(); ++i) {
    scene.views.push_back(read_view(views.at(i), view_ids, Source::kDatabase));
  }
  std::vector<SunPathHours> paths;
  if (const std::optional<JsonValue> value = top.find(key::kSunPaths)) {
    read_sun_paths(*value, scene, shard, paths);
  }
  for (const SunPathHours& path : paths) {
    scene.sun_paths.push_back({path.id, path.step_min, path.from, path.to});
  }
  const std::size_t light_count = scene.lights.size();
  LitTable lit(0, light_count, kept_lights(light_count, !sampled, paths));
  if (sampled) {
    for (const SunPathHours& path : paths) {
      if (path.regions_kept || path.lit_polygons_kept) {
        top.get(key::kSunPaths)
            .fail("sun path '" + one_line(path.id) +
                  "': a sampled method keeps lit areas alone: \"regions\" "
                  "and \"instant_polygons\" must be \"dropped\"");
      }
    }
    header.instant.assign(light_count, 0);
    for (const SunPathHours& path : paths) {
      for (const std::size_t l : path.instants) header.instant[l] = 1;
    }
    shadowed = ShadowedScene(std::move(scene), std::move(lit),
                             Estimate{*sampled, std::vector<std::vector<double>>(light_count)});
  } else {
    shadowed = ShadowedScene(std::move(scene), std::move(lit));
  }
  shadowed.sun_paths = std::move(paths);
  shadowed.shard = shard;
  return header;
}

}  // namespace shadowgen::scene::detail
