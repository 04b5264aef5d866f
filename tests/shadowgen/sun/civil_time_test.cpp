// Tests of shadowgen/sun/civil_time.h: the scene format's `YYYY-MM-DDTHH:MM[:SS]`, the
// calendar, and Julian days.

#include "shadowgen/sun/civil_time.h"

#include <gtest/gtest.h>

#include <string>

namespace shadowgen::sun {
namespace {

TEST(CivilTime, ParsesMinutesAndOptionalSeconds) {
  EXPECT_EQ(parse_civil_time("2026-03-21T12:00"), (CivilTime{2026, 3, 21, 12, 0, 0}));
  EXPECT_EQ(parse_civil_time("2003-10-17T12:30:30"), (CivilTime{2003, 10, 17, 12, 30, 30}));
  EXPECT_EQ(parse_civil_time("2024-02-29T23:59:59"), (CivilTime{2024, 2, 29, 23, 59, 59}));
}

TEST(CivilTime, RefusesAnythingElse) {
  for (const char* bad :
       {"", "2026-03-21", "2026-03-21 12:00", "2026-3-21T12:00", "2026-03-21T12:00Z",
        "2026-03-21T12:00:00.5", "2026-13-01T00:00", "2026-00-01T00:00", "2026-04-31T00:00",
        "2025-02-29T00:00", "1900-02-29T00:00", "2026-03-21T24:00", "2026-03-21T12:60",
        "2026-03-21T12:00:60", "+026-03-21T12:00", "2026-03-21T1a:00"}) {
    EXPECT_FALSE(parse_civil_time(bad).has_value()) << bad;
  }
  EXPECT_TRUE(parse_civil_time("2000-02-29T00:00").has_value());  // divisible by 400
}

TEST(CivilTime, NamesAnInstantToTheMinute) {
  EXPECT_EQ(minute_text({2026, 3, 21, 6, 5, 59}), "2026-03-21T06:05");
  EXPECT_EQ(minute_text({987, 1, 2, 3, 4, 0}), "0987-01-02T03:04");
  EXPECT_EQ(civil_text({2026, 3, 21, 6, 5, 0}), "2026-03-21T06:05");
  EXPECT_EQ(civil_text({2003, 10, 17, 12, 30, 7}), "2003-10-17T12:30:07");
}

TEST(CivilTime, SecondsRoundTripAcrossMonthsYearsAndLeapDays) {
  EXPECT_EQ(seconds_since_1970({1970, 1, 1, 0, 0, 0}), 0);
  EXPECT_EQ(seconds_since_1970({2000, 3, 1, 0, 0, 0}) - seconds_since_1970({2000, 2, 28, 0, 0, 0}),
            2 * 86400);
  EXPECT_EQ(seconds_since_1970({1969, 12, 31, 23, 59, 0}), -60);
  for (const CivilTime t : {CivilTime{2026, 3, 21, 23, 59, 0}, CivilTime{2024, 2, 29, 12, 0, 1},
                            CivilTime{1600, 1, 1, 0, 0, 0}, CivilTime{9999, 12, 31, 23, 59, 59},
                            CivilTime{0, 3, 1, 0, 0, 0}}) {
    EXPECT_EQ(civil_time_at(seconds_since_1970(t)), t) << minute_text(t);
  }
  EXPECT_EQ(civil_time_at(seconds_since_1970({2026, 12, 31, 23, 50, 0}) + 600),
            (CivilTime{2027, 1, 1, 0, 0, 0}));
}

// J2000.0 is 2000 January 1, 12h: JD 2451545.0; Meeus (example 7.a) gives 1957 October 4.81
// as JD 2436116.31.
TEST(CivilTime, JulianDays) {
  EXPECT_EQ(julian_day({2000, 1, 1, 12, 0, 0}), 2451545.0);
  EXPECT_NEAR(julian_day({1957, 10, 4, 19, 26, 24}), 2436116.31, 1e-9);
  EXPECT_EQ(julian_day({1858, 11, 17, 0, 0, 0}), 2400000.5);  // MJD 0
}

}  // namespace
}  // namespace shadowgen::sun
