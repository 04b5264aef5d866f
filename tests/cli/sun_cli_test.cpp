// End-to-end tests of `shadowgen sun`: the built executable lists a scene's sun instants
// as CSV, on standard output or into a file; bad input exits 1 with one message and
// leaves no file behind.

#include <gtest/gtest.h>

#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"

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

TEST_F(SunCli, ASceneWithoutSunsGivesTheHeaderAlone) {
  const fs::path scene = write("lamp.json", R"({"format": "shadowgen-scene/1", "polygons": [],
                       "lights": [{"id": "lamp", "type": "point", "position": [0, 0, 3]}]})");
  const Outcome o = run({"sun", scene.string()});
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(o.out, std::string(kHeader) + "\n");
}

TEST_F(SunCli, ThreadsIsNotAnOptionOfIt) {
  const fs::path scene = write("greenwich.json", kScene);
  EXPECT_EQ(run({"sun", scene.string(), "--threads", "2"}).code, 2);
}

}  // namespace
}  // namespace shadowgen::test
