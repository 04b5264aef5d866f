#include "shadowgen/weather/epw_reader.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <new>
#include <optional>
#include <utility>
#include <vector>

#include "detail/hour_text.h"
#include "shadowgen/json/document.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/model/line_reader.h"
#include "shadowgen/model/number_text.h"
#include "shadowgen/model/site_ranges.h"
#include "shadowgen/sun/civil_time.h"

namespace shadowgen::weather {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// The first field of each header line. EnergyPlus writes HOLIDAYS/DAYLIGHT SAVINGS in its
// files and HOLIDAYS/DAYLIGHT SAVING in its data dictionary; both are accepted.
constexpr std::size_t kHeaderLines = 8;
constexpr std::array<std::string_view, kHeaderLines> kHeaders = {"LOCATION",
                                                                 "DESIGN CONDITIONS",
                                                                 "TYPICAL/EXTREME PERIODS",
                                                                 "GROUND TEMPERATURES",
                                                                 "HOLIDAYS/DAYLIGHT SAVINGS",
                                                                 "COMMENTS 1",
                                                                 "COMMENTS 2",
                                                                 "DATA PERIODS"};
constexpr std::string_view kHolidaysAsDocumented = "HOLIDAYS/DAYLIGHT SAVING";
constexpr std::string_view kHeaderNote =
    "an EPW weather file begins with 8 header lines (LOCATION to DATA PERIODS)";

constexpr std::size_t kLocationFields = 10;  // LOCATION, city, ..., elevation
// The LOCATION's time zone and elevation as EnergyPlus states them (Site:Location; the
// data dictionary), both within a scene site's ranges (shadowgen/model/site_ranges.h).
const NumberRange kLocationTimeZone{.low = -12.0, .high = 14.0, .unit = " hours"};
const NumberRange kLocationElevation{.low = -1000.0, .high = 9999.9, .unit = " m"};

// An hourly row's fields, counted from 0 (the data dictionary counts from 1).
constexpr std::size_t kRowFields = 35;
constexpr std::size_t kYear = 0;
constexpr std::size_t kMonth = 1;
constexpr std::size_t kDay = 2;
constexpr std::size_t kHour = 3;
constexpr std::size_t kMinute = 4;
constexpr std::size_t kGlobalHorizontal = 13;
constexpr std::size_t kDirectNormal = 14;
constexpr std::size_t kDiffuseHorizontal = 15;
constexpr std::size_t kAlbedo = 32;

// The data dictionary's "missing" for radiation: 9999 or more; for the albedo, 999.
constexpr double kMissingRadiation = 9999.0;
constexpr double kMissingAlbedo = 999.0;
// Rows carry no year that counts, and February 29 may be among them: days are checked
// against a leap year.
constexpr int kAnyLeapYear = 2000;

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  return text;
}

