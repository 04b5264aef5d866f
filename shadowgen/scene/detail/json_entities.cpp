#include "detail/json_entities.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <utility>

#include "coordinate_range.h"
#include "shadowgen/model/view_limits.h"

namespace shadowgen::scene::detail {
namespace {

// A position in the scene: [x, y, z] within the supported coordinate range.
glm::dvec3 read_point(const JsonValue& value) {
  const glm::dvec3 p = value.vec3();
  if (const std::optional<std::string> problem = coordinate_problem(p)) value.fail(*problem);
  return p;
}

// A member a database must have and a scene may leave out.
std::optional<JsonValue> member(JsonObject& object, std::string_view key, Source source) {
  if (source == Source::kDatabase) return object.get(key);
  return object.find(key);
}

LightRange read_range(const JsonValue& value, Source source) {
  JsonObject object = value.object();
  LightRange range;
  const JsonValue end = object.get("end");
  range.end = end.number();
  const std::optional<JsonValue> start = member(object, "falloff_start", source);
  if (start) range.falloff_start = start->number();
  const std::optional<JsonValue> exponent = member(object, "exponent", source);
  if (exponent) range.exponent = exponent->number();
  // Absent members keep their defaults, which pass these checks.
  if (!(range.end > 0.0)) end.fail("must be greater than 0");
  if (start && range.falloff_start < 0.0) start->fail("must not be negative");
  if (start && range.falloff_start > range.end) start->fail("must not exceed 'end'");
  if (exponent && range.exponent < 0.0) exponent->fail("must not be negative");
  object.finish();
  return range;
}

void read_light_kind(JsonObject& entry, Light& light, Source source) {
  const JsonValue type = entry.get("type");
  const std::string kind = type.string();
  if (kind == "directional") {
    light.type = LightType::kDirectional;
    const JsonValue direction = entry.get("direction");
    light.direction = direction.vec3();
    if (light.direction == glm::dvec3(0.0)) direction.fail("must not be zero");
    // A database keeps what it was written with, bit for bit (scenes read by shadowgen
    // hold scaled directions already).
    if (source == Source::kScene) light.direction = power_of_two_scaled(light.direction);
    if (const std::optional<JsonValue> range = entry.find("range")) {
      range->fail("a range applies to point lights only");
    }
  } else if (kind == "point") {
    light.type = LightType::kPoint;
    light.position = read_point(entry.get("position"));
    if (const std::optional<JsonValue> range = entry.find("range")) {
      light.range = read_range(*range, source);
    }
  } else {
    // A scene's `sun` entries are read apart (sun_light.h); a database holds their
    // instants as directional lights.
    type.fail("unknown light type '" + kind + "' (expected " +
              (source == Source::kScene ? "'directional', 'point' or 'sun')"
                                        : "'directional' or 'point')"));
  }
}

// A database light's "sun": what the `sun` entry that placed it says of it (SunInstant).
SunInstant read_sun_instant(const JsonValue& value) {
  JsonObject sun = value.object();
  SunInstant instant;
  instant.sun_id = sun.get("entry").string();
  if (instant.sun_id.empty()) sun.get("entry").fail("must not be empty");
  instant.time = sun.get("time").string();
  const JsonValue step = sun.get("step_min");
  if (step.index() > 1'000'000) step.fail("expected a number of minutes up to 1000000");
  instant.step_min = static_cast<int>(step.index());
  instant.azimuth_deg = sun.get("azimuth_deg").number();
  instant.elevation_deg = sun.get("elevation_deg").number();
  sun.finish();
  return instant;
}

}  // namespace

// Only a direction's direction matters (the spec: it need not be unit length); at this
// scale 1e-300 or 1e300 long directions neither underflow nor overflow in dot products.
glm::dvec3 power_of_two_scaled(const glm::dvec3& v) {
  const double largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  int exponent = 0;
  std::frexp(largest, &exponent);
  return {std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent), std::ldexp(v.z, -exponent)};
}

void IdRegistry::claim(const std::string& id, std::string owner, const JsonValue& at) {
  const auto [it, fresh] = owners_.emplace(id, std::move(owner));
  if (!fresh) at.fail("duplicate id '" + id + "' (already used by " + it->second + ")");
}

bool IdRegistry::try_claim(const std::string& id, std::string owner) {
  return owners_.emplace(id, std::move(owner)).second;
}

std::string read_id(JsonObject& entry) {
  const JsonValue value = entry.get("id");
  std::string id = value.string();
  if (id.empty()) value.fail("an id must not be empty");
  return id;
}

std::string read_claimed_id(JsonObject& entry, IdRegistry& ids, const std::string& kind) {
  std::string id = read_id(entry);
  ids.claim(id, "another " + kind, entry.get("id"));
  entry.name(kind + " '" + id + "'", id);
  return id;
}

Light read_light(const JsonValue& value, IdRegistry& ids, Source source) {
  JsonObject entry = value.object();
  Light light;
  light.id = read_claimed_id(entry, ids, "light");
  read_light_kind(entry, light, source);
  if (source == Source::kDatabase) {
    if (const std::optional<JsonValue> sun = entry.find("sun")) light.sun = read_sun_instant(*sun);
  }
  if (const std::optional<JsonValue> intensity = member(entry, "intensity", source)) {
    light.intensity = intensity->vec3();
    if (light.intensity.x < 0.0 || light.intensity.y < 0.0 || light.intensity.z < 0.0) {
      intensity->fail("must not be negative");
    }
  }
  entry.finish();
  return light;
}

ViewSpec read_view(const JsonValue& value, IdRegistry& ids, Source source) {
  JsonObject entry = value.object();
  ViewSpec view;
  view.id = read_claimed_id(entry, ids, "view");
  view.eye = read_point(entry.get("eye"));
  view.target = read_point(entry.get("target"));
  const std::optional<JsonValue> up = member(entry, "up", source);
  if (up) view.up = up->vec3();
  const std::optional<JsonValue> fov = member(entry, "fov_deg", source);
  if (fov) view.fov_deg = fov->number();
  if (view.eye == view.target) entry.value().fail("'eye' and 'target' must differ");
  const glm::dvec3 sight = view.target - view.eye;
  const std::string sight_name = "from 'eye' to 'target'";
  if (up) {
    if (const std::optional<std::string> problem = up_problem(sight, view.up, sight_name)) {
      up->fail(*problem);
    }
  } else if (along_sight(sight, view.up)) {
    entry.value().fail("the default 'up' [0, 0, 1] is parallel to the direction " + sight_name +
                       "; give an 'up'");
  }
  if (fov) {
    if (const std::optional<std::string> problem = range_problem(view.fov_deg, fov_range())) {
      fov->fail(*problem);
    }
  }
  entry.finish();
  return view;
}

hsr::Polygon3 read_polygon(JsonObject& object) {
  hsr::Polygon3 polygon;
  polygon.outer = object.get("outer").vec3_list();
  if (const std::optional<JsonValue> holes = object.find("holes")) {
    const JsonArray list = holes->array();
    polygon.holes.reserve(list.size());
    for (std::size_t k = 0; k < list.size(); ++k) polygon.holes.push_back(list.at(k).vec3_list());
  }
  return polygon;
}

}  // namespace shadowgen::scene::detail
