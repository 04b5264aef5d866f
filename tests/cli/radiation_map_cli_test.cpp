// `shadowgen render --radiation`: each visible face whole in the colour of its total
// irradiation over a sun path, the value `report --format radiation` gives it, and the
// option errors.

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "shadowgen/view/radiation_bands.h"
#include "tests/cli/cli_harness.h"
#include "tests/shadowgen/weather/epw_text.h"

namespace shadowgen::test {
namespace {

// An open horizontal face off to the side, and a horizontal face under a wide canopy 1 m above it,
// under the sun of 21 March from 10:00 to 14:00 at the weather file's site.
const std::string kCanopy = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "open", "outer": [[55,0,0],[59,0,0],[59,4,0],[55,4,0]]},
    {"id": "under", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]},
    {"id": "canopy", "outer": [[-50,-50,1],[50,-50,1],[50,50,1],[-50,50,1]]}
  ],
  "weather": "march.epw",
  "lights": [{"id": "march21", "type": "sun", "from": "2026-03-21T10:00",
              "to": "2026-03-21T14:00", "step_min": 60}]
})";

// 21 March, every hour 400 Wh/m² direct normal and nothing else (no diffuse, no global
// horizontal for the ground to reflect): each face's total is its direct part alone.
std::string direct_only_epw() {
  std::vector<std::string> lines = epw_header();
  for (int h = 1; h <= 24; ++h) lines.push_back(epw_row(3, 21, h, "0", "400", "0", "0.2"));
  return joined(lines);
}

// "#rrggbb" of an sRGB colour, 8 bits a channel as round(255 v), as the SVG writes it.
std::string hex(const glm::dvec3& colour) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<int>(colour.r * 255.0 + 0.5),
                static_cast<int>(colour.g * 255.0 + 0.5), static_cast<int>(colour.b * 255.0 + 0.5));
  return text;
}

class RadiationMapCli : public CliFolderTest<> {
 protected:
  RadiationMapCli() : CliFolderTest("radiation-map-cli") {}

  // The database of kCanopy and its weather file beside it.
  fs::path database() {
    write("march.epw", direct_only_epw());
    const fs::path scene = write("canopy.json", kCanopy);
    const fs::path db = dir_ / "canopy.shadowed.json";
    EXPECT_EQ(run({"generate", scene.string(), "-o", db.string(), "--quiet"}).code, 0);
    return db;
  }
};

TEST_F(RadiationMapCli, EachFaceIsTheRampsColourOfItsTotalAsTheReportGivesIt) {
  const fs::path db = database();
  const std::string epw = (dir_ / "march.epw").string();
  const Outcome report = run(
      {"report", db.string(), "--format", "radiation", "--sky", "reinhart:2", "--weather", epw});
  ASSERT_EQ(report.code, 0) << report.err;
  std::map<std::string, double> kwh_per_m2;  // total_wh_per_area / 1000, by face
  for (const auto& row : csv_rows(report.out)) {
    if (row[0] != "face_id") kwh_per_m2[row[0]] = std::stod(row[10]) / 1000.0;
  }
  ASSERT_EQ(kwh_per_m2.size(), 3u);

  // By hand: an open horizontal face gets 400 Wh/m² × cos(zenith) each hour, the sun's
  // −direction_z, and the face under the canopy no direct light at all.
  const Outcome sun = run({"sun", (dir_ / "canopy.json").string()});
  ASSERT_EQ(sun.code, 0) << sun.err;
  double open_wh = 0.0;
  for (const auto& row : csv_rows(sun.out)) {
    if (row[0] != "light") open_wh += 400.0 * -std::stod(row[8]);
  }
  EXPECT_NEAR(kwh_per_m2["open"], open_wh / 1000.0, 1e-12);
  EXPECT_NEAR(kwh_per_m2["canopy"], open_wh / 1000.0, 1e-12);
  EXPECT_EQ(kwh_per_m2["under"], 0.0);

  const fs::path svg = dir_ / "map.svg";
  const Outcome render =
      run({"render", db.string(), "--eye", "5,-120,80", "--target", "5,0,0", "--radiation",
           "march21", "--weather", epw, "--sky", "reinhart:2", "--pieces", "-o", svg.string()});
  ASSERT_EQ(render.code, 0) << render.err;
  const std::string text = contents(svg);
  const RadiationBands bands = radiation_bands("march21", kwh_per_m2["open"]);
  const std::regex piece(
      R"re(fill="(#[0-9a-f]{6})" fill-rule="evenodd" data-face="([a-z]+)" data-kwh-per-m2="([^"]+)")re");
  std::map<std::string, int> pieces;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), piece);
       it != std::sregex_iterator(); ++it) {
    const std::string face = (*it)[2];
    ++pieces[face];
    EXPECT_EQ(std::stod((*it)[3]), kwh_per_m2[face]) << face;
    EXPECT_EQ((*it)[1], hex(bands.bands[bands.band_of(kwh_per_m2[face])].colour)) << face;
  }
  EXPECT_GT(pieces["open"], 0);
  EXPECT_GT(pieces["canopy"], 0);
  EXPECT_EQ(pieces["under"], 0);  // hidden by the canopy, as render hides it
  // The ramp's ends: nothing is the first band's darkest colour, the most the last band's.
  EXPECT_EQ(bands.band_of(kwh_per_m2["under"]), 0u);
  EXPECT_EQ(bands.band_of(kwh_per_m2["open"]), bands.bands.size() - 1);
  EXPECT_NE(text.find("data-legend=\"radiation\""), std::string::npos);
  EXPECT_NE(text.find(">Irradiation, kWh/m²: march21</text>"), std::string::npos);
  EXPECT_NE(text.find(">" + bands.bands.back().label + "</text>"), std::string::npos);
}

TEST_F(RadiationMapCli, OptionErrorsAreUsageErrorsSayingWhatIsWrong) {
  const fs::path db = database();
  const std::string epw = (dir_ / "march.epw").string();
  const fs::path svg = dir_ / "map.svg";
  const std::vector<std::string> camera = {"render",   db.string(), "--eye", "5,-120,80",
                                           "--target", "5,0,0",     "-o",    svg.string()};
  const auto with = [&camera](std::vector<std::string> more) {
    std::vector<std::string> args = camera;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  const Outcome no_weather = run(with({"--radiation", "march21"}));
  EXPECT_EQ(no_weather.code, 2);
  EXPECT_EQ(no_weather.err,
            "shadowgen: --radiation requires --weather\nRun with --help for more information.\n");
  const Outcome both =
      run(with({"--radiation", "march21", "--weather", epw, "--sun-hours", "march21"}));
  EXPECT_EQ(both.code, 2);
  EXPECT_EQ(both.err,
            "shadowgen: --sun-hours excludes --radiation\nRun with --help for more information.\n");
  const Outcome weather_alone = run(with({"--weather", epw}));
  EXPECT_EQ(weather_alone.code, 2);
  EXPECT_EQ(weather_alone.err,
            "shadowgen: --weather requires --radiation\nRun with --help for more information.\n");
  const Outcome no_path = run(with({"--radiation", "june21", "--weather", epw}));
  EXPECT_EQ(no_path.code, 1);
  EXPECT_EQ(no_path.err, "shadowgen: " + db.string() +
                             ": has no sun path 'june21' (its sun paths: 'march21')\n");
  EXPECT_FALSE(fs::exists(svg));
}

}  // namespace
}  // namespace shadowgen::test
