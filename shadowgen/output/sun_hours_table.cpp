#include "shadowgen/output/sun_hours_table.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "shadowgen/model/number_text.h"
#include "shadowgen/model/one_line.h"
#include "shadowgen/output/group_sums.h"
#include "shadowgen/output/sun_hours_report.h"
#include "shadowgen/sun/civil_time.h"

namespace shadowgen {
namespace {

constexpr const char* kMonths[] = {"January",   "February", "March",    "April",
                                   "May",       "June",     "July",     "August",
                                   "September", "October",  "November", "December"};

std::string day_text(const sun::CivilTime& time, bool with_year) {
  std::string out = std::to_string(time.day);
  out.append(" ").append(kMonths[time.month - 1]);
  if (with_year) out.append(" ").append(std::to_string(time.year));
  return out;
}

std::string clock_text(const sun::CivilTime& time) {
  const std::string minute = sun::minute_text(time);  // YYYY-MM-DDTHH:MM
  return minute.substr(minute.size() - 5);
}

// A percentage with one decimal, or as many more as a failing share needs not to read as
// 50.0 (a share within rounding of a half is shown as far as it differs).
std::string share_text(double share, bool passes) {
  double percent = 100.0 * share;
  if (!passes && percent >= 100.0 * kSunTestPassShare) {
    percent = std::nextafter(100.0 * kSunTestPassShare, 0.0);
  }
  for (int decimals = 1;; ++decimals) {
    const std::string text = number_text(percent, std::chars_format::fixed, decimals);
    if (passes || decimals >= 17 || parse_number(text).value_or(0.0) < 100.0 * kSunTestPassShare) {
      return text;
    }
  }
}

std::string area_text(double area) {
  if (area >= 100.0) return number_text(area, std::chars_format::fixed, 0);
  return number_text(area, std::chars_format::general, 3);
}

struct PathTimes {
  sun::CivilTime from, to;
};

PathTimes times_of(std::string_view from, std::string_view to) {
  const std::optional<sun::CivilTime> a = sun::parse_civil_time(from);
  const std::optional<sun::CivilTime> b = sun::parse_civil_time(to);
  // The database reader and the scene reader check both; a path made by hand is a caller's
  // mistake.
  if (!a || !b) throw std::invalid_argument("a sun path's from and to must be local times");
  return {*a, *b};
}

}  // namespace

std::string sun_test_line(std::string_view name, double area, double area_at_least,
                          double threshold, std::string_view when) {
  std::string out = one_line(name) + ": ";
  if (!(area > 0.0)) return out + "no area";
  const bool passes = area_at_least >= kSunTestPassShare * area;
  out += share_text(area_at_least / area, passes) + " % of " + area_text(area) + " m² gets ≥ " +
         shortest(threshold) + " h " + std::string(when) + ": " + (passes ? "passes" : "fails");
  return out;
}

std::string sun_path_days(std::string_view from, std::string_view to) {
  const PathTimes times = times_of(from, to);
  const sun::CivilTime& a = times.from;
  const sun::CivilTime& b = times.to;
  if (a.year == b.year && a.month == b.month && a.day == b.day) {
    return "on " + day_text(a, false);
  }
  const bool years = a.year != b.year;
  return "from " + day_text(a, years) + " to " + day_text(b, years);
}

std::string sun_hours_table(const ShadowedScene& shadowed, std::span<const double> thresholds,
                            std::span<const groups::FaceGroup> groups) {
  const std::vector<SunHoursRow> rows = sun_hours_rows(shadowed, thresholds);
  const std::size_t paths = shadowed.sun_paths.size();
  const std::vector<GroupSunHoursRow> group_rows = group_sun_hours_rows(rows, paths, groups);
  std::string out;
  for (std::size_t p = 0; p < paths; ++p) {
    const SunPathHours& path = shadowed.sun_paths[p];
    const PathTimes times = times_of(path.from, path.to);
    const bool one_day = times.from.year == times.to.year && times.from.month == times.to.month &&
                         times.from.day == times.to.day;
    if (p > 0) out += '\n';
    out += "sun path '" + one_line(path.id) + "': " + day_text(times.from, true) + " " +
           clock_text(times.from) + " to " + (one_day ? "" : day_text(times.to, true) + " ") +
           clock_text(times.to) + ", every " + std::to_string(path.step_min) + " min\n";
    out += "an area passes when at least " +
           number_text(100.0 * kSunTestPassShare, std::chars_format::general, 6) +
           " % of it gets at least the hours shown (BRE 209, 2022, section 3.3: 2 h on 21 "
           "March)\n";
    const std::string when = sun_path_days(path.from, path.to);
    for (std::size_t t = 0; t < thresholds.size(); ++t) {
      if (groups.empty()) {
        for (std::size_t f = 0; f < shadowed.scene().faces.size(); ++f) {
          const SunHoursRow& row = rows[f * paths + p];
          out += sun_test_line(shadowed.scene().faces[f].id, row.area, row.area_at_least[t],
                               thresholds[t], when) +
                 '\n';
        }
        continue;
      }
      for (std::size_t g = 0; g < groups.size(); ++g) {
        const GroupSunHoursRow& row = group_rows[g * paths + p];
        out +=
            sun_test_line(groups[g].id, row.area, row.area_at_least[t], thresholds[t], when) + '\n';
      }
    }
  }
  return out;
}

}  // namespace shadowgen
