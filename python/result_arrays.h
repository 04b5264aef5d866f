#pragma once

// Results as Python reads them: columns as numpy arrays, rows as tuples.
//
//   rows = shadows.lit_areas()                # a LitAreas, one row per (face, light)
//   for face_id, light_id, area, lit_area in rows: ...
//   rows.face, rows.light                     # int64 indices into the scene's faces, lights
//   rows.face_id, rows.light_id               # str arrays
//   rows.area, rows.lit_area, rows.lit_fraction   # float64, the report CSV's numbers
//
// SunHoursTable is the same for sun_hours() (rows (face_id, path_id, area, mean_hours,
// min_hours, max_hours); area_at_least an (rows, thresholds) array). A polygon is
// (outer, [hole, ...]), each loop an (n, 3) float64 array.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <shadowgen/shadowgen.h>

#include <vector>

namespace shadowgen::python {

struct LitAreas {
  std::vector<api::LitArea> rows;
};

struct SunHoursTable {
  std::vector<double> thresholds;
  std::vector<api::SunHours> rows;
};

// The classes LitAreas and SunHoursTable in `module`.
void register_results(pybind11::module_& module);

pybind11::list polygons_object(const std::vector<api::PolygonData>& polygons);

}  // namespace shadowgen::python
