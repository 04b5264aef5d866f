// End-to-end tests of `shadowgen sun`: the built executable lists a scene's sun instants
// as CSV, on standard output or into a file; bad input exits 1 with one message and
// leaves no file behind. And of sun paths summed into sun hours: `generate` writes the
// sums, `report --format sun-hours` reads them from a scene or a database alike, and the
// commands that draw lit polygons say what a database without the instants' polygons
// cannot give them.

#include <gtest/gtest.h>

#include <cstddef>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen::test {
namespace {

constexpr const char* kHeader =
    "light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,direction_z";

// A roof over a patio at the Royal Observatory, Greenwich, on 21 March 2026: a single
// instant at noon and an hourly path over the day.
const std::string kScene = R"({
  "format": "shadowgen-scene/1",
  "polygons": [{"id": "patio", "outer": [[-5,-5,0],[5,-5,0],[5,5,0],[-5,5,0]]}],
  "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "elevation_m": 45,
           "utc_offset_h": 0, "north_axis_deg": 0},
  "lights": [
    {"id": "noon", "type": "sun", "time": "2026-03-21T12:00"},
    {"id": "march21", "type": "sun", "from": "2026-03-21T00:00", "to": "2026-03-21T23:59",
     "step_min": 60}
  ]
})";

// A yard north of a 4 m wall at Greenwich, over the day of 21 March 2026, every 30 minutes.
const std::string kYard = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "yard", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "wall", "outer": [[0,-0.5,0],[10,-0.5,0],[10,-0.5,4],[0,-0.5,4]]}
  ],
  "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
  "lights": [{"id": "march21", "type": "sun", "from": "2026-03-21T06:00",
              "to": "2026-03-21T18:30", "step_min": 30}]
})";

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class SunCli : public CliFolderTest<> {
 protected:
  SunCli() : CliFolderTest("shadowgen-sun") {}
};

// The sun is up from 06:03 to 18:13 GMT that day: the hourly instants 07:00 to 18:00.
TEST_F(SunCli, ListsEveryInstantOnStandardOutput) {
  const fs::path scene = write("greenwich.json", kScene);
  const Outcome o = run({"sun", scene.string()});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.err, "");
  const std::vector<std::string> rows = lines(o.out);
  ASSERT_EQ(rows.size(), 1u + 1u + 12u);
  EXPECT_EQ(rows[0], kHeader);
  const std::vector<std::string> noon = csv_fields(rows[1]);
  ASSERT_EQ(noon.size(), 9u);
  EXPECT_EQ(noon[0], "noon");
  EXPECT_EQ(noon[1], "noon");
  EXPECT_EQ(noon[2], "2026-03-21T12:00");
  EXPECT_EQ(noon[3], "0");
  EXPECT_NEAR(std::stod(noon[4]), 177.71, 0.01);  // azimuth: just east of south
  EXPECT_NEAR(std::stod(noon[5]), 38.87, 0.01);   // elevation
  EXPECT_GT(std::stod(noon[7]), 0.77);            // the light travels north (+y)
  EXPECT_LT(std::stod(noon[8]), -0.62);           // and down
  EXPECT_EQ(csv_fields(rows[2])[1], "march21@2026-03-21T07:00");
  EXPECT_EQ(csv_fields(rows[2])[3], "60");
  EXPECT_EQ(csv_fields(rows.back())[1], "march21@2026-03-21T18:00");
}

TEST_F(SunCli, WritesAFileAndTakesTheSunPathsIdInLights) {
  const fs::path scene = write("greenwich.json", kScene);
  const Outcome o =
      run({"sun", scene.string(), "--lights", "march21", "-o", (dir_ / "instants.csv").string()});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out, "");
  const std::vector<std::string> rows = lines(contents(dir_ / "instants.csv"));
  ASSERT_EQ(rows.size(), 13u);
  for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_EQ(csv_fields(rows[k])[0], "march21");
}

