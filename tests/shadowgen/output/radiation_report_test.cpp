// The radiation report (shadowgen/output/radiation_report.h): an open horizontal face gets
// the hours' diffuse horizontal and direct normal × cos(zenith) radiation, an open wall the
// ground's albedo × global horizontal × 1/2, a face under a long overhang no direct light
// and the diffuse light of the closed-form view factor, and the CSV's columns.

#include "shadowgen/output/radiation_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/weather/epw_reader.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen {
namespace {

constexpr double kPi = std::numbers::pi;

// Hour h (1 to 24) of the test weather: global horizontal, direct normal and diffuse
// horizontal radiation, all different and changing through the day.
double global_of(int hour) { return 400.0 + hour; }
double direct_of(int hour) { return 300.0 + 10.0 * hour; }
double diffuse_of(int hour) { return 100.0 + 5.0 * hour; }

// Hours 1 to 24 of `month`/`day`, every albedo `albedo` as written.
Weather weather_of(int month, int day, const std::string& albedo = "0.3") {
  std::vector<std::string> lines = test::epw_header();
  for (int h = 1; h <= 24; ++h) {
    lines.push_back(test::epw_row(month, day, h, std::to_string(400 + h),
                                  std::to_string(300 + 10 * h), std::to_string(100 + 5 * h),
                                  albedo));
  }
  return weather::parse_epw(test::joined(lines), "test.epw");
}

// The weather hour an instant reads: the one after its HH (weather/irradiance.h).
int hour_of(const SunInstant& sun) { return std::stoi(sun.time.substr(11, 2)) + 1; }

// The report's rows of `shadowed` under `weather` with `options`, the sky of MF:`n`.
struct Report {
  sky::SkyExposure exposure;
  std::vector<PathSky> skies;
  std::vector<RadiationRow> rows;
};
Report report_of(const ShadowedScene& shadowed, const Weather& weather,
                 const RadiationOptions& options = {}, int n = sky::kDefaultSubdivisions) {
  Report r;
  sky::SkyOptions sky_options;
  sky_options.subdivisions = n;
  r.exposure = sky::sky_exposure(shadowed.scene(), sky_options);
  r.skies = path_skies(shadowed, r.exposure.patches, weather, options);
  r.rows = radiation_rows(shadowed, r.exposure, r.skies, weather);
  return r;
}

constexpr const char* kMarch21 =
    R"("from": "2026-03-21T00:00", "to": "2026-03-21T23:59", "step_min": 60)";

// An open horizontal face: the Perez sky's patches give back each hour's diffuse
// horizontal irradiance (within 0.1 %, the sky room's bound), the direct light is DNI ×
// sin(elevation), and a horizontal face sees no ground.
TEST(RadiationReport, AnOpenHorizontalFaceGetsTheHoursDiffuseAndDirectNormalTimesCosZenith) {
  const ShadowedScene shadowed = test::generated(
      test::site_scene(R"({"id": "roof", "outer": [[0,0,0],[2,0,0],[2,3,0],[0,3,0]]})", kMarch21));
  const Report r = report_of(shadowed, weather_of(3, 21));
  ASSERT_EQ(r.rows.size(), 1u);
  double diffuse = 0.0, direct = 0.0;
  for (const std::size_t l : shadowed.sun_paths[0].instants) {
    const SunInstant& sun = *shadowed.scene().lights[l].sun;
    diffuse += diffuse_of(hour_of(sun));
    direct += direct_of(hour_of(sun)) * std::sin(sun.elevation_deg * kPi / 180.0);
  }
  ASSERT_GE(shadowed.sun_paths[0].instants.size(), 11u);
  const RadiationRow& row = r.rows[0];
  EXPECT_EQ(row.area, 6.0);
  EXPECT_NEAR(row.diffuse_wh / 6.0 / diffuse, 1.0, 1e-3);
  EXPECT_NEAR(row.direct_wh / 6.0 / direct, 1.0, 1e-9);
  EXPECT_EQ(row.ground_wh, 0.0);
  EXPECT_EQ(row.diffuse_wh, row.unshaded_diffuse_wh);
  EXPECT_EQ(row.direct_wh, row.unshaded_direct_wh);
}

// An open wall facing south: its ground view factor is 1/2, so the ground gives
// albedo × GHI / 2 per hour: the weather file's albedo, --albedo's instead, or 0.2 with a
// warning where the file marks it missing.
TEST(RadiationReport, AnOpenWallGetsHalfTheAlbedoTimesGlobalHorizontal) {
  const ShadowedScene shadowed = test::generated(
      test::site_scene(R"({"id": "wall", "outer": [[0,0,0],[4,0,0],[4,0,3],[0,0,3]]})", kMarch21));
  double global = 0.0;
  for (const std::size_t l : shadowed.sun_paths[0].instants) {
    global += global_of(hour_of(*shadowed.scene().lights[l].sun));
  }
  const Report from_file = report_of(shadowed, weather_of(3, 21, "0.3"), {}, 1);
  EXPECT_NEAR(from_file.rows[0].ground_wh / 12.0 / (0.3 * global * 0.5), 1.0, 1e-12);

  RadiationOptions albedo;
  albedo.albedo = 0.7;
  const Report given = report_of(shadowed, weather_of(3, 21, "0.3"), albedo, 1);
  EXPECT_NEAR(given.rows[0].ground_wh / 12.0 / (0.7 * global * 0.5), 1.0, 1e-12);

  std::vector<std::string> warnings;
  RadiationOptions missing;
  missing.on_warning = [&warnings](const std::string& w) { warnings.push_back(w); };
  const Report by_default = report_of(shadowed, weather_of(3, 21, "999"), missing, 1);
  EXPECT_NEAR(by_default.rows[0].ground_wh / 12.0 / (kDefaultAlbedo * global * 0.5), 1.0, 1e-12);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "test.epw: the albedo (field 33) is missing (999) in the hours of " +
                             std::to_string(shadowed.sun_paths[0].instants.size()) +
                             " instants; 0.2 is taken there (--albedo sets it)");
  EXPECT_EQ(by_default.rows[0].unshaded_total_wh() - by_default.rows[0].ground_wh,
            by_default.rows[0].unshaded_direct_wh + by_default.rows[0].unshaded_diffuse_wh);
}

