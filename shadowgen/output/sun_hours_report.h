#pragma once

// Sun-hours report (docs/scene-format.md, "Sun-hours report"): per face and sun path, the
// face's area, its area-weighted mean sun hours, the least and most hours on it, and the
// area receiving at least each threshold of hours (the BRE "two hours of sun on 21 March"
// test is the threshold 2), from the sun-hours regions of the shadowed database alone.

#include <span>
#include <string>
#include <vector>

#include "shadowgen/groups/face_groups.h"
#include "shadowgen/model/shadowed_scene.h"
#include "shadowgen/output/report.h"

namespace shadowgen {

struct SunHoursRow {
  std::size_t face = 0;
  std::size_t path = 0;  // index into ShadowedScene::sun_paths
  double area = 0.0;
  double mean_hours = 0.0;  // Σ hours × area / area; 0 for a face without area
  double min_hours = 0.0;   // over the regions with area; 0 for a face without area
  double max_hours = 0.0;
  std::vector<double> area_at_least;  // per threshold: Σ area of regions with hours >= it
};

// One row per (face, path): faces in scene order, paths in the order of their first
// instant. Throws InputError (naming the input, Scene::file, and the problem) for a database
// without sun paths, and std::invalid_argument for a threshold that is negative or not finite.
std::vector<SunHoursRow> sun_hours_rows(const ShadowedScene& shadowed,
                                        std::span<const double> thresholds);

// CSV: face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours, then a column
// area_at_least_<T>h per threshold T (T written shortest: 2, 1.5); numbers as the report
// CSV writes them, ids as CsvIds says. With `groups`, one empty line and a second table
// follow: group_id,sun_path,faces,area,mean_sun_hours,min_sun_hours,max_sun_hours, then
// area_at_least_<T>h per threshold, then share_at_least_<T>h per threshold, one row per
// (group, path) (group_sun_hours_rows, output/group_sums.h).
std::string sun_hours_csv(const ShadowedScene& shadowed, std::span<const double> thresholds,
                          CsvIds ids = CsvIds::kExact,
                          std::span<const groups::FaceGroup> groups = {});

}  // namespace shadowgen