TEST_F(SunCli, ASunLightWithoutASiteExits1NamingTheLightAndLeavesNoFile) {
  const fs::path scene = write("nosite.json",
                               R"({"format": "shadowgen-scene/1", "polygons": [],
          "lights": [{"id": "noon", "type": "sun", "time": "2026-03-21T12:00"}]})");
  const Outcome o = run({"sun", scene.string(), "-o", (dir_ / "instants.csv").string()});
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.err, "shadowgen: " + scene.string() +
                       ": light 'noon': lights[0] ('noon'): a sun light needs the scene's "
                       "\"site\" (latitude_deg, longitude_deg, utc_offset_h) or a \"weather\" "
                       "file, and it has neither\n");
  EXPECT_EQ(files(), std::vector<std::string>{"nosite.json"});
}

// A scene without sun lights is bad input naming it (it once printed the header alone and
// exited 0, as if the suns had all been down); nothing is written.
TEST_F(SunCli, ASceneWithoutSunsIsAnErrorNamingIt) {
  const fs::path scene = write("lamp.json", R"({"format": "shadowgen-scene/1", "polygons": [],
                       "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 3]}]})");
  const Outcome o = run({"sun", scene.string(), "-o", (dir_ / "instants.csv").string()});
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.out, "");
  EXPECT_EQ(o.err, "shadowgen: " + scene.string() +
                       ": has no sun lights (a light of type \"sun\", at a time or from, to and "
                       "step_min) to list the instants of\n");
  EXPECT_EQ(files(), std::vector<std::string>{"lamp.json"});
}

TEST_F(SunCli, ThreadsIsNotAnOptionOfIt) {
  const fs::path scene = write("greenwich.json", kScene);
  EXPECT_EQ(run({"sun", scene.string(), "--threads", "2"}).code, 2);
}

TEST_F(SunCli, TheReportIsTheSameFromTheSceneAndFromItsDatabase) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome from_db =
      run({"report", db.string(), "--format", "sun-hours", "--threshold", "2,8"});
  const Outcome from_scene = run(
      {"report", scene.string(), "--format", "sun-hours", "--threshold", "2", "--threshold", "8"});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.err, "");
  EXPECT_EQ(from_scene.out, from_db.out);
  const std::vector<std::string> rows = lines(from_db.out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0],
            "face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours,"
            "area_at_least_2h,area_at_least_8h");
  const std::vector<std::string> yard = csv_fields(rows[1]);
  ASSERT_EQ(yard.size(), 8u);
  EXPECT_EQ(yard[0], "yard");
  EXPECT_EQ(yard[2], "100");
  // The wall shades the yard's south edge around noon (its ends let the low morning and
  // evening sun in), and the north part gets the whole day: 24 instants, 06:30 to 18:00.
  EXPECT_LT(std::stod(yard[4]), 6.0);
  EXPECT_EQ(std::stod(yard[5]), 12.0);
  EXPECT_GT(std::stod(yard[6]), std::stod(yard[7]));
  EXPECT_LT(std::stod(yard[6]), 100.0);
  // The instants' rows come from the stored lit areas.
  const Outcome csv = run({"report", db.string()});
  ASSERT_EQ(csv.code, 0) << csv.err;
  EXPECT_EQ(lines(csv.out).size(), 1u + 2u * 24u);
  EXPECT_EQ(csv.out, run({"report", scene.string()}).out);
}

TEST_F(SunCli, ExportOfSummedInstantsWarnsAndPartOfAPathIsRefused) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome exported = run({"export", db.string(), "--obj", (dir_ / "yard.obj").string()});
  ASSERT_EQ(exported.code, 0) << exported.err;
  EXPECT_EQ(exported.err,
            "shadowgen: warning: " + db.string() +
                ": sun path 'march21': its instants' lit polygons were summed into sun hours, "
                "not kept, so its instants are left out (generate --keep-instants keeps them)\n");
  const Outcome part = run({"report", db.string(), "--lights", "march21@2026-03-21T12:00"});
  EXPECT_EQ(part.code, 1);
  EXPECT_EQ(part.err, "shadowgen: " + db.string() +
                          ": --lights names 1 of the 24 instants of sun path 'march21', whose "
                          "lit polygons were summed into sun hours: name the path itself, or "
                          "generate with --keep-instants\n");
  EXPECT_EQ(run({"report", db.string(), "--lights", "march21", "--format", "sun-hours"}).code, 0);
  // Kept, the instants' polygons are exported like any light's.
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string(), "--keep-instants"}).code, 0);
  const Outcome kept = run({"export", db.string(), "--obj", (dir_ / "yard.obj").string()});
  ASSERT_EQ(kept.code, 0) << kept.err;
  EXPECT_EQ(kept.err, "");
  EXPECT_NE(contents(dir_ / "yard.mtl").find("march21@2026-03-21T12:00"), std::string::npos);
}

