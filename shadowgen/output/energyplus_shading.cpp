#include "shadowgen/output/energyplus_shading.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>

#include "detail/energyplus_surface_names.h"
#include "detail/sun_paths_required.h"
#include "hsr/area.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/sun/civil_time.h"

namespace shadowgen {
namespace {

constexpr std::int64_t kSecondsPerDay = 86'400;

std::string header(const ShadowedScene& shadowed) {
  std::string out = "Surface Name,";
  for (const std::string& name : output::detail::energyplus_surface_names(shadowed.scene())) {
    out += name + ',';
  }
  return out + '\n';
}

std::int64_t seconds_of(const std::string& time_text, const std::string& file,
                        const std::string& what) {
  const std::optional<sun::CivilTime> time = sun::parse_civil_time(time_text);
  if (!time) throw InputError(file, "", what + " '" + time_text + "' is not a local time");
  return sun::seconds_since_1970(*time);
}

// " MM/DD HH:MM," for the step of day `day_start` ending `minutes` after its midnight.
void append_stamp(std::string& out, std::int64_t day_start, int minutes) {
  const sun::CivilTime day = sun::civil_time_at(day_start);
  char text[32];
  const int n = std::snprintf(text, sizeof text, " %02d/%02d %02d:%02d,", day.month, day.day,
                              minutes / 60, minutes % 60);
  out.append(text, static_cast<std::size_t>(n));
}

// A fraction in [0, 1] with 8 decimals, as EnergyPlus writes it ("{:10.8F}"), then ','.
void append_fraction(std::string& out, double fraction) {
  char text[32];
  const auto [end, error] =
      std::to_chars(text, text + sizeof text, fraction, std::chars_format::fixed, 8);
  out.append(text, end);
  out += ',';
}

}  // namespace

EnergyPlusShading energyplus_shading(const ShadowedScene& shadowed) {
  output::detail::require_sun_paths(shadowed, "a shading schedule");
  const std::string file = shadowed.scene().file;
  if (shadowed.sun_paths.size() > 1) {
    std::string ids;
    for (const SunPathHours& path : shadowed.sun_paths) ids += (ids.empty() ? "" : ", ") + path.id;
    throw InputError(file, "",
                     "has " + std::to_string(shadowed.sun_paths.size()) + " sun paths (" + ids +
                         "); a shading schedule is of one: choose it with --lights ID");
  }
  const SunPathHours& path = shadowed.sun_paths.front();
  const std::string named = "sun path '" + path.id + "'";
  if (path.step_min <= 0 || 60 % path.step_min != 0) {
    throw InputError(file, "",
                     named + " steps by " + std::to_string(path.step_min) +
                         " minutes; EnergyPlus's time steps divide an hour (1, 2, 3, 4, 5, 6, 10, "
                         "12, 15, 20, 30 or 60 minutes)");
  }
  const std::int64_t step_s = std::int64_t{path.step_min} * 60;
  const std::int64_t from = seconds_of(path.from, file, named + " from");
  const std::int64_t to = seconds_of(path.to, file, named + " to");
  const std::int64_t first_day = from - (from % kSecondsPerDay + kSecondsPerDay) % kSecondsPerDay;
  if ((from - first_day) % step_s != 0) {
    throw InputError(file, "",
                     named + " starts at " + path.from + ", not at the start of one of its " +
                         std::to_string(path.step_min) + "-minute time steps in the day");
  }
  const std::int64_t days = (to - first_day) / kSecondsPerDay + 1;
  const std::int64_t steps_per_day = kSecondsPerDay / step_s;

  // The instant starting each step, where the path has one (the sun is up).
  std::vector<std::optional<std::size_t>> instant_of_step(
      static_cast<std::size_t>(days * steps_per_day));
  for (std::size_t k = 0; k < path.instants.size(); ++k) {
    const Light& light = shadowed.scene().lights.at(path.instants[k]);
    const std::int64_t at = seconds_of(light.sun ? light.sun->time : "", file, light.id);
    if (at < from || at > to || (at - first_day) % step_s != 0) {
      throw InputError(file, "", "light '" + light.id + "' is not on a time step of " + named);
    }
    instant_of_step.at(static_cast<std::size_t>((at - first_day) / step_s)) = k;
  }

  EnergyPlusShading out;
  const std::size_t faces = shadowed.scene().faces.size();
  std::vector<double> areas(faces);
  for (std::size_t f = 0; f < faces; ++f) areas[f] = hsr::area(shadowed.scene().faces[f].parts);
  out.csv = header(shadowed);
  for (std::size_t s = 0; s < instant_of_step.size(); ++s) {
    const std::int64_t day = static_cast<std::int64_t>(s) / steps_per_day;
    const int end_minutes =
        static_cast<int>((static_cast<std::int64_t>(s) % steps_per_day + 1) * path.step_min);
    append_stamp(out.csv, first_day + day * kSecondsPerDay, end_minutes);
    for (std::size_t f = 0; f < faces; ++f) {
      double fraction = 0.0;
      if (instant_of_step[s] && areas[f] > 0.0) {
        fraction = std::clamp(path.lit_area[f][*instant_of_step[s]] / areas[f], 0.0, 1.0);
      }
      append_fraction(out.csv, fraction);
    }
    out.csv += '\n';
  }

  const sun::CivilTime start = sun::civil_time_at(first_day);
  const bool whole_year = from == first_day && start.month == 1 && start.day == 1 &&
                          days == (sun::is_leap(start.year) ? 366 : 365) &&
                          to >= first_day + days * kSecondsPerDay - step_s;
  if (!whole_year) {
    out.warnings.push_back(named + " covers " + std::to_string(days) + " days, from " + path.from +
                           " to " + path.to +
                           ": EnergyPlus reads Schedule:File:Shading only for a whole year "
                           "(January 1 to December 31 at every time step)");
  }
  return out;
}

}  // namespace shadowgen
