#include "shadowgen/output/group_sums.h"

#include <algorithm>

#include "detail/compensated_sum.h"

namespace shadowgen {
namespace {

using output::detail::CompensatedSum;

double fraction(double part, double whole) { return whole == 0.0 ? 0.0 : part / whole; }

}  // namespace

std::vector<GroupLitRow> group_lit_rows(std::span<const ReportRow> rows, std::size_t lights,
                                        std::span<const groups::FaceGroup> groups) {
  std::vector<GroupLitRow> out;
  out.reserve(groups.size() * lights);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t l = 0; l < lights; ++l) {
      CompensatedSum area, lit_area;
      for (const std::size_t f : groups[g].faces) {
        const ReportRow& row = rows[f * lights + l];
        area.add(row.area);
        lit_area.add(row.lit_area);
      }
      GroupLitRow row{g, l, groups[g].faces.size(), area.value(), lit_area.value(), 0.0};
      // Each lit area is at most its face's (report_rows), so the sums keep that order.
      row.lit_area = std::min(row.lit_area, row.area);
      row.lit_fraction = fraction(row.lit_area, row.area);
      out.push_back(row);
    }
  }
  return out;
}

std::vector<GroupSunHoursRow> group_sun_hours_rows(std::span<const SunHoursRow> rows,
                                                   std::size_t paths,
                                                   std::span<const groups::FaceGroup> groups) {
  std::vector<GroupSunHoursRow> out;
  out.reserve(groups.size() * paths);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (std::size_t p = 0; p < paths; ++p) {
      GroupSunHoursRow row;
      row.group = g;
      row.path = p;
      row.faces = groups[g].faces.size();
      const std::size_t thresholds = rows.empty() ? 0 : rows.front().area_at_least.size();
      CompensatedSum area, hours_area;
      std::vector<CompensatedSum> at_least(thresholds);
      bool any = false;
      for (const std::size_t f : groups[g].faces) {
        const SunHoursRow& face = rows[f * paths + p];
        area.add(face.area);
        hours_area.add(face.mean_hours * face.area);
        for (std::size_t t = 0; t < thresholds; ++t) at_least[t].add(face.area_at_least[t]);
        if (!(face.area > 0.0)) continue;
        row.min_hours = any ? std::min(row.min_hours, face.min_hours) : face.min_hours;
        row.max_hours = any ? std::max(row.max_hours, face.max_hours) : face.max_hours;
        any = true;
      }
      row.area = area.value();
      // As for a face (sun_hours_rows): a mean between the least and most, no area above
      // the whole.
      row.mean_hours = row.area > 0.0
                           ? std::clamp(hours_area.value() / row.area, row.min_hours, row.max_hours)
                           : 0.0;
      for (const CompensatedSum& sum : at_least) {
        const double a = std::min(sum.value(), row.area);
        row.area_at_least.push_back(a);
        row.share_at_least.push_back(fraction(a, row.area));
      }
      out.push_back(std::move(row));
    }
  }
  return out;
}

}  // namespace shadowgen