// A square face of side a = 0.2 on the ground under an opaque plate at height h = 1,
// 2w = 4 wide across it (y) and 200 long (x, 100 × its width: infinitely long as far as
// the face can tell, the sky past its ends lying within 0.6° of the horizon). 21 June from
// 10:00 to 14:00 the sun is high enough (|cos azimuth| < 2 tan elevation) that the plate
// hides it: no direct light. Under an isotropic sky of radiance L the diffuse light is
// π L F, F the face's view factor to the sky; the plate and the ground are infinitely
// long, so F is the two-dimensional one, 1 − F(face → plate), and Hottel's crossed strings
// give F(face → plate) = (crossed − uncrossed) / (2a) with the crossed strings from each
// edge of the face to the far edge of the plate, √((w + a/2)² + h²) each, the uncrossed
// ones √((w − a/2)² + h²): F = 1 − (√(2.1² + 1) − √(1.9² + 1)) / 0.2 = 0.10575... The
// patches light a face as their centres do (docs/sky.md): at the default MF:8 that is
// within 0.5 %, the street canyon's bound.
TEST(RadiationReport, AFaceUnderALongOverhangGetsNoDirectAndTheClosedFormsDiffuse) {
  const ShadowedScene shadowed = test::generated(test::site_scene(
      R"({"id": "face", "outer": [[-0.1,-0.1,0],[0.1,-0.1,0],[0.1,0.1,0],[-0.1,0.1,0]]},
         {"id": "plate", "outer": [[-100,-2,1],[-100,2,1],[100,2,1],[100,-2,1]]})",
      R"("from": "2026-06-21T10:00", "to": "2026-06-21T14:00", "step_min": 60)"));
  const Weather weather = weather_of(6, 21);
  sky::SkyOptions sky_options;
  const sky::SkyExposure exposure = sky::sky_exposure(shadowed.scene(), sky_options);
  const double radiance = 1.0;  // Wh/m²/sr on every patch: isotropic
  const std::vector<PathSky> isotropic{
      {std::vector<double>(exposure.patches.size(), radiance), 0.0}};
  const std::vector<RadiationRow> rows = radiation_rows(shadowed, exposure, isotropic, weather);
  ASSERT_EQ(rows.size(), 2u);
  const RadiationRow& face = rows[0];
  EXPECT_EQ(face.direct_wh, 0.0);
  EXPECT_GT(face.unshaded_direct_wh, 0.0);
  const double a = 0.2, w = 2.0, h = 1.0;
  const double crossed = std::sqrt((w + a / 2) * (w + a / 2) + h * h);
  const double uncrossed = std::sqrt((w - a / 2) * (w - a / 2) + h * h);
  const double view_factor = 1.0 - (crossed - uncrossed) / a;
  EXPECT_NEAR(face.unshaded_diffuse_wh / face.area / (kPi * radiance), 1.0, 1e-4);
  EXPECT_NEAR(face.diffuse_wh / face.area / (kPi * radiance * view_factor), 1.0, 0.005);
}

