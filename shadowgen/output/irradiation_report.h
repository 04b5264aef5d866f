#pragma once

// Direct irradiation report (docs/scene-format.md, "Direct irradiation report"): per face
// and sun path, the direct solar energy the face receives over the path, from a weather
// file's hourly direct normal irradiance and the exact lit area of every instant:
//
//   Σ over instants k, over the face's parts i:
//       DNI(k) × lit area of part i at k × cos(incidence of the sun on part i at k)
//       × step_min / 60
//
// with DNI(k) the direct normal radiation of the weather hour holding instant k
// (weather/irradiance.h: Wh/m² over the hour, the hour's mean irradiance in W/m²), and
// the incidence measured between the part's front normal and the direction to the sun.
// Each instant stands for the step_min minutes that start at it. Only parts lit from the
// front have lit area, so every cosine counted is positive. Energies are in Wh when the
// scene's coordinates are metres (Wh per square scene unit of irradiance otherwise).

#include <cstddef>
#include <string>
#include <vector>

#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/report.h"

namespace shadowgen {

struct IrradiationRow {
  std::size_t face = 0;
  std::size_t path = 0;  // index into ShadowedScene::sun_paths
  double area = 0.0;
  double direct_wh = 0.0;    // on the face's lit areas, as above
  double unshaded_wh = 0.0;  // the same with the whole of every part facing the sun lit
};

// One row per (face, path): faces in scene order, paths in the order of their first
// instant. Throws InputError for a database without sun paths, and (naming the weather
// file and its line) for an instant whose hour the weather file lacks or marks missing.
std::vector<IrradiationRow> irradiation_rows(const ShadowedScene& shadowed, const Weather& weather);

// CSV: face_id,sun_path,area,direct_wh,direct_wh_per_area,unshaded_direct_wh_per_area
// (per area: over the face's area, 0 for a face without area); numbers as the report CSV
// writes them, ids as CsvIds says.
std::string irradiation_csv(const ShadowedScene& shadowed, const Weather& weather,
                            CsvIds ids = CsvIds::kExact);

}  // namespace shadowgen
