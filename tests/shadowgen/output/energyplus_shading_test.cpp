// The EnergyPlus shading schedule (shadowgen/output/energyplus_shading.h): its header,
// time stamps and fractions against sums made by hand, a whole leap year generated for a
// roof in an empty site, and the inputs EnergyPlus could not read.

#include "shadowgen/output/energyplus_shading.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Faces "roof" (area 4) and "Wall-South" (area 2), a path "day" of `step_min` from `from` to
// `to` whose instants are `lit`: (time, roof's lit area, wall's lit area). Read from
// "test.json", the file of its faces too.
ShadowedScene by_hand(int step_min, const std::string& from, const std::string& to,
                      const std::vector<std::tuple<std::string, double, double>>& lit) {
  Scene scene;
  scene.file = "test.json";
  scene.faces.push_back({"roof", {test::unit_strip(0, 4)}, "test.json"});
  scene.faces.push_back({"Wall-South", {test::unit_strip(0, 2)}, "test.json"});
  SunPathHours path;
  path.id = "day";
  path.step_min = step_min;
  path.from = from;
  path.to = to;
  path.lit_area.resize(2);
  path.part_lit_area.resize(2);
  path.regions.resize(2);
  for (const auto& [time, roof, wall] : lit) {
    Light light;
    light.id = "day@" + time;
    light.sun = SunInstant{"day", time, step_min, 180.0, 30.0};
    path.instants.push_back(scene.lights.size());
    scene.lights.push_back(light);
    path.lit_area[0].push_back(roof);
    path.lit_area[1].push_back(wall);
  }
  ShadowedScene shadowed(std::move(scene),
                         LitTable(2, lit.size(), std::vector<bool>(lit.size(), false)));
  shadowed.sun_paths.push_back(std::move(path));
  return shadowed;
}

TEST(EnergyPlusShading, OneRowPerHourStampedWithItsEndHoldingTheInstantThatStartsIt) {
  const EnergyPlusShading out =
      energyplus_shading(by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59",
                                 {{"2026-06-21T05:00", 1, 0}, {"2026-06-21T12:00", 4, 0.875}}));
  const std::vector<std::string> rows = lines_of(out.csv);
  ASSERT_EQ(rows.size(), 1u + 24u);
  EXPECT_EQ(rows[0], "Surface Name,ROOF,WALL-SOUTH,");
  EXPECT_EQ(rows[1], " 06/21 01:00,0.00000000,0.00000000,");
  EXPECT_EQ(rows[6], " 06/21 06:00,0.25000000,0.00000000,");   // 05:00 to 06:00
  EXPECT_EQ(rows[13], " 06/21 13:00,1.00000000,0.43750000,");  // 12:00 to 13:00
  EXPECT_EQ(rows[24], " 06/21 24:00,0.00000000,0.00000000,");
  ASSERT_EQ(out.warnings.size(), 1u);
  EXPECT_EQ(out.warnings[0],
            "sun path 'day' covers 1 days, from 2026-06-21T00:00 to 2026-06-21T23:59: EnergyPlus "
            "reads Schedule:File:Shading only for a whole year (January 1 to December 31 at "
            "every time step)");
}

TEST(EnergyPlusShading, AnEnergyPlusModelsFaceIsNamedByItsSurfaceNameAlone) {
  ShadowedScene shadowed =
      by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59", {{"2026-06-21T12:00", 4, 0.875}});
  shadowed.edit_face(1, [&](Face& face) { face.id = "house/Zn001:Wall-South"; });
  shadowed.edit_face(1, [&](Face& face) {
    face.origin = {"energyplus", "Zn001:Wall-South", "Zn001", "Wall"};
  });
  EXPECT_EQ(lines_of(energyplus_shading(shadowed).csv)[0], "Surface Name,ROOF,ZN001:WALL-SOUTH,");
  // Two models' surfaces of one name cannot both be EnergyPlus surfaces.
  shadowed.edit_face(0, [&](Face& face) { face.id = "other/zn001:wall-south"; });
  shadowed.edit_face(0, [&](Face& face) {
    face.origin = {"energyplus", "zn001:wall-south", "Zn001", "Wall"};
  });
  try {
    energyplus_shading(shadowed);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.json: face 'house/Zn001:Wall-South': is the EnergyPlus surface name "
              "ZN001:WALL-SOUTH in upper case, as face 'other/zn001:wall-south' is");
  }
}

TEST(EnergyPlusShading, QuarterHourStepsAndDaysRunOn) {
  const EnergyPlusShading out =
      energyplus_shading(by_hand(15, "2026-12-31T00:00", "2027-01-01T23:45",
                                 {{"2026-12-31T23:45", 2, 2}, {"2027-01-01T00:00", 4, 1}}));
  const std::vector<std::string> rows = lines_of(out.csv);
  ASSERT_EQ(rows.size(), 1u + 2u * 96u);
  EXPECT_EQ(rows[1].substr(0, 13), " 12/31 00:15,");
  EXPECT_EQ(rows[4].substr(0, 13), " 12/31 01:00,");
  EXPECT_EQ(rows[96], " 12/31 24:00,0.50000000,1.00000000,");
  EXPECT_EQ(rows[97], " 01/01 00:15,1.00000000,0.50000000,");
  EXPECT_EQ(rows[192].substr(0, 13), " 01/01 24:00,");
}

