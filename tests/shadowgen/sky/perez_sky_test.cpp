#include "shadowgen/sky/perez_sky.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "shadowgen/sky/patch_cosine.h"
#include "shadowgen/sky/sky_exposure.h"
#include "shadowgen/sun/civil_time.h"
#include "shadowgen/sun/sun_position.h"

namespace shadowgen::sky {
namespace {

constexpr double kPi = std::numbers::pi;

// Σ_p L_p I(p, up), I from patch_cosine_integral itself.
double horizontal_irradiance(const std::vector<double>& up, const std::vector<double>& l) {
  double sum = 0.0;
  for (std::size_t k = 0; k < up.size(); ++k) sum += l[k] * up[k];
  return sum;
}

// A year of hours at London (51.5° N, 0.1° W, UT), the sun at each hour's middle, with
// direct normal and diffuse horizontal irradiances that run through every clearness bin
// and brightness from dim to bright, twilight diffuse light included.
std::vector<SkyHour> synthetic_year() {
  std::vector<SkyHour> hours;
  const sun::Observer london{51.5, -0.1, 0.0};
  const std::int64_t start = sun::seconds_since_1970({2026, 1, 1, 0, 0, 0});
  for (int h = 0; h < 8760; ++h) {
    const sun::CivilTime middle = sun::civil_time_at(start + h * 3600 + 1800);
    const sun::SunPosition p =
        sun::sun_position(london, sun::julian_day(middle), sun::delta_t_estimate(2026.0));
    SkyHour hour;
    hour.sun_altitude_rad = p.elevation_deg * kPi / 180.0;
    hour.sun_azimuth_rad = p.azimuth_deg * kPi / 180.0;
    hour.day_of_year = h / 24 + 1;
    const double up = std::max(0.0, std::sin(hour.sun_altitude_rad));
    const double dni_levels[] = {0.0, 20.0, 80.0, 200.0, 400.0, 650.0, 850.0};
    hour.direct_normal_w_m2 = up > 0.0 ? dni_levels[h % 7] : 0.0;
    hour.diffuse_horizontal_w_m2 =
        p.elevation_deg > -6.0 ? 5.0 + 300.0 * up * ((h % 5) + 1) / 5.0 : 0.0;
    hours.push_back(hour);
  }
  return hours;
}

TEST(PerezSky, EveryHourOfAYearIntegratesBackToItsDiffuseHorizontal) {
  const std::vector<SkyPatch> patches = reinhart_patches(kDefaultSubdivisions);
  const PerezSky sky(patches);
  std::vector<double> up;
  for (const SkyPatch& p : patches) up.push_back(patch_cosine_integral(p, {0.0, 0.0, 1.0}));
  int bins[8] = {};
  int hours_with_sky = 0;
  for (const SkyHour& hour : synthetic_year()) {
    const std::vector<double> l = sky.radiance(hour);
    const double dhi = hour.diffuse_horizontal_w_m2;
    if (dhi <= 0.0) {
      EXPECT_EQ(horizontal_irradiance(up, l), 0.0);
      continue;
    }
    ++hours_with_sky;
    if (hour.sun_altitude_rad > 0.0) ++bins[perez_parameters(hour).bin];
    EXPECT_NEAR(horizontal_irradiance(up, l), dhi, 1e-3 * dhi)
        << "day " << hour.day_of_year << " altitude " << hour.sun_altitude_rad;
    for (const double v : l) ASSERT_GE(v, 0.0);
  }
  EXPECT_GT(hours_with_sky, 4000);
  for (int b = 0; b < 8; ++b) EXPECT_GT(bins[b], 0) << "clearness bin " << b;
}

TEST(PerezSky, AClearSkyIsBrightestAroundTheSun) {
  const std::vector<SkyPatch> patches = reinhart_patches(2);
  SkyHour hour;
  hour.sun_altitude_rad = 45.0 * kPi / 180.0;
  hour.sun_azimuth_rad = kPi;  // south
  hour.direct_normal_w_m2 = 850.0;
  hour.diffuse_horizontal_w_m2 = 80.0;
  hour.day_of_year = 172;
  EXPECT_EQ(perez_parameters(hour).bin, 7);
  const std::vector<double> l = PerezSky(patches).radiance(hour);
  const auto brightest = std::max_element(l.begin(), l.end()) - l.begin();
  const glm::dvec3 sun{0.0, -std::cos(kPi / 4.0), std::sin(kPi / 4.0)};
  const glm::dvec3& c = patches[static_cast<std::size_t>(brightest)].centre;
  EXPECT_GT(c.x * sun.x + c.y * sun.y + c.z * sun.z, std::cos(10.0 * kPi / 180.0));
}

TEST(PerezSky, AnOvercastSkyIsBrighterAtTheZenithThanAtTheHorizonAwayFromTheSun) {
  const std::vector<SkyPatch> patches = reinhart_patches(1);
  SkyHour hour;
  hour.sun_altitude_rad = 20.0 * kPi / 180.0;
  hour.direct_normal_w_m2 = 0.0;
  hour.diffuse_horizontal_w_m2 = 150.0;
  EXPECT_EQ(perez_parameters(hour).bin, 0);
  const std::vector<double> l = PerezSky(patches).radiance(hour);
  // The sun is due north (azimuth 0); patch 16 is the horizon's due south, away from the
  // circumsolar brightening: the gradation a exp(b / cos ζ) (a > 0, b < 0) and the
  // indicatrix make the zenith 1.6 times as bright by the 1993 paper's formulas.
  EXPECT_NEAR(patches[15].centre.y, -std::cos(6.0 * kPi / 180.0), 1e-12);
  EXPECT_GT(l.back(), 1.5 * l[15]);
}

TEST(PerezSky, TwilightIsIsotropicAndNoDiffuseIsDark) {
  const std::vector<SkyPatch> patches = reinhart_patches(1);
  SkyHour hour;
  hour.sun_altitude_rad = -3.0 * kPi / 180.0;
  hour.diffuse_horizontal_w_m2 = 10.0;
  const PerezSky sky(patches);
  for (const double v : sky.radiance(hour)) EXPECT_NEAR(v, 10.0 / kPi, 1e-12);
  hour.diffuse_horizontal_w_m2 = 0.0;
  for (const double v : sky.radiance(hour)) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace shadowgen::sky
