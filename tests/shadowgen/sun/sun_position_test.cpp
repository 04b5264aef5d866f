// Tests of shadowgen/sun/sun_position.h against published values: NREL's worked example,
// Meeus's example 25.b, and the instants of equinoxes and solstices that the US Naval
// Observatory publishes (at which the sun's apparent longitude is 0°, 90°, 180° or 270°).

#include "shadowgen/sun/sun_position.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "shadowgen/sun/civil_time.h"

namespace shadowgen::sun {
namespace {

double julian_day_of(const std::string& text) {
  const std::optional<CivilTime> time = parse_civil_time(text);
  EXPECT_TRUE(time.has_value()) << text;
  return time ? julian_day(*time) : 0.0;
}

// Reda and Andreas (NREL/TP-560-34302, 2008), Table A5.1: 2003-10-17 12:30:30 at UTC-7
// (19:30:30 UT), ΔT 67 s, 39.742476° N, 105.1786° W, 1830.14 m, 820 hPa, 11 °C.
TEST(SunPosition, MatchesNrelsWorkedExample) {
  const Observer golden{39.742476, -105.1786, 1830.14, 820.0, 11.0};
  const double jd = julian_day_of("2003-10-17T19:30:30");
  EXPECT_NEAR(jd, 2452930.312847, 1e-6);
  const SunPosition p = sun_position(golden, jd, 67.0);
  EXPECT_NEAR(90.0 - p.elevation_deg, 50.11162, 1e-4);  // topocentric zenith
  EXPECT_NEAR(p.azimuth_deg, 194.34024, 1e-4);
  EXPECT_NEAR(p.right_ascension_deg, 202.22741, 1e-4);
  EXPECT_NEAR(p.declination_deg, -9.31434, 1e-4);
}

// The same instant under the standard atmosphere: refraction at 39.9° is 0.0196°, not
// 0.0163° (Saemundsson's formula scaled by 1010/820 and 284/283).
TEST(SunPosition, RefractionFollowsPressureAndTemperature) {
  const double jd = julian_day_of("2003-10-17T19:30:30");
  const SunPosition thin = sun_position({39.742476, -105.1786, 1830.14, 820.0, 11.0}, jd, 67.0);
  const SunPosition standard = sun_position({39.742476, -105.1786, 1830.14}, jd, 67.0);
  EXPECT_NEAR(standard.elevation_deg - thin.elevation_deg,
              0.016332 * (1010.0 / 820.0 * 284.0 / 283.0 - 1.0), 2e-5);
  EXPECT_EQ(standard.azimuth_deg, thin.azimuth_deg);
}

// Meeus, Astronomical Algorithms (2nd ed.), example 25.b: 1992 October 13.0 TD, the sun's
// apparent α = 13h13m30.749s = 198.378178°, δ = -7°47'01.74" = -7.783872° (full VSOP87;
// the algorithm's truncated series stays within 1e-4°).
TEST(SunPosition, MatchesMeeusExample25b) {
  const SunPosition p = sun_position({}, 2448908.5, 0.0);
  EXPECT_NEAR(p.right_ascension_deg, 198.378178, 1e-4);
  EXPECT_NEAR(p.declination_deg, -7.783872, 1e-4);
}

struct Season {
  const char* utc;       // USNO, "Earth's Seasons", to the minute
  double longitude_deg;  // the sun's apparent longitude then
};

void PrintTo(const Season& s, std::ostream* os) { *os << s.utc; }

class SunAtSeasons : public ::testing::TestWithParam<Season> {};

// At an equinox or solstice the apparent longitude λ is a multiple of 90°, so α = λ and
// δ = 0 or ±ε (ε ≈ 23.438° in 2024 to 2026, true obliquity with nutation). The sun moves
// 0.041° an hour in α: the published minute is good to 0.0007°.
TEST_P(SunAtSeasons, RightAscensionAndDeclinationAreTheSeasons) {
  const Season& s = GetParam();
  const double jd = julian_day_of(s.utc);
  const SunPosition p = sun_position({}, jd, delta_t_estimate(2025.0));
  double offset = p.right_ascension_deg - s.longitude_deg;
  if (offset > 180.0) offset -= 360.0;
  EXPECT_NEAR(offset, 0.0, 0.01);
  const double expected_declination =
      s.longitude_deg == 90.0 ? 23.438 : (s.longitude_deg == 270.0 ? -23.438 : 0.0);
  EXPECT_NEAR(p.declination_deg, expected_declination, 0.01);
}

INSTANTIATE_TEST_SUITE_P(
    Usno, SunAtSeasons,
    ::testing::Values(Season{"2024-03-20T03:06", 0.0}, Season{"2024-06-20T20:51", 90.0},
                      Season{"2024-09-22T12:44", 180.0}, Season{"2024-12-21T09:20", 270.0},
                      Season{"2025-03-20T09:01", 0.0}, Season{"2025-06-21T02:42", 90.0},
                      Season{"2025-09-22T18:19", 180.0}, Season{"2025-12-21T15:03", 270.0},
                      Season{"2026-03-20T14:46", 0.0}, Season{"2026-06-21T08:24", 90.0},
                      Season{"2026-09-23T00:05", 180.0}, Season{"2026-12-21T20:50", 270.0}));

// At an equinox the sun stands due east all morning and due west all afternoon seen from
// the equator (δ = 0): at the 2026 March equinox (14:46 UT) it is morning at 90° W and
// afternoon on the Greenwich meridian, the sun well above the horizon at both.
TEST(SunPosition, OnTheEquatorAtAnEquinoxTheSunIsDueEastOrDueWest) {
  const double jd = julian_day_of("2026-03-20T14:46");
  const SunPosition morning = sun_position({0.0, -90.0}, jd, delta_t_estimate(2026.2));
  const SunPosition afternoon = sun_position({0.0, 0.0}, jd, delta_t_estimate(2026.2));
  EXPECT_NEAR(morning.azimuth_deg, 90.0, 0.01);
  EXPECT_NEAR(afternoon.azimuth_deg, 270.0, 0.01);
  EXPECT_GT(morning.elevation_deg, 5.0);
  EXPECT_GT(afternoon.elevation_deg, 5.0);
  // The sun is then a quarter turn of the Earth's rotation apart in hour angle.
  EXPECT_NEAR(morning.elevation_deg + afternoon.elevation_deg, 90.0, 0.05);
}

// Seen from a pole the sun's elevation is its declination, whatever the hour: at the
// June solstices from the North Pole and the December ones from the South Pole, ε (23.438°)
// plus the refraction there (0.038°, Bennett and Saemundsson alike) less the parallax
// (0.002°).
TEST(SunPosition, FromThePoleAtASolsticeTheSunStandsAtTheObliquity) {
  for (const char* june : {"2024-06-20T20:51", "2025-06-21T02:42", "2026-06-21T08:24"}) {
    const SunPosition p = sun_position({90.0, 0.0}, julian_day_of(june), 69.0);
    EXPECT_NEAR(p.elevation_deg, 23.438 + 0.038 - 0.002, 0.01) << june;
  }
  for (const char* december : {"2024-12-21T09:20", "2025-12-21T15:03", "2026-12-21T20:50"}) {
    const SunPosition p = sun_position({-90.0, 0.0}, julian_day_of(december), 69.0);
    EXPECT_NEAR(p.elevation_deg, 23.438 + 0.038 - 0.002, 0.01) << december;
  }
}

TEST(SunPosition, BelowTheHorizonNoRefractionIsAdded) {
  // Midnight at Greenwich in March: the sun is some 38° below the horizon, and its
  // elevation is the true one, so that raising the pressure changes nothing.
  const double jd = julian_day_of("2026-03-21T00:00");
  const SunPosition low = sun_position({51.4779, -0.0015, 45.0, 1010.0, 10.0}, jd, 69.0);
  const SunPosition dense = sun_position({51.4779, -0.0015, 45.0, 1100.0, -20.0}, jd, 69.0);
  EXPECT_LT(low.elevation_deg, -37.0);
  EXPECT_EQ(low.elevation_deg, dense.elevation_deg);
}

// Espenak and Meeus's values for 2005 (64.7 s measured) and 2000 (63.8 s).
TEST(DeltaT, FollowsThePublishedPolynomials) {
  EXPECT_NEAR(delta_t_estimate(2000.0), 63.86, 1e-9);
  EXPECT_NEAR(delta_t_estimate(2005.0), 62.92 + 0.32217 * 5.0 + 0.005589 * 25.0, 1e-9);
  EXPECT_NEAR(delta_t_estimate(2005.0), 64.69, 0.1);
}

}  // namespace
}  // namespace shadowgen::sun
