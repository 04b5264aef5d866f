#pragma once

// Sums over groups of faces (docs/scene-format.md, "Groups"): a report's per-face rows
// added up per group, so that "lit area per building" or "the share of the garden with
// two hours of sun" is read off one row. Each face of a group counts once; a face in
// several groups counts in each.

#include <cstddef>
#include <span>
#include <vector>

#include "shadowgen/groups/face_groups.h"
#include "shadowgen/output/report.h"
#include "shadowgen/output/sun_hours_report.h"

namespace shadowgen {

struct GroupLitRow {
  std::size_t group = 0;  // index into the groups given
  std::size_t light = 0;
  std::size_t faces = 0;      // the group's faces
  double area = 0.0;          // Σ of its faces' areas
  double lit_area = 0.0;      // Σ of their lit areas under the light
  double lit_fraction = 0.0;  // lit_area / area; 0 for a group without area
};

// One row per (group, light), groups in order, lights in scene order, from report_rows'
// rows (one per (face, light), face by face, `lights` per face). Sums are compensated
// (Neumaier), so they stay within a rounding or two of the exact sums of the rows.
std::vector<GroupLitRow> group_lit_rows(std::span<const ReportRow> rows, std::size_t lights,
                                        std::span<const groups::FaceGroup> groups);

struct GroupSunHoursRow {
  std::size_t group = 0;
  std::size_t path = 0;  // index into ShadowedScene::sun_paths
  std::size_t faces = 0;
  double area = 0.0;        // Σ of its faces' areas
  double mean_hours = 0.0;  // Σ mean hours × area / area over its faces; 0 without area
  double min_hours = 0.0;   // the least and most of its faces with area; 0 without area
  double max_hours = 0.0;
  std::vector<double> area_at_least;   // per threshold: Σ of its faces' areas with ≥ T hours
  std::vector<double> share_at_least;  // per threshold: area_at_least / area; 0 without area
};

// One row per (group, path), groups in order, paths in order, from sun_hours_rows' rows
// (one per (face, path), face by face, `paths` per face).
std::vector<GroupSunHoursRow> group_sun_hours_rows(std::span<const SunHoursRow> rows,
                                                   std::size_t paths,
                                                   std::span<const groups::FaceGroup> groups);

}  // namespace shadowgen