TEST_F(SunCli, LitAreasAloneServeTheScheduleButNotTheSunHoursRegions) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string(), "--areas-only"}).code, 0);
  const Outcome schedule = run({"report", db.string(), "--format", "energyplus"});
  ASSERT_EQ(schedule.code, 0) << schedule.err;
  EXPECT_EQ(schedule.out, run({"report", scene.string(), "--format", "energyplus"}).out);
  EXPECT_EQ(run({"report", db.string()}).out, run({"report", scene.string()}).out);
  // Named by the database read, not by the scene it was generated from.
  const std::string refused = "shadowgen: " + db.string() +
                              ": sun path 'march21' was summed into lit areas alone (generate "
                              "--areas-only), without the sun-hours regions ";
  const Outcome report = run({"report", db.string(), "--format", "sun-hours"});
  EXPECT_EQ(report.code, 1);
  EXPECT_EQ(report.err, refused + "a sun-hours report needs: generate without --areas-only\n");
  const Outcome map = run({"render", db.string(), "--sun-hours", "march21", "--eye", "5,-20,10",
                           "--target", "5,5,0", "--svg", (dir_ / "map.svg").string()});
  EXPECT_EQ(map.code, 1);
  EXPECT_EQ(map.err, refused + "a sun-hours map needs: generate without --areas-only\n");
  const Outcome bands = run(
      {"export", db.string(), "--sun-hours", "march21", "--obj", (dir_ / "bands.obj").string()});
  EXPECT_EQ(bands.code, 1);
  EXPECT_EQ(bands.err, refused + "an export by hour bands needs: generate without --areas-only\n");
  EXPECT_EQ(files(), std::vector<std::string>({"yard.json", "yard.shadowed.json"}));
}

// One instant of a path named alone is a light of its own, not the path: the sun-hours
// report and the shading schedule, which need the whole path, say there is none (where
// they gave 0.5 h for the instant and no sun at the path's other steps), and the
// database holds the light with no path claiming the path's span.
TEST_F(SunCli, AnInstantOfAPathNamedAloneIsALightOfItsOwnNotThePath) {
  const fs::path scene = write("yard.json", kYard);
  const std::string noon = "march21@2026-03-21T12:00";
  for (const auto& [format, what] : {std::pair<std::string, std::string>{"sun-hours", "sun hours"},
                                     {"energyplus", "a shading schedule"}}) {
    const Outcome o = run({"report", scene.string(), "--format", format, "--lights", noon});
    EXPECT_EQ(o.code, 1) << format;
    EXPECT_EQ(o.err, "shadowgen: " + scene.string() +
                         ": has no sun path (a `sun` light with from, to and step_min) to report " +
                         what + " of\n");
    EXPECT_EQ(o.out, "");
  }
  const fs::path db = dir_ / "noon.shadowed.json";
  const Outcome generated = run({"generate", scene.string(), "-o", db.string(), "--lights", noon});
  ASSERT_EQ(generated.code, 0) << generated.err;
  const nlohmann::json written = nlohmann::json::parse(contents(db));
  EXPECT_FALSE(written.contains("sun_paths"));
  ASSERT_EQ(written.at("lights").size(), 1u);
  EXPECT_EQ(written["lights"][0]["id"], noon);
  EXPECT_EQ(written["lights"][0]["sun"]["entry"], noon);
  EXPECT_EQ(written["lights"][0]["sun"]["step_min"], 0);
  // Its lit polygons are the instant's: the report reads them back as the scene gives them.
  const Outcome from_db = run({"report", db.string()});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, run({"report", scene.string(), "--lights", noon}).out);
  EXPECT_EQ(lines(from_db.out).size(), 3u);
  EXPECT_EQ(run({"report", db.string(), "--format", "sun-hours"}).code, 1);
}

