#include "scene_arrays.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstddef>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace py = pybind11;

namespace shadowgen::python {
namespace {

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// `what` names the thing at fault in a ValueError: "face 'roof'", "light 'sun'".
[[noreturn]] void bad(const std::string& what, const std::string& problem) {
  throw py::value_error(what + ": " + problem);
}

std::string shape_text(const Points& points) {
  std::string text = "(";
  for (py::ssize_t axis = 0; axis < points.ndim(); ++axis) {
    text += (axis ? ", " : "") + std::to_string(points.shape(axis));
  }
  return text + (points.ndim() == 1 ? ",)" : ")");
}

api::Loop loop_of(const py::handle& object, const std::string& what) {
  const Points points = Points::ensure(object);
  if (!points) {
    PyErr_Clear();
    bad(what, "not an array of numbers");
  }
  if (points.ndim() != 2 || points.shape(1) != 3) {
    bad(what, "an (n, 3) array of points expected, not shape " + shape_text(points));
  }
  api::Loop loop;
  const auto at = points.unchecked<2>();
  for (py::ssize_t i = 0; i < at.shape(0); ++i) loop.push_back({at(i, 0), at(i, 1), at(i, 2)});
  return loop;
}

api::Point point_of(const py::handle& object, const std::string& what) {
  const Points point = Points::ensure(object);
  if (!point || point.ndim() != 1 || point.shape(0) != 3) {
    PyErr_Clear();
    bad(what, "3 numbers expected");
  }
  return {point.at(0), point.at(1), point.at(2)};
}

api::FaceData face_of(const py::handle& item, std::size_t index) {
  const std::string at = "face " + std::to_string(index);
  if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item)) {
    bad(at, "(id, outer) or (id, outer, holes) expected");
  }
  const auto fields = py::reinterpret_borrow<py::sequence>(item);
  if (fields.size() != 2 && fields.size() != 3) {
    bad(at, "(id, outer) or (id, outer, holes) expected, not " + std::to_string(fields.size()) +
                " items");
  }
  if (!py::isinstance<py::str>(fields[0])) bad(at, "its id is not a str");
  api::FaceData face;
  face.id = fields[0].cast<std::string>();
  const std::string what = "face '" + face.id + "'";
  face.polygon.outer = loop_of(fields[1], what + ": outer");
  if (fields.size() == 3) {
    std::size_t hole = 0;
    for (const py::handle& loop : fields[2]) {
      face.polygon.holes.push_back(loop_of(loop, what + ": hole " + std::to_string(hole++)));
    }
  }
  return face;
}

// Each key a light dict may hold, and what it sets.
using Setter = std::function<void(api::LightData&, const py::handle&, const std::string& what)>;
const std::map<std::string, Setter>& light_keys() {
  static const std::map<std::string, Setter> keys = {
      {"id", [](api::LightData&, const py::handle&, const std::string&) {}},
      {"type",
       [](api::LightData& light, const py::handle& value, const std::string& what) {
         const std::string type = py::str(value);
         if (type == "directional") {
           light.kind = api::LightKind::kDirectional;
         } else if (type == "point") {
           light.kind = api::LightKind::kPoint;
         } else if (type == "sun") {
           light.kind = api::LightKind::kSun;
         } else {
           bad(what, "type '" + type + "' is none of directional, point, sun");
         }
       }},
      {"direction",
       [](api::LightData& light, const py::handle& value, const std::string& what) {
         light.direction = point_of(value, what + ": direction");
       }},
      {"position",
       [](api::LightData& light, const py::handle& value, const std::string& what) {
         light.position = point_of(value, what + ": position");
       }},
      {"intensity",
       [](api::LightData& light, const py::handle& value, const std::string& what) {
         light.intensity = point_of(value, what + ": intensity");
       }},
      {"range",
       [](api::LightData& light, const py::handle& value, const std::string& what) {
         const auto range = value.cast<std::map<std::string, double>>();
         api::RangeData data;
         for (const auto& [key, number] : range) {
           if (key == "falloff_start") {
             data.falloff_start = number;
           } else if (key == "end") {
             data.end = number;
           } else if (key == "exponent") {
             data.exponent = number;
           } else {
             bad(what, "range: unknown key '" + key + "' (falloff_start, end, exponent)");
           }
         }
         light.range = data;
       }},
      {"time", [](api::LightData& light, const py::handle& value,
                  const std::string&) { light.time = value.cast<std::string>(); }},
      {"from", [](api::LightData& light, const py::handle& value,
                  const std::string&) { light.from = value.cast<std::string>(); }},
      {"to", [](api::LightData& light, const py::handle& value,
                const std::string&) { light.to = value.cast<std::string>(); }},
      {"step_min", [](api::LightData& light, const py::handle& value,
                      const std::string&) { light.step_min = value.cast<int>(); }},
  };
  return keys;
}

api::LightData light_of(const py::handle& item, std::size_t index) {
  if (!py::isinstance<py::dict>(item)) bad("light " + std::to_string(index), "a dict expected");
  const auto fields = py::reinterpret_borrow<py::dict>(item);
  if (!fields.contains("id") || !py::isinstance<py::str>(fields["id"])) {
    bad("light " + std::to_string(index), "no str 'id'");
  }
  api::LightData light;
  light.id = fields["id"].cast<std::string>();
  const std::string what = "light '" + light.id + "'";
  for (const auto& [key, value] : fields) {
    const std::string name = py::str(key);
    const auto setter = light_keys().find(name);
    if (setter == light_keys().end()) bad(what, "unknown key '" + name + "'");
    try {
      setter->second(light, value, what);
    } catch (const py::cast_error&) {
      bad(what, "'" + name + "' is of the wrong type");
    }
  }
  return light;
}

api::SiteData site_of(const py::handle& object) {
  api::SiteData site;
  const std::map<std::string, double*> fields = {{"latitude_deg", &site.latitude_deg},
                                                 {"longitude_deg", &site.longitude_deg},
                                                 {"elevation_m", &site.elevation_m},
                                                 {"utc_offset_h", &site.utc_offset_h},
                                                 {"north_axis_deg", &site.north_axis_deg}};
  std::map<std::string, double> given;
  try {
    given = object.cast<std::map<std::string, double>>();
  } catch (const py::cast_error&) {
    bad("site", "a dict of numbers expected");
  }
  for (const auto& [key, number] : given) {
    const auto field = fields.find(key);
    if (field == fields.end()) bad("site", "unknown key '" + key + "'");
    *field->second = number;
  }
  return site;
}

}  // namespace

api::SceneData scene_data(const std::string& name, const py::object& faces,
                          const py::object& lights, const py::object& site,
                          const py::object& groups) {
  api::SceneData data;
  data.name = name;
  std::size_t index = 0;
  for (const py::handle& face : faces) data.faces.push_back(face_of(face, index++));
  index = 0;
  for (const py::handle& light : lights) data.lights.push_back(light_of(light, index++));
  if (!site.is_none()) data.site = site_of(site);
  if (!groups.is_none()) {
    for (const auto& [id, patterns] : groups.cast<py::dict>()) {
      data.groups.push_back({py::str(id), patterns.cast<std::vector<std::string>>()});
    }
  }
  return data;
}

}  // namespace shadowgen::python