// A roof alone under a year of hourly suns in 2028, a leap year: 366 × 24 rows, the roof
// wholly lit at every hour that starts with the sun up and dark at the others.
TEST(EnergyPlusShading, AWholeLeapYearIsWhatEnergyPlusReads) {
  const ShadowedScene shadowed = test::generated(R"({"format": "shadowgen-scene/1",
      "polygons": [{"id": "roof", "outer": [[0,0,3],[4,0,3],[4,4,3],[0,4,3]]}],
      "site": {"latitude_deg": 51.5, "longitude_deg": -0.1, "utc_offset_h": 0},
      "lights": [{"id": "year", "type": "sun", "from": "2028-01-01T00:00",
                  "to": "2028-12-31T23:59", "step_min": 60}]})");
  const EnergyPlusShading out = energyplus_shading(shadowed);
  EXPECT_TRUE(out.warnings.empty());
  const std::vector<std::string> rows = lines_of(out.csv);
  ASSERT_EQ(rows.size(), 1u + 366u * 24u);
  std::size_t lit = 0, dark = 0;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::string value = rows[r].substr(13);
    if (value == "1.00000000,") ++lit;
    if (value == "0.00000000,") ++dark;
  }
  EXPECT_EQ(lit, shadowed.sun_paths[0].instants.size());
  EXPECT_EQ(lit + dark, 366u * 24u);
  EXPECT_EQ(rows[60 * 24 - 11].substr(0, 13), " 02/29 13:00,");  // day 60, 12:00 to 13:00
  EXPECT_EQ(rows[60 * 24 - 11].substr(13), "1.00000000,");
}

std::string error_of(const ShadowedScene& shadowed) {
  try {
    (void)energyplus_shading(shadowed);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EnergyPlusShading, WhatEnergyPlusCouldNotReadIsRefused) {
  EXPECT_EQ(error_of(by_hand(7, "2026-06-21T00:00", "2026-06-21T23:59", {})),
            "test.json: sun path 'day' steps by 7 minutes; EnergyPlus's time steps divide an "
            "hour (1, 2, 3, 4, 5, 6, 10, 12, 15, 20, 30 or 60 minutes)");
  EXPECT_EQ(error_of(by_hand(10, "2026-06-21T00:05", "2026-06-21T23:59", {})),
            "test.json: sun path 'day' starts at 2026-06-21T00:05, not at the start of one of its "
            "10-minute time steps in the day");
  ShadowedScene comma = by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59", {});
  comma.edit_face(1, [&](Face& face) { face.id = "wall,south"; });
  EXPECT_EQ(error_of(comma),
            "test.json: face 'wall,south': cannot be an EnergyPlus surface name: it holds a "
            "comma, which separates fields");
  ShadowedScene same = by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59", {});
  same.edit_face(1, [&](Face& face) { face.id = "Roof"; });
  EXPECT_EQ(error_of(same),
            "test.json: face 'Roof': is the EnergyPlus surface name ROOF in upper case, as face "
            "'roof' is");
  ShadowedScene two = by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59", {});
  two.sun_paths.push_back(two.sun_paths[0]);
  two.sun_paths[1].id = "other";
  EXPECT_EQ(error_of(two),
            "test.json: has 2 sun paths (day, other); a shading schedule is of one: choose it "
            "with --lights ID");
  ShadowedScene none = by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59", {});
  none.sun_paths.clear();
  EXPECT_NE(error_of(none).find("has no sun path"), std::string::npos);
}

// A database names its faces' scene in source_file; the errors name the database read, the
// file the user gave.
TEST(EnergyPlusShading, ErrorsNameTheInputReadNotTheSceneItsFacesCameFrom) {
  // The path by hand, read from "db.json"; its faces came from "test.json".
  const auto from_db = [] {
    ShadowedScene shadowed = by_hand(60, "2026-06-21T00:00", "2026-06-21T23:59", {});
    shadowed.edit_scene([&](Scene& scene) { scene.file = "db.json"; });
    return shadowed;
  };
  ShadowedScene none = from_db();
  none.sun_paths.clear();
  EXPECT_EQ(error_of(none),
            "db.json: has no sun path (a `sun` light with from, to and step_min) to report a "
            "shading schedule of");
  ShadowedScene same = from_db();
  same.edit_face(1, [&](Face& face) { face.id = "Roof"; });
  EXPECT_EQ(error_of(same),
            "db.json: face 'Roof': is the EnergyPlus surface name ROOF in upper case, as face "
            "'roof' is");
  ShadowedScene comma = from_db();
  comma.edit_face(0, [&](Face& face) { face.id = "roof,north"; });
  EXPECT_EQ(error_of(comma),
            "db.json: face 'roof,north': cannot be an EnergyPlus surface name: it holds a comma, "
            "which separates fields");
}

}  // namespace
}  // namespace shadowgen