// 21 December at Tromsø (69.65° N): the sun below the horizon at every hour. A polar
// night is a sun path with no sun, not an error: every face gets 0 sun hours and the
// shading schedule a row of zeros at each of the 24 steps, from the scene and from its
// database alike, and shards of it merge into the file one run writes.
TEST_F(SunCli, APolarNightIsAPathWithNoSun) {
  std::string night = kYard;
  night.replace(night.find("51.4779"), 7, "69.65");
  night.replace(night.find("-0.0015"), 7, "18.96");
  night.replace(night.find(R"("utc_offset_h": 0)"), 17, R"("utc_offset_h": 1)");
  night.replace(night.find("2026-03-21T06:00"), 16, "2026-12-21T00:00");
  night.replace(night.find("2026-03-21T18:30"), 16, "2026-12-21T23:00");
  night.replace(night.find(R"("step_min": 30)"), 14, R"("step_min": 60)");
  night.replace(night.find("march21"), 7, "dec21");
  const fs::path scene = write("tromso.json", night);
  const fs::path db = dir_ / "tromso.shadowed.json";
  const Outcome generated = run({"generate", scene.string(), "-o", db.string()});
  ASSERT_EQ(generated.code, 0) << generated.err;
  EXPECT_EQ(generated.err, "shadowgen: warning: " + scene.string() +
                               ": light 'dec21': lights[0] ('dec21'): the sun is below the "
                               "horizon at every instant of the path\n");
  for (const fs::path& input : {scene, db}) {
    const Outcome hours = run({"report", input.string(), "--format", "sun-hours"});
    ASSERT_EQ(hours.code, 0) << hours.err;
    EXPECT_EQ(hours.out,
              "face_id,sun_path,area,mean_sun_hours,min_sun_hours,max_sun_hours,"
              "area_at_least_2h\n"
              "yard,dec21,100,0,0,0,0\n"
              "wall,dec21,40,0,0,0,0\n");
    const Outcome schedule = run({"report", input.string(), "--format", "energyplus"});
    ASSERT_EQ(schedule.code, 0) << schedule.err;
    const std::vector<std::string> rows = lines(schedule.out);
    ASSERT_EQ(rows.size(), 1u + 24u);
    EXPECT_EQ(rows[0], "Surface Name,YARD,WALL,");
    for (int hour = 1; hour <= 24; ++hour) {
      const std::string stamp = (hour < 10 ? " 12/21 0" : " 12/21 ") + std::to_string(hour);
      EXPECT_EQ(rows[static_cast<std::size_t>(hour)], stamp + ":00,0.00000000,0.00000000,");
    }
  }
  std::vector<std::string> merge = {"merge"};
  for (const char* share : {"1/2", "2/2"}) {
    const fs::path shard = dir_ / ("shard-" + std::string(share, 1) + ".json");
    const Outcome o = run({"generate", scene.string(), "-o", shard.string(), "--instants", share});
    ASSERT_EQ(o.code, 0) << o.err;
    merge.push_back(shard.string());
  }
  const fs::path merged = dir_ / "merged.json";
  merge.insert(merge.end(), {"-o", merged.string()});
  const Outcome joined = run(merge);
  ASSERT_EQ(joined.code, 0) << joined.err;
  EXPECT_EQ(contents(merged), contents(db));
}

