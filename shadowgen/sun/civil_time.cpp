#include "shadowgen/sun/civil_time.h"

#include <cstdio>

namespace shadowgen::sun {
namespace {

constexpr std::int64_t kSecondsPerDay = 86400;
// The Julian day of 1970-01-01T00:00.
constexpr double kJulianDay1970 = 2440587.5;

// Days from 1970-01-01 to a date, and back, in 400-year eras of 146097 days with the
// year starting in March, so that February's leap day comes last (H. Hinnant,
// "chrono-Compatible Low-Level Date Algorithms").
std::int64_t days_from_civil(std::int64_t y, int m, int d) {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t year_of_era = y - era * 400;
  const std::int64_t day_of_year = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const std::int64_t day_of_era =
      year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

void civil_from_days(std::int64_t days, CivilTime& out) {
  days += 719468;
  const std::int64_t era = (days >= 0 ? days : days - 146096) / 146097;
  const std::int64_t day_of_era = days - era * 146097;
  const std::int64_t year_of_era =
      (day_of_era - day_of_era / 1460 + day_of_era / 36524 - day_of_era / 146096) / 365;
  const std::int64_t day_of_year =
      day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
  const std::int64_t month_from_march = (5 * day_of_year + 2) / 153;
  out.day = static_cast<int>(day_of_year - (153 * month_from_march + 2) / 5 + 1);
  out.month = static_cast<int>(month_from_march < 10 ? month_from_march + 3 : month_from_march - 9);
  out.year = static_cast<int>(year_of_era + era * 400 + (out.month <= 2 ? 1 : 0));
}

// `count` digits at `text[at]`, as a number; -1 when any is not a digit.
int digits(std::string_view text, std::size_t at, std::size_t count) {
  int value = 0;
  for (std::size_t i = at; i < at + count; ++i) {
    if (text[i] < '0' || text[i] > '9') return -1;
    value = value * 10 + (text[i] - '0');
  }
  return value;
}

}  // namespace

bool is_leap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int year, int month) {
  constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month == 2 && is_leap(year) ? 29 : kDays[month - 1];
}

std::optional<CivilTime> parse_civil_time(std::string_view text) {
  // YYYY-MM-DDTHH:MM, then optionally :SS.
  if (text.size() != 16 && text.size() != 19) return std::nullopt;
  if (text[4] != '-' || text[7] != '-' || text[10] != 'T' || text[13] != ':') return std::nullopt;
  if (text.size() == 19 && text[16] != ':') return std::nullopt;
  CivilTime t;
  t.year = digits(text, 0, 4);
  t.month = digits(text, 5, 2);
  t.day = digits(text, 8, 2);
  t.hour = digits(text, 11, 2);
  t.minute = digits(text, 14, 2);
  t.second = text.size() == 19 ? digits(text, 17, 2) : 0;
  if (t.year < 0 || t.month < 1 || t.month > 12 || t.hour < 0 || t.hour > 23 || t.minute < 0 ||
      t.minute > 59 || t.second < 0 || t.second > 59) {
    return std::nullopt;
  }
  if (t.day < 1 || t.day > days_in_month(t.year, t.month)) return std::nullopt;
  return t;
}

std::string minute_text(const CivilTime& time) {
  char text[32];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d", time.year, time.month, time.day,
                time.hour, time.minute);
  return text;
}

std::string civil_text(const CivilTime& time) {
  std::string text = minute_text(time);
  if (time.second != 0) {
    text += ':';
    text += static_cast<char>('0' + time.second / 10);
    text += static_cast<char>('0' + time.second % 10);
  }
  return text;
}

std::int64_t seconds_since_1970(const CivilTime& time) {
  return days_from_civil(time.year, time.month, time.day) * kSecondsPerDay +
         (time.hour * 60 + time.minute) * 60 + time.second;
}

CivilTime civil_time_at(std::int64_t seconds_since_1970) {
  std::int64_t days = seconds_since_1970 / kSecondsPerDay;
  std::int64_t rest = seconds_since_1970 % kSecondsPerDay;
  if (rest < 0) {
    rest += kSecondsPerDay;
    --days;
  }
  CivilTime t;
  civil_from_days(days, t);
  t.hour = static_cast<int>(rest / 3600);
  t.minute = static_cast<int>(rest / 60 % 60);
  t.second = static_cast<int>(rest % 60);
  return t;
}

double julian_day(const CivilTime& time) {
  // Whole days and the fraction apart, so the seconds are not lost to the large day count.
  const std::int64_t seconds = seconds_since_1970(time);
  const std::int64_t days = seconds / kSecondsPerDay;
  const std::int64_t rest = seconds % kSecondsPerDay;
  return (kJulianDay1970 + static_cast<double>(days)) +
         static_cast<double>(rest) / static_cast<double>(kSecondsPerDay);
}

}  // namespace shadowgen::sun