// Comma-separated fields without the spaces around them. EPW has no quoting.
std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> fields;
  for (;;) {
    const std::size_t comma = line.find(',');
    fields.push_back(trimmed(line.substr(0, comma)));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

// Whether `next` is the hour after `before`.
bool follows(const WeatherHour& before, const WeatherHour& next) {
  if (before.hour < 24) {
    return next.month == before.month && next.day == before.day && next.hour == before.hour + 1;
  }
  if (next.hour != 1) return false;
  const bool month_ends = before.day == sun::days_in_month(kAnyLeapYear, before.month);
  const int month = month_ends ? before.month % 12 + 1 : before.month;
  const int day = month_ends ? 1 : before.day + 1;
  const bool no_leap_day =
      before.month == 2 && before.day == 28 && next.month == 3 && next.day == 1;
  return (next.month == month && next.day == day) || no_leap_day;
}

class EpwParser {
 public:
  EpwParser(std::string_view text, const std::string& file)
      : lines_(text), file_(file), first_line_(12 * 31 * 24, 0) {}

  Weather run() {
    weather_.file = file_;
    read_header();
    read_rows();
    return std::move(weather_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, "", what); }
  [[noreturn]] void fail_at(std::size_t line, const std::string& what) const {
    fail("line " + std::to_string(line) + ": " + what);
  }

  void read_header() {
    for (std::size_t i = 0; i < kHeaderLines; ++i) {
      std::string_view line;
      if (!lines_.next(line)) {
        if (i == 0) fail("empty file; " + std::string(kHeaderNote));
        fail("the file ends after " + std::to_string(i) + (i == 1 ? " line; " : " lines; ") +
             std::string(kHeaderNote));
      }
      const std::vector<std::string_view> fields = fields_of(line);
      if (fields[0] != kHeaders[i] && !(i == 4 && fields[0] == kHolidaysAsDocumented)) {
        fail_at(lines_.number(), "expected the " + std::string(kHeaders[i]) +
                                     " header line, found '" + std::string(fields[0]) + "'");
      }
      if (i == 0) read_location(fields);
      if (i + 1 == kHeaderLines) read_data_periods(fields);
    }
  }

  void read_location(const std::vector<std::string_view>& fields) {
    if (fields.size() < kLocationFields) {
      fail_at(1, "the LOCATION line has " + std::to_string(fields.size()) +
                     " fields; it needs 10 (LOCATION, city, state or province, country, "
                     "source, WMO, latitude, longitude, time zone, elevation)");
    }
    weather_.city = fields[1];
    weather_.state_province = fields[2];
    weather_.country = fields[3];
    weather_.source = fields[4];
    weather_.wmo = fields[5];
    Site& site = weather_.site;
    site.latitude_deg = number_within(fields[6], "latitude", latitude_range(), 1);
    site.longitude_deg = number_within(fields[7], "longitude", longitude_range(), 1);
    site.utc_offset_h = number_within(fields[8], "time zone", kLocationTimeZone, 1);
    site.elevation_m = number_within(fields[9], "elevation", kLocationElevation, 1);
  }

  // Only hourly files: with several records an hour, rows would need the minute field to
  // tell them apart, and their timing is another matter.
  void read_data_periods(const std::vector<std::string_view>& fields) {
    const std::size_t line = kHeaderLines;
    if (fields.size() < 3) {
      fail_at(line, "the DATA PERIODS line has " + std::to_string(fields.size()) +
                        " fields; it needs at least 3 (DATA PERIODS, number of data periods, "
                        "records per hour)");
    }
    const std::int64_t records = whole(fields[2], "records per hour", line);
    if (records != 1) {
      fail_at(line, std::to_string(records) +
                        " records per hour; only hourly weather files (1 record per hour) are "
                        "read");
    }
  }

  void read_rows() {
    std::string_view line;
    std::size_t empty_line = 0;  // the first empty line among the rows, 0 if none yet
    while (lines_.next(line)) {
      if (trimmed(line).empty()) {
        if (empty_line == 0) empty_line = lines_.number();
        continue;
      }
      if (empty_line != 0) fail_at(empty_line, "an empty line among the hourly rows");
      read_row(line);
    }
    if (weather_.hours.empty()) fail("no hourly rows after the 8 header lines");
  }

  void read_row(std::string_view text) {
    const std::size_t line = lines_.number();
    const std::vector<std::string_view> fields = fields_of(text);
    if (fields.size() != kRowFields) {
      fail_at(line, std::to_string(fields.size()) + " fields; an hourly row has 35");
    }
    (void)whole(fields[kYear], "year", line);
    WeatherHour hour;
    hour.line = line;
    hour.month = whole_within(fields[kMonth], "month", 1, 12, line);
    hour.day = whole_within(fields[kDay], "day", 1, 31, line);
    if (hour.day > sun::days_in_month(kAnyLeapYear, hour.month)) {
      fail_at(line,
              "month " + std::to_string(hour.month) + " has no day " + std::to_string(hour.day));
    }
    hour.hour = whole_within(fields[kHour], "hour", 1, 24, line);
    hour.minute = whole_within(fields[kMinute], "minute", 0, 60, line);
    hour.global_horizontal_wh_m2 =
        radiation(fields[kGlobalHorizontal], "global horizontal radiation (field 14)", line);
    hour.direct_normal_wh_m2 =
        radiation(fields[kDirectNormal], "direct normal radiation (field 15)", line);
    hour.diffuse_horizontal_wh_m2 =
        radiation(fields[kDiffuseHorizontal], "diffuse horizontal radiation (field 16)", line);
    hour.albedo = albedo(fields[kAlbedo], line);
    check_order(hour);
    weather_.hours.push_back(hour);
  }

  // Each row the hour after the one before, and no hour twice.
  void check_order(const WeatherHour& hour) {
    std::size_t& first = first_line_[((hour.month - 1) * 31 + hour.day - 1) * 24 + hour.hour - 1];
    if (first != 0) {
      fail_at(hour.line, detail::hour_text(hour) + " again (first on line " +
                             std::to_string(first) +
                             "); a weather file holds a year at most, and its years are not "
                             "read");
    }
    first = hour.line;
    if (weather_.hours.empty()) return;
    const WeatherHour& before = weather_.hours.back();
    if (!follows(before, hour)) {
      fail_at(hour.line, "expected the hour after " + detail::hour_text(before) + " (line " +
                             std::to_string(before.line) + "), found " + detail::hour_text(hour) +
                             "; the rows must run hour by hour");
    }
  }

  // A radiation field: nullopt where marked missing (9999 or more) or negative.
  std::optional<double> radiation(std::string_view field, const std::string& what,
                                  std::size_t line) const {
    const double value = number(field, what, line);
    if (value >= 0.0 && value < kMissingRadiation) return value;
    return std::nullopt;
  }

  // The albedo (field 33): 0 to 1, or 999 or more for missing.
  std::optional<double> albedo(std::string_view field, std::size_t line) const {
    const std::string what = "albedo (field 33)";
    const double value = number(field, what, line);
    if (value >= kMissingAlbedo) return std::nullopt;
    if (value < 0.0 || value > 1.0) {
      fail_at(line, what + " " + shortest(value) + " must lie between 0 and 1 (999: missing)");
    }
    return value;
  }

  double number(std::string_view field, const std::string& what, std::size_t line) const {
    const std::optional<double> value = parse_number(field);
    if (!value || !std::isfinite(*value)) fail_at(line, not_a(field, what, "number"));
    return *value;
  }

  std::int64_t whole(std::string_view field, const std::string& what, std::size_t line) const {
    const std::optional<std::int64_t> value = parse_integer(field);
    if (!value) fail_at(line, not_a(field, what, "whole number"));
    return *value;
  }

  double number_within(std::string_view field, const std::string& what, const NumberRange& range,
                       std::size_t line) const {
    const double value = number(field, what, line);
    if (!within(value, range))
      fail_at(line, what + " " + shortest(value) + " " + range_rule(range));
    return value;
  }

  int whole_within(std::string_view field, const std::string& what, int low, int high,
                   std::size_t line) const {
    const std::int64_t value = whole(field, what, line);
    if (value < low || value > high) {
      fail_at(line, what + " " + std::to_string(value) + " must lie between " +
                        std::to_string(low) + " and " + std::to_string(high));
    }
    return static_cast<int>(value);
  }

  static std::string not_a(std::string_view field, const std::string& what,
                           const std::string& kind) {
    if (field.empty()) return what + " is empty; it must be a " + kind;
    return what + " '" + std::string(field) + "' is not a " + kind;
  }

  LineReader lines_;
  const std::string file_;
  Weather weather_;
  std::vector<std::size_t> first_line_;  // by month, day and hour; 0 while not seen
};

}  // namespace

Weather read_epw(const std::filesystem::path& path) {
  try {
    return parse_epw(read_text_file(path, "weather file", kLargestEpwFile), path.string());
  } catch (const std::bad_alloc&) {
    // Said here, where the file is known: the command line would name its own input.
    throw InputError(path.string(), "", std::string(kOutOfMemoryProblem));
  }
}

Weather parse_epw(std::string_view text, const std::string& file) {
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  return EpwParser(text, file).run();
}

}  // namespace shadowgen::weather