TEST_F(SunCli, NoSunPathOrAThresholdWithoutTheFormatIsAnError) {
  const fs::path scene = write("lamp.json", R"({"format": "shadowgen-scene/1",
      "polygons": [{"id": "g", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
      "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 3]}]})");
  const Outcome none = run({"report", scene.string(), "--format", "sun-hours"});
  EXPECT_EQ(none.code, 1);
  EXPECT_EQ(none.err, "shadowgen: " + scene.string() +
                          ": has no sun path (a `sun` light with from, to and step_min) to "
                          "report sun hours of\n");
  EXPECT_EQ(run({"report", scene.string(), "--threshold", "2"}).code, 2);
  EXPECT_EQ(run({"report", scene.string(), "--format", "sun-hours", "--threshold", "-1"}).code, 2);
}

// A database keeps the scene it was generated from as its faces' source_file; a report on
// it names the database given, not that scene.
TEST_F(SunCli, ReportsOnADatabaseNameTheDatabaseNotItsScene) {
  const fs::path scene = write("lamp.json", R"({"format": "shadowgen-scene/1",
      "polygons": [{"id": "g", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
      "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 3]}]})");
  const fs::path db = dir_ / "lamp.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const std::string no_path =
      "shadowgen: " + db.string() + ": has no sun path (a `sun` light with from, to and step_min) ";
  const Outcome shading = run({"report", db.string(), "--format", "energyplus"});
  EXPECT_EQ(shading.code, 1);
  EXPECT_EQ(shading.err, no_path + "to report a shading schedule of\n");
  const Outcome hours = run({"report", db.string(), "--format", "sun-hours"});
  EXPECT_EQ(hours.code, 1);
  EXPECT_EQ(hours.err, no_path + "to report sun hours of\n");
}

// What an --areas-only database cannot give (sun-hours regions) is said of that database,
// as the user named it, never of the scene it was generated from.
TEST_F(SunCli, WhatAnAreasOnlyDatabaseCannotGiveNamesThatDatabase) {
  const fs::path scene = write("yard.json", kYard);
  fs::create_directories(dir_ / "out");
  const fs::path db = dir_ / "out" / "areas.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string(), "--areas-only"}).code, 0);
  const std::string summed = "shadowgen: " + db.string() +
                             ": sun path 'march21' was summed into lit areas alone (generate "
                             "--areas-only), without the sun-hours regions ";
  const Outcome report = run({"report", db.string(), "--format", "sun-hours"});
  EXPECT_EQ(report.code, 1);
  EXPECT_EQ(report.err, summed + "a sun-hours report needs: generate without --areas-only\n");
  const Outcome exported =
      run({"export", db.string(), "--sun-hours", "march21", "-o", (dir_ / "m.obj").string()});
  EXPECT_EQ(exported.code, 1);
  EXPECT_EQ(exported.err,
            summed + "an export by hour bands needs: generate without --areas-only\n");
  fs::remove(scene);  // a map reads the database alone
  const Outcome map = run({"render", db.string(), "--sun-hours", "march21", "--eye", "5,-20,20",
                           "--target", "5,5,0", "-o", (dir_ / "m.svg").string()});
  EXPECT_EQ(map.code, 1);
  EXPECT_EQ(map.err, summed + "a sun-hours map needs: generate without --areas-only\n");
  EXPECT_EQ(files(), std::vector<std::string>{"out"});
}

TEST_F(SunCli, EnergyPlusShadingScheduleFromTheSceneOrItsDatabase) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome from_scene = run({"report", scene.string(), "--format", "energyplus"});
  ASSERT_EQ(from_scene.code, 0) << from_scene.err;
  EXPECT_EQ(from_scene.err, "shadowgen: warning: " + scene.string() +
                                ": sun path 'march21' covers 1 days, from 2026-03-21T06:00 to "
                                "2026-03-21T18:30: EnergyPlus reads Schedule:File:Shading only "
                                "for a whole year (January 1 to December 31 at every time step)\n");
  const Outcome from_db = run({"report", db.string(), "--format", "energyplus"});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, from_scene.out);
  const std::vector<std::string> rows = lines(from_db.out);
  ASSERT_EQ(rows.size(), 1u + 48u);
  EXPECT_EQ(rows[0], "Surface Name,YARD,WALL,");
  EXPECT_EQ(rows[1], " 03/21 00:30,0.00000000,0.00000000,");
  // 12:00 to 12:30: the wall's front faces south, wholly lit; the yard partly shaded.
  const std::vector<std::string> noon = csv_fields(rows[25]);
  ASSERT_EQ(noon.size(), 4u);
  EXPECT_EQ(noon[0], " 03/21 12:30");
  EXPECT_GT(std::stod(noon[1]), 0.5);
  EXPECT_LT(std::stod(noon[1]), 1.0);
  EXPECT_EQ(noon[2], "1.00000000");
}

// The yard with its site from a weather file of 21 March's hours.
TEST_F(SunCli, IrradiationFromTheScenesWeatherFileOrFromADatabaseWithWeather) {
  write("march.epw", joined(epw_lines(3, 21, 1)));
  std::string yard = kYard;
  const std::string site =
      R"("site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},)";
  ASSERT_NE(yard.find(site), std::string::npos);
  yard.replace(yard.find(site), site.size(), R"("weather": "march.epw",)");
  const fs::path scene = write("yard.json", yard);
  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome from_scene = run({"report", scene.string(), "--format", "irradiation"});
  ASSERT_EQ(from_scene.code, 0) << from_scene.err;
  EXPECT_EQ(from_scene.err, "");
  const fs::path epw = dir_ / "march.epw";
  const Outcome from_db =
      run({"report", db.string(), "--format", "irradiation", "--weather", epw.string()});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.out, from_scene.out);
  const std::vector<std::string> rows = lines(from_db.out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0],
            "face_id,sun_path,area,direct_wh,direct_wh_per_area,unshaded_direct_wh_per_area");
  const std::vector<std::string> ground = csv_fields(rows[1]);
  ASSERT_EQ(ground.size(), 6u);
  EXPECT_EQ(ground[0], "yard");
  EXPECT_GT(std::stod(ground[3]), 0.0);
  EXPECT_LT(std::stod(ground[4]), std::stod(ground[5]));  // the wall shades part of it

  const Outcome no_weather = run({"report", db.string(), "--format", "irradiation"});
  EXPECT_EQ(no_weather.code, 1);
  EXPECT_EQ(no_weather.err, "shadowgen: " + db.string() +
                                ": the irradiation report needs a weather file: a scene's "
                                "\"weather\" key, or --weather FILE.epw\n");
  EXPECT_EQ(run({"report", db.string(), "--weather", epw.string()}).code, 2);
  const Outcome onto_weather = run({"report", db.string(), "--format", "irradiation", "--weather",
                                    epw.string(), "-o", epw.string()});
  EXPECT_EQ(onto_weather.code, 2);
  EXPECT_NE(onto_weather.err.find("is the input"), std::string::npos) << onto_weather.err;
  EXPECT_EQ(contents(epw), joined(epw_lines(3, 21, 1)));
}

