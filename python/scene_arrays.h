#pragma once

// A scene's faces, lights, site and groups given from Python as numbers (numpy arrays or
// anything numpy.asarray takes), as shadowgen::api::SceneData holds them:
//
//   faces   [(id, outer), (id, outer, [hole, ...]), ...]  each loop an (n, 3) array of
//           points, n >= 3, its last point not repeated; the front is the side from which
//           `outer` runs counter-clockwise
//   lights  [{"id": "sun", "type": "directional", "direction": (x, y, z)},
//            {"id": "lamp", "type": "point", "position": (x, y, z), "intensity": (r, g, b),
//             "range": {"falloff_start": a, "end": b, "exponent": e}},
//            {"id": "day", "type": "sun", "from": "2026-03-21T06:00", "to": ..., "step_min": 30},
//            {"id": "noon", "type": "sun", "time": "2026-03-21T12:00"}]
//   site    {"latitude_deg": .., "longitude_deg": .., "elevation_m": .., "utc_offset_h": ..,
//            "north_axis_deg": ..}, each optional (0)
//   groups  {"garden": ["garden*", "lawn/*"], ...}
//
// The keys and types are the scene file's (docs/scene-format.md). What is not of this
// shape (a loop not (n, 3), a key no light type has, a type that is no light's) raises
// ValueError naming the face or light and what is wrong; what is of this shape is checked
// by make_scene as a scene file is.

#include <pybind11/pybind11.h>
#include <shadowgen/shadowgen.h>

#include <string>

namespace shadowgen::python {

api::SceneData scene_data(const std::string& name, const pybind11::object& faces,
                          const pybind11::object& lights, const pybind11::object& site,
                          const pybind11::object& groups);

}  // namespace shadowgen::python
