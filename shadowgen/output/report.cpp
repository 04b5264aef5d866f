#include "shadowgen/output/report.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "detail/chunked_text.h"
#include "detail/compensated_sum.h"
#include "detail/csv_fields.h"
#include "detail/method_json.h"
#include "detail/origin_json.h"
#include "detail/text_table.h"
#include "hsr/area.h"
#include "hsr/parallel.h"
#include "shadowgen/json/json_writer.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/output/group_sums.h"

namespace shadowgen {
namespace {

using Layout = JsonWriter::Layout;
using output::detail::append_csv_field;
using output::detail::append_csv_number;

double fraction(double part, double whole) { return whole == 0.0 ? 0.0 : part / whole; }

using Sum = output::detail::CompensatedSum;

void write_totals(JsonWriter& out, double area, double lit_area) {
  out.key("area").value(area).key("lit_area").value(lit_area);
  out.key("lit_fraction").value(fraction(lit_area, area));
}

std::string readable_area(double value) {
  return number_text(value, std::chars_format::general, 6);
}

std::string readable_fraction(double value) {
  return number_text(value, std::chars_format::fixed, 4);
}

// Generation gives a part lit whole the part itself and no part more lit area than its
// own (shadows/detail/lit_parts.h), but a face of several parts sums its lit polygons in
// another order than its parts, which can round a hair over the face's area (lit fraction
// 1.0000000000000007), and a database written by an older generator or by hand may hold
// polygons rounded outwards. An excess within 2^-40 of the area (far above such rounding,
// far below any real error) is clamped, so a report never shows more lit than there is;
// a larger one is left visible.
double clamped_lit_area(double lit, double face_area) {
  constexpr double kRoundingExcess = 0x1p-40;
  if (lit > face_area && lit - face_area <= kRoundingExcess * face_area) return face_area;
  return lit;
}

// No output holds inf or nan (docs/scene-format.md): an area beyond a double's range comes
// from coordinates beyond the range the readers support, and is bad input.
void check_finite(const ReportRow& row, const Scene& scene) {
  const Face& face = scene.faces[row.face];
  if (!std::isfinite(row.area)) {
    throw InputError(scene.file, face.id,
                     "its area is not a finite number (coordinates too large)");
  }
  if (!std::isfinite(row.lit_area) || !std::isfinite(row.lit_fraction)) {
    throw InputError(scene.file, face.id,
                     "its lit area for light '" + scene.lights[row.light].id +
                         "' is not a finite number (coordinates too large)");
  }
}

// The totals of report_json and report_table: per light, and for the scene.
struct Totals {
  std::vector<double> light_area;
  std::vector<double> light_lit_area;
  std::vector<std::size_t> lit_faces;  // per light, the faces with some lit area
  double area = 0.0;
  double lit_area = 0.0;
};

Totals totals_of(const Scene& scene, const std::vector<ReportRow>& rows) {
  const std::size_t lights = scene.lights.size();
  std::vector<Sum> light_area(lights);
  std::vector<Sum> light_lit_area(lights);
  Sum area;
  Sum lit_area;
  Totals totals;
  totals.lit_faces.assign(lights, 0);
  for (const ReportRow& row : rows) {
    light_area[row.light].add(row.area);
    light_lit_area[row.light].add(row.lit_area);
    area.add(row.area);
    lit_area.add(row.lit_area);
    if (row.lit_area > 0.0) ++totals.lit_faces[row.light];
  }
  for (std::size_t l = 0; l < lights; ++l) {
    totals.light_area.push_back(light_area[l].value());
    totals.light_lit_area.push_back(light_lit_area[l].value());
  }
  totals.area = area.value();
  totals.lit_area = lit_area.value();
  if (!std::isfinite(totals.area) || !std::isfinite(totals.lit_area)) {
    throw InputError(scene.file, "",
                     "the faces' total area is not a finite number (coordinates too large)");
  }
  return totals;
}

}  // namespace

std::vector<ReportRow> report_rows(const ShadowedScene& shadowed) {
  const Scene& scene = shadowed.scene();
  const LitAreas lit_areas(shadowed);
  const std::size_t lights = scene.lights.size();
  std::vector<ReportRow> rows(scene.faces.size() * lights);
  // Faces in parallel, each writing its own rows; the first face in scene order that
  // fails is the one named.
  hsr::for_each_in_parallel(scene.faces.size(), [&](std::size_t f) {
    const double face_area = area(scene.faces[f].parts);
    for (std::size_t l = 0; l < lights; ++l) {
      ReportRow& row = rows[f * lights + l];
      row.face = f;
      row.light = l;
      row.area = face_area;
      row.lit_area = clamped_lit_area(lit_areas(f, l), face_area);
      row.lit_fraction = fraction(row.lit_area, face_area);
      check_finite(row, scene);
    }
  });
  return rows;
}

std::string report_csv(const ShadowedScene& shadowed, CsvIds ids,
                       std::span<const groups::FaceGroup> groups) {
  const std::vector<ReportRow> rows = report_rows(shadowed);
  std::string out = "face_id,light_id,area,lit_area,lit_fraction\n";
  output::detail::append_in_chunks(out, rows.size(), [&](std::string& text, std::size_t i) {
    const ReportRow& row = rows[i];
    append_csv_field(text, shadowed.scene().faces[row.face].id, ids);
    text += ',';
    append_csv_field(text, shadowed.scene().lights[row.light].id, ids);
    text += ',';
    append_csv_number(text, row.area);
    text += ',';
    append_csv_number(text, row.lit_area);
    text += ',';
    append_csv_number(text, row.lit_fraction);
    text += '\n';
  });
  if (groups.empty()) return out;
  out += "\ngroup_id,light_id,faces,area,lit_area,lit_fraction\n";
  for (const GroupLitRow& row : group_lit_rows(rows, shadowed.scene().lights.size(), groups)) {
    append_csv_field(out, groups[row.group].id, ids);
    out += ',';
    append_csv_field(out, shadowed.scene().lights[row.light].id, ids);
    out += ',' + std::to_string(row.faces);
    for (const double v : {row.area, row.lit_area, row.lit_fraction}) {
      out += ',';
      append_csv_number(out, v);
    }
    out += '\n';
  }
  return out;
}

std::string report_json(const ShadowedScene& shadowed, std::span<const groups::FaceGroup> groups) {
  const std::vector<ReportRow> rows = report_rows(shadowed);
  const Scene& scene = shadowed.scene();
  const Totals totals = totals_of(scene, rows);

  JsonWriter out;
  out.begin_object(Layout::kLines).key("format").value("shadowgen-report/1");
  output::detail::write_method(out, shadowed.method());
  out.key("rows").begin_array(Layout::kLines);
  for (const ReportRow& row : rows) {
    out.begin_object();
    out.key("face_id").value(scene.faces[row.face].id);
    output::detail::write_origin(out, scene.faces[row.face].origin);
    out.key("light_id").value(scene.lights[row.light].id);
    out.key("area").value(row.area).key("lit_area").value(row.lit_area);
    out.key("lit_fraction").value(row.lit_fraction);
    out.end_object();
  }
  out.end_array();
  out.key("lights").begin_array(Layout::kLines);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    out.begin_object().key("light_id").value(scene.lights[l].id);
    write_totals(out, totals.light_area[l], totals.light_lit_area[l]);
    out.end_object();
  }
  out.end_array();
  out.key("totals").begin_object();
  write_totals(out, totals.area, totals.lit_area);
  out.end_object();
  if (!groups.empty()) {
    out.key("groups").begin_array(Layout::kLines);
    for (const GroupLitRow& row : group_lit_rows(rows, scene.lights.size(), groups)) {
      out.begin_object().key("group_id").value(groups[row.group].id);
      out.key("light_id").value(scene.lights[row.light].id);
      out.key("faces").value(std::uint64_t{row.faces});
      write_totals(out, row.area, row.lit_area);
      out.end_object();
    }
    out.end_array();
  }
  out.end_object();
  return out.take();
}

