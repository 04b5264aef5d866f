#pragma once

// A date and time of day as a clock shows it (docs/scene-format.md, "Site and sun path":
// `YYYY-MM-DDTHH:MM`, seconds optional), on the proleptic Gregorian calendar, and the
// arithmetic a sun path needs: whole seconds on one clock, without leap seconds or
// daylight saving, so that stepping by minutes and naming each instant are exact.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace shadowgen::sun {

struct CivilTime {
  int year = 2000;  // 0 to 9999
  int month = 1;    // 1 to 12
  int day = 1;      // 1 to the month's length
  int hour = 0;     // 0 to 23
  int minute = 0;   // 0 to 59
  int second = 0;   // 0 to 59

  friend bool operator==(const CivilTime&, const CivilTime&) = default;
};

// Whether `year` is a leap year, and the days of `month` (1 to 12) in it.
bool is_leap(int year);
int days_in_month(int year, int month);

// `YYYY-MM-DDTHH:MM` or `YYYY-MM-DDTHH:MM:SS`, every field its digits exactly and within
// its range (February 29 only in a leap year); nullopt for anything else.
std::optional<CivilTime> parse_civil_time(std::string_view text);

// `YYYY-MM-DDTHH:MM`: the name of an instant (its seconds are left out).
std::string minute_text(const CivilTime& time);

// `YYYY-MM-DDTHH:MM`, with `:SS` when the seconds are not 0.
std::string civil_text(const CivilTime& time);

// Seconds from 1970-01-01T00:00:00 on the same clock (negative before it), and back.
std::int64_t seconds_since_1970(const CivilTime& time);
CivilTime civil_time_at(std::int64_t seconds_since_1970);

// The Julian day of the time, on the time scale the clock keeps (UT for a UT clock).
double julian_day(const CivilTime& time);

}  // namespace shadowgen::sun
