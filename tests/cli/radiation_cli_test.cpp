// `shadowgen report --format radiation`: direct, diffuse and ground-reflected irradiation
// per face and sun path, end to end, and its option errors.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli/cli_harness.h"
#include "tests/cli/cli_scenes.h"

namespace shadowgen::test {
namespace {

const std::string kYard = kMarchYardScene;

class RadiationCli : public CliFolderTest<> {
 protected:
  RadiationCli() : CliFolderTest("radiation-cli") {}
};

TEST_F(RadiationCli, ReportsEveryComponentFromASceneOrItsDatabase) {
  write("march.epw", march_epw("999"));
  const fs::path scene = write("yard.json", kYard);
  const Outcome report =
      run({"report", scene.string(), "--format", "radiation", "--sky", "reinhart:2"});
  ASSERT_EQ(report.code, 0) << report.err;
  EXPECT_EQ(report.err, "shadowgen: warning: " + scene.string() + ": " +
                            (dir_ / "march.epw").string() +
                            ": the albedo (field 33) is missing (999) in the hours of 5 "
                            "instants; 0.2 is taken there (--albedo sets it)\n");
  const auto rows = csv_rows(report.out);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{
                "face_id", "sun_path", "area", "direct_wh", "diffuse_wh", "ground_wh", "total_wh",
                "direct_wh_per_area", "diffuse_wh_per_area", "ground_wh_per_area",
                "total_wh_per_area", "unshaded_total_wh", "unshaded_direct_wh_per_area",
                "unshaded_diffuse_wh_per_area", "unshaded_total_wh_per_area", "total_ratio"}));
  EXPECT_EQ(rows[1][0], "yard");
  EXPECT_EQ(rows[1][1], "march21");
  EXPECT_EQ(rows[1][5], "0");              // a horizontal face sees no ground
  EXPECT_LT(std::stod(rows[1][15]), 1.0);  // the wall shades the yard
  EXPECT_GT(std::stod(rows[1][15]), 0.5);
  EXPECT_EQ(rows[2][0], "wall");
  // The wall (facing south) sees the ground with view factor 1/2: albedo 0.2 × 500 Wh/m² ×
  // 5 hours × 1/2 per m².
  EXPECT_NEAR(std::stod(rows[2][9]), 0.2 * 500 * 5 * 0.5, 1e-9);

  const fs::path db = dir_ / "yard.shadowed.json";
  ASSERT_EQ(run({"generate", scene.string(), "-o", db.string(), "--areas-only"}).code, 0);
  const std::string epw = (dir_ / "march.epw").string();  // a database does not keep it
  const Outcome from_db =
      run({"report", db.string(), "--format", "radiation", "--sky", "reinhart:2", "--threads", "1",
           "--albedo", "0.2", "--weather", epw});
  ASSERT_EQ(from_db.code, 0) << from_db.err;
  EXPECT_EQ(from_db.err, "");
  EXPECT_EQ(from_db.out, report.out);
  const Outcome snow = run({"report", db.string(), "--format", "radiation", "--sky", "reinhart:2",
                            "--albedo", "0.8", "--weather", epw});
  ASSERT_EQ(snow.code, 0) << snow.err;
  EXPECT_NEAR(std::stod(csv_rows(snow.out)[2][9]), 0.8 * 500 * 5 * 0.5, 1e-9);
}

TEST_F(RadiationCli, BadOptionsAndAMissingWeatherFileAreRefusedSayingWhy) {
  write("march.epw", march_epw("0.2"));
  const fs::path scene = write("yard.json", kYard);
  for (const std::string bad : {"1.5", "-0.1", "nan"}) {
    const Outcome refused =
        run({"report", scene.string(), "--format", "radiation", "--albedo", bad});
    EXPECT_EQ(refused.code, 2) << bad;
    EXPECT_NE(refused.err.find("--albedo"), std::string::npos) << refused.err;
  }
  const Outcome out_of_range =
      run({"report", scene.string(), "--format", "radiation", "--albedo", "1.5"});
  EXPECT_NE(out_of_range.err.find("1.5 must lie between 0 and 1"), std::string::npos)
      << out_of_range.err;
  const Outcome not_radiation =
      run({"report", scene.string(), "--format", "sky", "--albedo", "0.3"});
  EXPECT_EQ(not_radiation.code, 2);
  EXPECT_NE(not_radiation.err.find("--albedo: applies only to --format radiation"),
            std::string::npos)
      << not_radiation.err;
  const Outcome sampled =
      run({"report", scene.string(), "--format", "radiation", "--method", "rays"});
  EXPECT_EQ(sampled.code, 2);
  EXPECT_NE(sampled.err.find("--format radiation takes the exact lit areas of every sky patch"),
            std::string::npos)
      << sampled.err;

  std::string no_weather = kYard;
  no_weather.replace(no_weather.find(R"("weather": "march.epw",)"), 23,
                     R"("site": {"latitude_deg": 51.5, "longitude_deg": 0, "utc_offset_h": 0},)");
  const fs::path bare = write("bare.json", no_weather);
  const Outcome missing =
      run({"report", bare.string(), "--format", "radiation", "--sky", "tregenza"});
  EXPECT_EQ(missing.code, 1);
  EXPECT_EQ(missing.err, "shadowgen: " + bare.string() +
                             ": the radiation report needs a weather file: a scene's \"weather\" "
                             "key, or --weather FILE.epw\n");
}

}  // namespace
}  // namespace shadowgen::test