TEST(RadiationReport, TheCsvGivesEveryColumnPerFaceAndPath) {
  const ShadowedScene shadowed = test::generated(
      test::site_scene(R"({"id": "wall", "outer": [[0,0,0],[4,0,0],[4,0,3],[0,0,3]]})", kMarch21));
  const Weather weather = weather_of(3, 21);
  sky::SkyOptions sky_options;
  sky_options.subdivisions = 1;
  const sky::SkyExposure exposure = sky::sky_exposure(shadowed.scene(), sky_options);
  const std::string csv = radiation_csv(shadowed, exposure, weather);
  const Report r = report_of(shadowed, weather, {}, 1);
  const RadiationRow& row = r.rows[0];
  const std::string header =
      "face_id,sun_path,area,direct_wh,diffuse_wh,ground_wh,total_wh,direct_wh_per_area,"
      "diffuse_wh_per_area,ground_wh_per_area,total_wh_per_area,unshaded_total_wh,"
      "unshaded_direct_wh_per_area,unshaded_diffuse_wh_per_area,unshaded_total_wh_per_area,"
      "total_ratio\n";
  ASSERT_EQ(csv.substr(0, header.size()), header);
  EXPECT_EQ(csv.substr(header.size(), 12), "wall,day,12,");
  EXPECT_EQ(row.total_wh(), row.direct_wh + row.diffuse_wh + row.ground_wh);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 2);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), ','), 2 * 15);
}

TEST(RadiationReport, AnHourWithoutDiffuseOrGlobalRadiationIsAnError) {
  const ShadowedScene shadowed = test::generated(
      test::site_scene(R"({"id": "roof", "outer": [[0,0,0],[2,0,0],[2,3,0],[0,3,0]]})",
                       R"("from": "2026-03-21T12:00", "to": "2026-03-21T12:59",
                                          "step_min": 60)"));
  std::vector<std::string> lines = test::epw_header();
  for (int h = 1; h <= 24; ++h) {
    lines.push_back(test::epw_row(3, 21, h, "500", "400", h == 13 ? "9999" : "100", "0.2"));
  }
  const sky::SkyExposure exposure = sky::sky_exposure(shadowed.scene(), {});
  try {
    (void)path_skies(shadowed, exposure.patches, weather::parse_epw(test::joined(lines), "t.epw"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "t.epw: line 21: the diffuse horizontal radiation of month 3 day 21 hour 13 is "
              "marked missing (9999 or more, or negative), and 2026-03-21T12:00 needs it");
  }
}

}  // namespace
}  // namespace shadowgen
