#pragma once

// Shadow area analysis: area, lit area and lit fraction per (face, light), from the
// shadowed database alone.

#include <string>
#include <vector>

#include "shadowgen/shadowed_scene.h"

namespace shadowgen {

struct ReportRow {
  std::size_t face = 0;
  std::size_t light = 0;
  double area = 0.0;
  double lit_area = 0.0;
  double lit_fraction = 0.0;  // lit_area / area; 0 for a zero-area face
};

// One row per (face, light): faces in scene order, lights in scene order.
std::vector<ReportRow> report_rows(const ShadowedScene& shadowed);

// The spec's CSV: header face_id,light_id,area,lit_area,lit_fraction; numbers with %.17g;
// ids quoted as RFC 4180 says when they hold a comma, a quote or a line break.
std::string report_csv(const ShadowedScene& shadowed);
// The same rows as JSON, with totals per light and for the scene.
std::string report_json(const ShadowedScene& shadowed);

}  // namespace shadowgen
