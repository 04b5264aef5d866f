// Tests of a scene's weather file (shadowgen/scene/detail/weather_entry.h, docs/scene-format.md
// "Weather file"): read relative to the scene, giving the site when the scene has none,
// second to a site the scene gives, and named when it is not there or not right.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/scene/scene_reader.h"
#include "tests/shadowgen/weather/epw_text.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

namespace fs = std::filesystem;

const test::TempFolder& folder() {
  static const test::TempFolder folder("shadowgen-weather-entry");
  return folder;
}

// A scene in the folder, with `members` after its polygons; the synthetic weather file
// (London Gatwick, January 1 to 3) is at climate/gatwick.epw beside it.
fs::path scene_file(const std::string& members) {
  static const fs::path weather =
      folder().write("climate/gatwick.epw", test::joined(test::epw_lines()));
  (void)weather;
  return folder().write("scene.json",
                        R"({"format": "shadowgen-scene/1", "polygons": [], )" + members + "}");
}

const char* const kNoon =
    R"("lights": [{"id": "noon", "type": "sun", "time": "2026-01-02T12:00"}])";

TEST(SceneWeather, IsReadRelativeToTheScene) {
  const ReadResult r = read_scene(scene_file(R"("weather": "climate/gatwick.epw")"));
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_TRUE(r.scene.weather.has_value());
  EXPECT_EQ(r.scene.weather->file, (folder().path() / "climate" / "gatwick.epw").string());
  EXPECT_EQ(r.scene.weather->city, "London Gatwick");
  EXPECT_EQ(r.scene.weather->hours.size(), 72u);
}

// Every file a scene is read from is listed (Scene::files), so that no run writes over
// one: the scene, its mesh files and its weather file, in that order.
TEST(SceneWeather, IsAmongTheFilesTheSceneIsReadFrom) {
  folder().write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const fs::path scene =
      scene_file(R"("meshes": [{"id": "m", "file": "tri.obj"}], "weather": "climate/gatwick.epw")");
  const ReadResult r = read_scene(scene);
  EXPECT_EQ(r.scene.files,
            (std::vector<std::string>{scene.string(), (folder().path() / "tri.obj").string(),
                                      (folder().path() / "climate" / "gatwick.epw").string()}));
}

TEST(SceneWeather, GivesTheSiteWhenTheSceneHasNone) {
  const ReadResult r =
      read_scene(scene_file(R"("weather": "climate/gatwick.epw", )" + std::string(kNoon)));
  ASSERT_TRUE(r.scene.site.has_value());
  EXPECT_EQ(r.scene.site->latitude_deg, 51.15);
  EXPECT_EQ(r.scene.site->longitude_deg, -0.18);
  EXPECT_EQ(r.scene.site->utc_offset_h, 0.0);
  EXPECT_EQ(r.scene.site->elevation_m, 62.0);
  EXPECT_EQ(r.scene.site->north_axis_deg, 0.0);
  // The sun light is placed from it: low in the south at noon in January.
  ASSERT_EQ(r.scene.lights.size(), 1u);
  ASSERT_TRUE(r.scene.lights[0].sun.has_value());
  EXPECT_NEAR(r.scene.lights[0].sun->azimuth_deg, 180.0, 2.0);
  EXPECT_NEAR(r.scene.lights[0].sun->elevation_deg, 16.0, 1.0);
}

// The scene's own site wins (it may turn the scene by north_axis_deg, which a weather file
// cannot); within 0.1° of the file's LOCATION and on its time zone, without a word.
TEST(SceneWeather, TheScenesSiteWins) {
  const ReadResult r = read_scene(scene_file(
      R"("weather": "climate/gatwick.epw", "site": {"latitude_deg": 51.2, "longitude_deg": -0.1,
         "utc_offset_h": 0, "north_axis_deg": 30})"));
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_TRUE(r.scene.site.has_value());
  EXPECT_EQ(r.scene.site->latitude_deg, 51.2);
  EXPECT_EQ(r.scene.site->north_axis_deg, 30.0);
  EXPECT_EQ(r.scene.site->elevation_m, 0.0);
  EXPECT_TRUE(r.scene.weather.has_value());
}

TEST(SceneWeather, ASiteFarFromTheWeatherFileIsKeptWithAWarning) {
  const fs::path scene = scene_file(
      R"("site": {"latitude_deg": 48.85, "longitude_deg": 2.35, "utc_offset_h": 1},
         "weather": "climate/gatwick.epw")");
  const ReadResult r = read_scene(scene);
  EXPECT_EQ(r.scene.site->latitude_deg, 48.85);
  EXPECT_EQ(r.warnings,
            std::vector<std::string>{scene.string() + ": site: differs from the LOCATION of " +
                                     "weather file '" +
                                     (folder().path() / "climate" / "gatwick.epw").string() +
                                     "' (latitude 51.15, longitude -0.18, time zone 0); the "
                                     "site is used"});
}

std::string error_of(const fs::path& scene) {
  try {
    (void)read_scene(scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SceneWeather, AMissingFileIsAnErrorNamingIt) {
  const fs::path scene = scene_file(R"("weather": "climate/absent.epw")");
  EXPECT_EQ(error_of(scene), scene.string() +
                                 ": weather: weather file 'climate/absent.epw' not found (looked "
                                 "for '" +
                                 (folder().path() / "climate" / "absent.epw").string() + "')");
}

// A folder or a device is there, but is no weather file: said so, not "not found".
TEST(SceneWeather, AFolderOrADeviceIsAnErrorSayingWhatItIs) {
  const fs::path scene = scene_file(R"("weather": "climate")");
  EXPECT_EQ(error_of(scene), scene.string() +
                                 ": weather: weather file 'climate' is a folder, not a file "
                                 "(looked for '" +
                                 (folder().path() / "climate").string() + "')");
  EXPECT_EQ(error_of(scene_file(R"("weather": "/dev/zero")")),
            scene.string() +
                ": weather: weather file '/dev/zero' is not a regular file (a character device) "
                "(looked for '/dev/zero')");
}

TEST(SceneWeather, TheFilesOwnErrorsNameItAndTheLine) {
  const fs::path bad = folder().write("bad.epw", "LOCATION,X,,GBR,IWEC,037760,95,0,0,0\n");
  EXPECT_EQ(error_of(scene_file(R"("weather": "bad.epw")")),
            bad.string() + ": line 1: latitude 95 must lie between -90 and 90 degrees");
}

TEST(SceneWeather, MustBeAString) {
  const fs::path scene = scene_file(R"("weather": 3)");
  EXPECT_EQ(error_of(scene), scene.string() + ": weather: expected a string, found a number");
}

}  // namespace
}  // namespace shadowgen