// --weather naming a device, or a pipe fed without end: refused naming it, the device
// before it is read, the pipe once more than an EPW file can hold has come (about 9.5 MB,
// epw_reader.h), where it was once read on until memory ran out.
TEST_F(SunCli, AWeatherPathThatIsADeviceOrNeverEndsIsRefusedNamingIt) {
  const fs::path scene = write("yard.json", kYard);
  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string()}).code, 0);
  const Outcome zero =
      run({"report", db.string(), "--format", "irradiation", "--weather", "/dev/zero"});
  EXPECT_EQ(zero.code, 1);
  EXPECT_EQ(zero.err, "shadowgen: /dev/zero: is not a regular file (a character device)\n");

  const fs::path fifo = dir_ / "endless.epw";
  ASSERT_EQ(shell("mkfifo " + quoted(fifo.string())), 0);
  // The writer stops when the pipe is closed (SIGPIPE), or after a minute at the latest.
  ASSERT_EQ(shell("(timeout 60 yes > " + quoted(fifo.string()) + " 2> /dev/null &)"), 0);
  const Outcome endless =
      run({"report", db.string(), "--format", "irradiation", "--weather", fifo.string()});
  EXPECT_EQ(endless.code, 1);
  EXPECT_EQ(endless.err, "shadowgen: " + fifo.string() +
                             ": is larger than a weather file can be (more than 9519107 bytes)\n");
}

}  // namespace
}  // namespace shadowgen::test
