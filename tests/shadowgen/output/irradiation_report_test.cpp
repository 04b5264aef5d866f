// The direct irradiation report (shadowgen/output/irradiation_report.h): energies worked
// out by hand from a weather file's hours, a lone south wall against the sun's azimuth and
// elevation, a face of two parts turned different ways against its instants' lit
// polygons, and the errors for hours the weather file lacks.

#include "shadowgen/output/irradiation_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "hsr/area.h"
#include "hsr/polygon3.h"
#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/database_reader.h"
#include "shadowgen/weather/epw_reader.h"
#include "tests/shadowgen/hand_scenes.h"
#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen {
namespace {

using test::test_direct_normal;

// Hours 1 to 24 of `days` days of `month` from `first_day`, each with test_direct_normal.
Weather weather_of(int month, int first_day, int days) {
  return weather::parse_epw(test::joined(test::epw_lines(month, first_day, days)), "test.epw");
}

double relative(double a, double b) {
  const double scale = std::max(std::fabs(a), std::fabs(b));
  return scale == 0.0 ? 0.0 : std::fabs(a - b) / scale;
}

// Face g (4 × 1, facing +z) under four 30-minute instants from 10:00 on 21 March, the sun
// straight overhead (the lights' default direction), lit 3, 3, 3 and 1.
TEST(IrradiationReport, EnergyIsEachInstantsHourTimesItsLitAreaAndStep) {
  const ShadowedScene shadowed = test::sun_path_by_hand();
  const std::vector<IrradiationRow> rows = irradiation_rows(shadowed, weather_of(3, 21, 1));
  ASSERT_EQ(rows.size(), 1u);
  // The instant at 10:00 reads hour 11 (10:00 to 11:00), and so on.
  const double lit[] = {3, 3, 3, 1};
  double direct = 0.0, unshaded = 0.0;
  for (int k = 0; k < 4; ++k) {
    direct += test_direct_normal(21, 11 + k) * lit[k] * 0.5;
    unshaded += test_direct_normal(21, 11 + k) * 4.0 * 0.5;
  }
  EXPECT_EQ(rows[0].area, 4.0);
  EXPECT_DOUBLE_EQ(rows[0].direct_wh, direct);
  EXPECT_DOUBLE_EQ(rows[0].unshaded_wh, unshaded);
  EXPECT_EQ(irradiation_csv(shadowed, weather_of(3, 21, 1)),
            "face_id,sun_path,area,direct_wh,direct_wh_per_area,unshaded_direct_wh_per_area\n"
            "g,p,4,10563.5,2640.875,4226\n");
}

std::string site_scene(const std::string& polygons, const std::string& path) {
  return R"({"format": "shadowgen-scene/1", "polygons": [)" + polygons +
         R"(], "site": {"latitude_deg": 51.5, "longitude_deg": -0.1, "utc_offset_h": 0},
         "lights": [{"id": "day", "type": "sun", )" +
         path + "}]}";
}

// A wall facing due south (-y; north_axis_deg 0), nothing around it, over 21 June: every
// instant's energy is the hour's direct normal radiation × the wall's area × the cosine
// of incidence worked out from the sun's azimuth A and elevation e alone, -cos A cos e,
// where the sun is in front of the wall.
TEST(IrradiationReport, ALoneSouthWallGetsTheCosineOfTheSunsAzimuthAndElevation) {
  const ShadowedScene shadowed =
      test::generated(site_scene(R"({"id": "wall", "outer": [[0,0,0],[4,0,0],[4,0,3],[0,0,3]]})",
                                 R"("from": "2026-06-21T00:00", "to": "2026-06-21T23:59",
                                    "step_min": 10)"));
  const std::vector<IrradiationRow> rows = irradiation_rows(shadowed, weather_of(6, 21, 1));
  ASSERT_EQ(rows.size(), 1u);
  double expected = 0.0;
  for (const std::size_t l : shadowed.sun_paths[0].instants) {
    const SunInstant& sun = *shadowed.scene().lights[l].sun;
    const int hour = std::stoi(sun.time.substr(11, 2)) + 1;
    const double a = sun.azimuth_deg * M_PI / 180.0, e = sun.elevation_deg * M_PI / 180.0;
    const double cosine = -std::cos(a) * std::cos(e);
    if (cosine > 0.0) expected += test_direct_normal(21, hour) * 12.0 * cosine * 10.0 / 60.0;
  }
  ASSERT_GT(expected, 0.0);
  EXPECT_LT(relative(rows[0].direct_wh, expected), 1e-9);
  EXPECT_LT(relative(rows[0].unshaded_wh, expected), 1e-9);
}

// The dart of kDartUnderRoof (two triangles turned different ways), north of a roof
// whose shadow crosses it, through a day: the energy sums each part's own lit area with its own
// cosine. Worked out here from the instants' lit polygons, kept for it, and read back from the
// database, where only the parts' lit areas are.
TEST(IrradiationReport, EachPartOfAFaceCountsWithItsOwnCosine) {
  const std::string scene = site_scene(R"(
      {"id": "dart", "outer": [[0,0,0],[4,2,0],[0,4,0],[1,2,1]]},
      {"id": "roof", "outer": [[-1,-5,5],[5,-5,5],[5,-1,5],[-1,-1,5]]})",
                                       R"("from": "2026-03-21T06:00", "to": "2026-03-21T18:00",
                                          "step_min": 30)");
  GenerateOptions keep;
  keep.keep_instant_polygons = true;
  const ShadowedScene kept = generate_shadows(parse_scene(scene, "test.json").scene, keep).shadowed;
  const Face& dart = kept.scene().faces[0];
  ASSERT_EQ(dart.parts.size(), 2u);
  const Weather weather = weather_of(3, 21, 1);
  double expected = 0.0;
  bool both_parts_lit = false;
  for (const std::size_t l : kept.sun_paths[0].instants) {
    const Light& light = kept.scene().lights[l];
    const int hour = std::stoi(light.sun->time.substr(11, 2)) + 1;
    const glm::dvec3 to_sun = -glm::normalize(light.direction);
    bool lit_on[2] = {false, false};
    for (const LitPolygon& p : kept.lit()[0][l]) {
      const glm::dvec3 normal = glm::normalize(hsr::newell_vector(dart.parts[p.part].outer));
      expected +=
          test_direct_normal(21, hour) * hsr::area(p.polygon) * glm::dot(normal, to_sun) * 0.5;
      lit_on[p.part] = true;
    }
    both_parts_lit = both_parts_lit || (lit_on[0] && lit_on[1]);
  }
  ASSERT_TRUE(both_parts_lit);
  const ShadowedScene read_back =
      parse_database(database_json(test::generated(scene)), "test.shadowed.json");
  const std::vector<IrradiationRow> rows = irradiation_rows(read_back, weather);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_LT(relative(rows[0].direct_wh, expected), 1e-12);
  EXPECT_LT(rows[0].direct_wh, 0.9 * rows[0].unshaded_wh);  // the roof's shadow crosses it
  EXPECT_EQ(irradiation_csv(read_back, weather), irradiation_csv(kept, weather));
}

TEST(IrradiationReport, AnHourTheWeatherFileLacksOrMarksMissingIsAnError) {
  const ShadowedScene shadowed = test::sun_path_by_hand();
  try {
    (void)irradiation_rows(shadowed, weather_of(3, 22, 1));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "test.epw");
    EXPECT_NE(std::string(e.what()).find("2026-03-21"), std::string::npos) << e.what();
  }
  std::vector<std::string> lines = test::epw_lines(3, 21, 1);
  lines[8 + 11] = test::epw_row(3, 21, 12, "9999");  // 11:00 to 12:00, the second instant
  try {
    (void)irradiation_rows(shadowed, weather::parse_epw(test::joined(lines), "test.epw"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 20"), std::string::npos) << e.what();
  }
  ShadowedScene none = shadowed;
  none.sun_paths.clear();
  EXPECT_THROW((void)irradiation_rows(none, weather_of(3, 21, 1)), InputError);
}

}  // namespace
}  // namespace shadowgen
