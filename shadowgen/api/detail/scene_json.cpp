#include "detail/scene_json.h"

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string_view>

#include "shadowgen/json/json_writer.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/one_line.h"

namespace shadowgen::api::detail {
namespace {

using Layout = JsonWriter::Layout;

bool finite(const Point& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

void write_loop(JsonWriter& json, const Loop& loop, const SceneData& data, const FaceData& face) {
  json.begin_array();
  for (const Point& p : loop) {
    if (!finite(p)) {
      throw shadowgen::InputError(data.name, face.id, "a vertex coordinate is not a finite number");
    }
    json.value(glm::dvec3(p[0], p[1], p[2]));
  }
  json.end_array();
}

void write_face(JsonWriter& json, const FaceData& face, const SceneData& data) {
  json.begin_object().key("id").value(face.id).key("outer");
  write_loop(json, face.polygon.outer, data, face);
  if (!face.polygon.holes.empty()) {
    json.key("holes").begin_array();
    for (const Loop& hole : face.polygon.holes) write_loop(json, hole, data, face);
    json.end_array();
  }
  json.end_object();
}

// `value` of light `light`'s `what`, refused where it is not finite.
double checked(double value, const LightData& light, std::string_view what, const SceneData& data) {
  if (!std::isfinite(value)) {
    throw shadowgen::InputError(
        data.name, "",
        "light '" + one_line(light.id) + "': " + std::string(what) + " is not a finite number");
  }
  return value;
}

void write_point(JsonWriter& json, std::string_view key, const Point& p, const LightData& light,
                 const SceneData& data) {
  for (const double v : p) checked(v, light, key, data);
  json.key(key).value(glm::dvec3(p[0], p[1], p[2]));
}

void write_light(JsonWriter& json, const LightData& light, const SceneData& data) {
  json.begin_object().key("id").value(light.id);
  switch (light.kind) {
    case LightKind::kDirectional:
      json.key("type").value("directional");
      write_point(json, "direction", light.direction, light, data);
      write_point(json, "intensity", light.intensity, light, data);
      break;
    case LightKind::kPoint:
      json.key("type").value("point");
      write_point(json, "position", light.position, light, data);
      write_point(json, "intensity", light.intensity, light, data);
      if (light.range) {
        json.key("range").begin_object();
        json.key("falloff_start").value(checked(light.range->falloff_start, light, "range", data));
        json.key("end").value(checked(light.range->end, light, "range", data));
        json.key("exponent").value(checked(light.range->exponent, light, "range", data));
        json.end_object();
      }
      break;
    case LightKind::kSun:
      json.key("type").value("sun");
      if (!light.time.empty()) json.key("time").value(light.time);
      if (!light.from.empty()) json.key("from").value(light.from);
      if (!light.to.empty()) json.key("to").value(light.to);
      if (light.step_min != 0) {
        // A negative step is the reader's to refuse, with its message.
        json.key("step_min").value(static_cast<double>(light.step_min));
      }
      break;
  }
  json.end_object();
}

void write_site(JsonWriter& json, const SiteData& site, const SceneData& data) {
  const auto number = [&](std::string_view key, double value) {
    if (!std::isfinite(value)) {
      throw shadowgen::InputError(data.name, "",
                                  "site: " + std::string(key) + " is not a finite number");
    }
    json.key(key).value(value);
  };
  json.key("site").begin_object();
  number("latitude_deg", site.latitude_deg);
  number("longitude_deg", site.longitude_deg);
  number("elevation_m", site.elevation_m);
  number("utc_offset_h", site.utc_offset_h);
  number("north_axis_deg", site.north_axis_deg);
  json.end_object();
}

}  // namespace

std::string scene_json(const SceneData& data) {
  JsonWriter json;
  json.begin_object(Layout::kLines).key("format").value("shadowgen-scene/1");
  json.key("polygons").begin_array(Layout::kLines);
  for (const FaceData& face : data.faces) write_face(json, face, data);
  json.end_array();
  json.key("lights").begin_array(Layout::kLines);
  for (const LightData& light : data.lights) write_light(json, light, data);
  json.end_array();
  if (data.site) write_site(json, *data.site, data);
  if (!data.groups.empty()) {
    json.key("groups").begin_array(Layout::kLines);
    for (const GroupData& group : data.groups) {
      json.begin_object().key("id").value(group.id).key("faces").begin_array();
      for (const std::string& pattern : group.faces) json.value(pattern);
      json.end_array().end_object();
    }
    json.end_array();
  }
  json.end_object();
  return json.take();
}

}  // namespace shadowgen::api::detail
