#include "shadowgen/output/sun_hours_report.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "detail/csv_fields.h"
#include "detail/sun_paths_required.h"
#include "hsr/area.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/output/group_sums.h"

namespace shadowgen {

std::vector<SunHoursRow> sun_hours_rows(const ShadowedScene& shadowed,
                                        std::span<const double> thresholds) {
  for (const double t : thresholds) {
    if (!std::isfinite(t) || t < 0.0) {
      throw std::invalid_argument("a sun-hours threshold must be a finite number of hours >= 0");
    }
  }
  output::detail::require_sun_paths(shadowed, "sun hours");
  for (const SunPathHours& path : shadowed.sun_paths) {
    require_regions(path, shadowed.scene().file, "a sun-hours report");
  }
  const Scene& scene = shadowed.scene();
  std::vector<SunHoursRow> rows;
  rows.reserve(scene.faces.size() * shadowed.sun_paths.size());
  for (std::size_t f = 0; f < scene.faces.size(); ++f) {
    for (std::size_t p = 0; p < shadowed.sun_paths.size(); ++p) {
      SunHoursRow row;
      row.face = f;
      row.path = p;
      row.area = hsr::area(scene.faces[f].parts);
      row.area_at_least.assign(thresholds.size(), 0.0);
      double hours_area = 0.0;
      bool any = false;
      for (const SunHoursRegion& region : shadowed.sun_paths[p].regions.at(f)) {
        const double a = lit_area(region.polygons);
        if (!(a > 0.0)) continue;
        hours_area += region.hours * a;
        row.min_hours = any ? std::min(row.min_hours, region.hours) : region.hours;
        row.max_hours = any ? std::max(row.max_hours, region.hours) : region.hours;
        any = true;
        for (std::size_t t = 0; t < thresholds.size(); ++t) {
          if (region.hours >= thresholds[t]) row.area_at_least[t] += a;
        }
      }
      // The regions' areas are the face's up to the clipper's rounding of crossings, so
      // the sums are too: a mean lies between the least and most hours, and no area
      // above the face's is reported.
      row.mean_hours =
          row.area > 0.0 ? std::clamp(hours_area / row.area, row.min_hours, row.max_hours) : 0.0;
      for (double& a : row.area_at_least) a = std::min(a, row.area);
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::string sun_hours_csv(const ShadowedScene& shadowed, std::span<const double> thresholds,
                          CsvIds ids, std::span<const groups::FaceGroup> groups) {
  const std::vector<SunHoursRow> rows = sun_hours_rows(shadowed, thresholds);
  std::string out = "face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours";
  for (const double t : thresholds) out += ",area_at_least_" + shortest(t) + "h";
  out += '\n';
  for (const SunHoursRow& row : rows) {
    output::detail::append_csv_field(out, shadowed.scene().faces[row.face].id, ids);
    out += ',';
    output::detail::append_csv_field(out, shadowed.sun_paths[row.path].id, ids);
    for (const double v : {row.area, row.mean_hours, row.min_hours, row.max_hours}) {
      out += ',';
      output::detail::append_csv_number(out, v);
    }
    for (const double a : row.area_at_least) {
      out += ',';
      output::detail::append_csv_number(out, a);
    }
    out += '\n';
  }
  if (groups.empty()) return out;
  out += "\ngroup_id,sun_path,faces,area,mean_sun_hours,min_sun_hours,max_sun_hours";
  for (const double t : thresholds) out += ",area_at_least_" + shortest(t) + "h";
  for (const double t : thresholds) out += ",share_at_least_" + shortest(t) + "h";
  out += '\n';
  for (const GroupSunHoursRow& row :
       group_sun_hours_rows(rows, shadowed.sun_paths.size(), groups)) {
    output::detail::append_csv_field(out, groups[row.group].id, ids);
    out += ',';
    output::detail::append_csv_field(out, shadowed.sun_paths[row.path].id, ids);
    out += ',' + std::to_string(row.faces);
    for (const double v : {row.area, row.mean_hours, row.min_hours, row.max_hours}) {
      out += ',';
      output::detail::append_csv_number(out, v);
    }
    for (const std::vector<double>* list : {&row.area_at_least, &row.share_at_least}) {
      for (const double v : *list) {
        out += ',';
        output::detail::append_csv_number(out, v);
      }
    }
    out += '\n';
  }
  return out;
}

}  // namespace shadowgen
