#pragma once

// Shadow area analysis: area, lit area and lit fraction per (face, light), from the
// shadowed database alone.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "shadowgen/groups/face_groups.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

struct ReportRow {
  std::size_t face = 0;
  std::size_t light = 0;
  double area = 0.0;
  double lit_area = 0.0;
  double lit_fraction = 0.0;  // lit_area / area; 0 for a zero-area face
};

// One row per (face, light): faces in scene order, lights in scene order. `area` is the
// face's area (holes removed, shadowgen::area of its parts), `lit_area` that of its lit
// polygons for the light, never above `area` by rounding (an excess within 2^-40 of the
// area is clamped, so 0 <= lit_fraction <= 1; anything larger is left to show). Throws
// InputError (naming the input, Scene::file, and the face) when an area is not a finite
// number: no report, in any of the forms below, holds inf or nan.
std::vector<ReportRow> report_rows(const ShadowedScene& shadowed);

// How ids are written in the CSV.
enum class CsvIds {
  kExact,  // byte for byte (the spec's CSV, for reading back)
  // An id that begins with '=', '+', '-', '@', a tab or a carriage return gets a leading
  // "'": spreadsheets take such a field for a formula, which a scene from elsewhere could
  // use to run one on whoever opens the report (CSV injection). The id then reads back
  // with that "'" in front.
  kSpreadsheetSafe,
};

// The spec's CSV: header face_id,light_id,area,lit_area,lit_fraction; numbers with %.17g;
// ids quoted as RFC 4180 says when they hold a comma, a quote or a line break. Lines end
// with "\n".
//
// With `groups` (groups/face_groups.h, resolved on shadowed.scene()), one empty line and a
// second table follow the rows: header group_id,light_id,faces,area,lit_area,lit_fraction,
// one row per (group, light), groups in order (group_lit_rows, output/group_sums.h).
std::string report_csv(const ShadowedScene& shadowed, CsvIds ids = CsvIds::kExact,
                       std::span<const groups::FaceGroup> groups = {});

// The same rows as JSON, with totals per light and for the scene:
//
//   {
//     "format": "shadowgen-report/1",
//     "rows": [
//       {"face_id":"wall","light_id":"sun","area":28.0,"lit_area":17.25,
//        "lit_fraction":0.6160714285714286},                          one row per line
//     ],
//     "lights": [                                                    scene order
//       {"light_id":"sun","area":A,"lit_area":L,"lit_fraction":L/A}
//     ],
//     "totals": {"area":A,"lit_area":L,"lit_fraction":L/A},
//     "groups": [                                                    only with `groups`
//       {"group_id":"garden","light_id":"sun","faces":3,"area":A,"lit_area":L,
//        "lit_fraction":L/A}                                        per (group, light)
//     ]
//   }
//
// A light's totals sum its rows: `area` is the scene's whole face area, `lit_area` what
// that light lights of it. The scene's totals sum every row, so `area` counts each face
// once per light and `lit_fraction` is the area-weighted mean over the lights. Sums are
// compensated (Neumaier), fractions are 0 where the area is 0, and numbers are the
// shortest form that reads back to the same double.
std::string report_json(const ShadowedScene& shadowed,
                        std::span<const groups::FaceGroup> groups = {});

// A summary for people to read, in aligned columns (ids left, numbers right, two spaces
// between columns, no trailing blanks):
//
//   light_id  faces  lit_faces  area  lit_area  lit_fraction
//   sun           3          2   114        98        0.8596
//
//   most shadowed faces under sun (lowest lit fraction first, 2 of 2)
//   face_id  area  lit_area  lit_fraction
//   ground     98        82        0.8367
//   roof       16        16        1.0000
//
// First one row per light (scene order) with the totals of report_json: `faces` counts the
// scene's faces, `lit_faces` those with some lit area. Then, per light, its `top` faces of
// lowest lit fraction, ties in scene order; zero-area faces are left out there (they have
// nothing to shadow), and `top` = 0 leaves these lists out. Areas have 6 significant
// digits, fractions 4 decimals (this is for reading; report_csv is for reading back).
// Control characters in ids are shown escaped (\n, \xHH) so rows stay on one line;
// widths count UTF-8 code points. With `groups`, a block after the lights' totals:
//
//   groups (each face counted once in each group it is in)
//   group_id  light_id  faces  area  lit_area  lit_fraction
//   garden    sun           3   572   467.083        0.8166
std::string report_table(const ShadowedScene& shadowed, std::size_t top = 10,
                         std::span<const groups::FaceGroup> groups = {});

}  // namespace shadowgen
