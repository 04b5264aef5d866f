// Tests of the direct normal radiation at an instant (shadowgen/weather/irradiance.h): which
// hour of a weather file an instant reads, at the hours' boundaries and across the turn of
// the year, and the errors for an hour the file lacks or marks missing.

#include "shadowgen/weather/irradiance.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/weather/epw_reader.h"
#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen::weather {
namespace {

using sun::CivilTime;
using test::test_direct_normal;

constexpr const char* kFile = "test.epw";

// January 1 to 3.
const Weather& january() {
  static const Weather weather = parse_epw(test::joined(test::epw_lines(1, 1, 3)), kFile);
  return weather;
}

CivilTime at(int year, int month, int day, int hour, int minute, int second = 0) {
  return {year, month, day, hour, minute, second};
}

// Hour h holds (h - 1):00 to h:00; an instant at h:00 reads the hour that starts there.
TEST(DirectNormal, AnInstantReadsTheHourThatStartsAtOrBeforeIt) {
  const Weather& w = january();
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 0, 0)), test_direct_normal(2, 1));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 0, 59, 59)), test_direct_normal(2, 1));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 1, 0)), test_direct_normal(2, 2));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 12, 30)), test_direct_normal(2, 13));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 23, 0)), test_direct_normal(2, 24));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 23, 59, 59)), test_direct_normal(2, 24));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 3, 0, 0)), test_direct_normal(3, 1));
  const WeatherHour* hour = weather_hour_at(w, at(2026, 1, 2, 12, 30));
  ASSERT_NE(hour, nullptr);
  EXPECT_EQ(hour->day, 2);
  EXPECT_EQ(hour->hour, 13);
  EXPECT_EQ(hour->line, 8u + 24 + 13);
}

// Every hour of the file is found from an instant within it, and from none outside it.
TEST(DirectNormal, EveryHourIsFoundFromItsInstants) {
  const Weather& w = january();
  for (const WeatherHour& hour : w.hours) {
    for (const int minute : {0, 1, 30, 59}) {
      EXPECT_EQ(weather_hour_at(w, at(2026, hour.month, hour.day, hour.hour - 1, minute)), &hour);
    }
  }
  EXPECT_EQ(weather_hour_at(w, at(2026, 1, 4, 0, 0)), nullptr);
  EXPECT_EQ(weather_hour_at(w, at(2025, 12, 31, 23, 59)), nullptr);
}

TEST(DirectNormal, TheYearIsNotMatched) {
  const Weather& w = january();
  EXPECT_EQ(direct_normal_wh_m2(w, at(1999, 1, 1, 10, 0)), test_direct_normal(1, 11));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2031, 1, 1, 10, 0)), test_direct_normal(1, 11));
}

// A run of hours from December 31 to January 2: in order, but for the turn of the year.
TEST(DirectNormal, FindsHoursOnBothSidesOfTheTurnOfTheYear) {
  std::vector<std::string> lines = test::epw_lines(12, 31, 1);
  for (int day = 1; day <= 2; ++day) {
    for (int hour = 1; hour <= 24; ++hour) {
      lines.push_back(test::epw_row(1, day, hour, std::to_string(day * 1000 + hour)));
    }
  }
  const Weather w = parse_epw(test::joined(lines), kFile);
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 12, 31, 0, 0)), test_direct_normal(31, 1));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 12, 31, 23, 30)), test_direct_normal(31, 24));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 1, 0, 0)), 1001.0);
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 2, 23, 59)), 2024.0);
  EXPECT_EQ(weather_hour_at(w, at(2026, 1, 3, 0, 0)), nullptr);
  EXPECT_EQ(weather_hour_at(w, at(2026, 12, 30, 23, 0)), nullptr);
}

std::string error_of(const Weather& weather, const CivilTime& time) {
  try {
    (void)direct_normal_wh_m2(weather, time);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DirectNormal, AnHourTheFileLacksIsAnError) {
  EXPECT_EQ(error_of(january(), at(2024, 2, 29, 12, 30)),
            "test.epw: no month 2 day 29 hour 13 for 2024-02-29T12:30 (local standard time; the "
            "year is not matched)");
}

TEST(DirectNormal, AMissingValueIsAnErrorOnlyWhereAnInstantNeedsIt) {
  std::vector<std::string> lines = test::epw_lines(1, 1, 1);
  lines[8 + 12] = test::epw_row(1, 1, 13, "9999");  // hour 13, on line 21
  const Weather w = parse_epw(test::joined(lines), kFile);
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 1, 11, 59)), test_direct_normal(1, 12));
  EXPECT_EQ(direct_normal_wh_m2(w, at(2026, 1, 1, 13, 0)), test_direct_normal(1, 14));
  EXPECT_EQ(error_of(w, at(2026, 1, 1, 12, 0, 30)),
            "test.epw: line 21: the direct normal radiation of month 1 day 1 hour 13 is marked "
            "missing (9999 or more, or negative), and 2026-01-01T12:00:30 needs it");
}

}  // namespace
}  // namespace shadowgen::weather