std::string report_table(const ShadowedScene& shadowed, std::size_t top,
                         std::span<const groups::FaceGroup> groups) {
  const std::vector<ReportRow> rows = report_rows(shadowed);
  const Scene& scene = shadowed.scene();
  const std::size_t lights = scene.lights.size();
  const Totals sums = totals_of(scene, rows);

  std::string out;
  if (const std::optional<Estimate>& estimate = shadowed.estimate()) {  // never taken as exact
    const Method& method = estimate->method;
    out += "lit areas estimated by the " + std::string(method_name(method.kind)) + " method, " +
           std::to_string(method.samples) + " samples per face";
    if (method.kind == MethodKind::kShadowMap) {
      out += ", depth maps of " + std::to_string(method.resolution) + " texels a side";
    }
    out += "\n";
  }
  output::detail::TextTable totals({false, true, true, true, true, true});
  totals.add({"light_id", "faces", "lit_faces", "area", "lit_area", "lit_fraction"});
  for (std::size_t l = 0; l < lights; ++l) {
    const double area_value = sums.light_area[l];
    const double lit_value = sums.light_lit_area[l];
    totals.add({one_line(scene.lights[l].id), std::to_string(scene.faces.size()),
                std::to_string(sums.lit_faces[l]), readable_area(area_value),
                readable_area(lit_value), readable_fraction(fraction(lit_value, area_value))});
  }
  totals.append_to(out);
  if (lights == 0) out += "(no lights)\n";
  if (!groups.empty()) {
    out += "\ngroups (each face counted once in each group it is in)\n";
    output::detail::TextTable table({false, false, true, true, true, true});
    table.add({"group_id", "light_id", "faces", "area", "lit_area", "lit_fraction"});
    for (const GroupLitRow& row : group_lit_rows(rows, lights, groups)) {
      table.add({one_line(groups[row.group].id), one_line(scene.lights[row.light].id),
                 std::to_string(row.faces), readable_area(row.area), readable_area(row.lit_area),
                 readable_fraction(row.lit_fraction)});
    }
    table.append_to(out);
  }
  if (top == 0) return out;

  for (std::size_t l = 0; l < lights; ++l) {
    // report_rows holds one row per (face, light), face by face: light l's are every
    // lights-th. Only the `top` most shadowed are ordered (ties in scene order), so a sun
    // path of thousands of instants costs lights × faces, not lights² × faces.
    std::vector<const ReportRow*> shadowed_rows;
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      const ReportRow& row = rows[f * lights + l];
      if (row.area > 0.0) shadowed_rows.push_back(&row);
    }
    const std::size_t shown = std::min(top, shadowed_rows.size());
    std::partial_sort(shadowed_rows.begin(),
                      shadowed_rows.begin() + static_cast<std::ptrdiff_t>(shown),
                      shadowed_rows.end(), [](const ReportRow* a, const ReportRow* b) {
                        return a->lit_fraction < b->lit_fraction ||
                               (a->lit_fraction == b->lit_fraction && a->face < b->face);
                      });
    out += "\nmost shadowed faces under " + one_line(scene.lights[l].id) +
           " (lowest lit fraction first, " + std::to_string(shown) + " of " +
           std::to_string(shadowed_rows.size()) + ")\n";
    output::detail::TextTable faces({false, true, true, true});
    faces.add({"face_id", "area", "lit_area", "lit_fraction"});
    for (std::size_t i = 0; i < shown; ++i) {
      const ReportRow& row = *shadowed_rows[i];
      faces.add({one_line(scene.faces[row.face].id), readable_area(row.area),
                 readable_area(row.lit_area), readable_fraction(row.lit_fraction)});
    }
    faces.append_to(out);
  }
  return out;
}

}  // namespace shadowgen
