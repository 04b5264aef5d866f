// The scene's site from whoever gives its keys (shadowgen/scene/detail/site_entry.h): the
// scene's own keys first, then model files in entry order, then the weather file.

#include "shadowgen/scene/detail/site_entry.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"

namespace shadowgen::scene::detail {
namespace {

SourceSite keys(std::optional<double> lat, std::optional<double> lon, std::optional<double> utc,
                std::string from) {
  SourceSite site;
  site.latitude_deg = lat;
  site.longitude_deg = lon;
  site.utc_offset_h = utc;
  site.from = std::move(from);
  return site;
}

TEST(SiteEntry, EachKeyFromTheFirstThatGivesIt) {
  SourceSite scene = keys(std::nullopt, std::nullopt, 1.0, "the scene's site");
  SourceSite model = keys(52.1, 5.4, std::nullopt, "EPSG:7415 through PROJ at (155000, 463000)");
  model.north_axis_deg = -0.5;
  model.elevation_m = 3.0;
  SourceSite weather = keys(40.0, -3.0, 2.0, "the weather file's LOCATION");
  weather.elevation_m = 600.0;
  const MergedSite merged =
      merge_site({{scene, "s.json"}, {model, "d.city.json"}, {weather, "w.epw", true}});
  ASSERT_TRUE(merged.site);
  EXPECT_EQ(merged.site->latitude_deg, 52.1);
  EXPECT_EQ(merged.site->longitude_deg, 5.4);
  EXPECT_EQ(merged.site->utc_offset_h, 1.0);
  EXPECT_EQ(merged.site->elevation_m, 3.0);
  EXPECT_EQ(merged.site->north_axis_deg, -0.5);
  EXPECT_TRUE(merged.incomplete.empty());
}

TEST(SiteEntry, TheWeatherFileGivesAWholeSiteOrNothing) {
  SourceSite weather = keys(40.0, -3.0, 2.0, "the weather file's LOCATION");
  weather.elevation_m = 600.0;
  const SiteGiver from_weather{weather, "w.epw", true};
  // Alone, or after givers of elevation and north axis alone: the weather file's place.
  SourceSite turned;
  turned.north_axis_deg = 30.0;
  turned.from = "the scene's site";
  const MergedSite placed = merge_site({{turned, "s.json"}, from_weather});
  ASSERT_TRUE(placed.site);
  EXPECT_EQ(placed.site->latitude_deg, 40.0);
  EXPECT_EQ(placed.site->elevation_m, 600.0);
  EXPECT_EQ(placed.site->north_axis_deg, 30.0);
  // After a giver of any of latitude, longitude and offset: none of its keys.
  const MergedSite elsewhere = merge_site(
      {{keys(std::nullopt, std::nullopt, 1.0, "the scene's site"), "s.json"}, from_weather});
  EXPECT_FALSE(elsewhere.site);
  EXPECT_EQ(elsewhere.incomplete, "missing 'latitude_deg'");
}

TEST(SiteEntry, DefaultsForElevationAndNorthAxis) {
  const MergedSite merged = merge_site({{keys(10.0, 20.0, 3.0, "the scene's site"), "s.json"}});
  ASSERT_TRUE(merged.site);
  EXPECT_EQ(merged.site->elevation_m, 0.0);
  EXPECT_EQ(merged.site->north_axis_deg, 0.0);
}

TEST(SiteEntry, IncompleteSaysWhatCameFromWhere) {
  const MergedSite from_model = merge_site(
      {{keys(52.1, 5.4, std::nullopt, "EPSG:7415 through PROJ at (155000, 463000)"), "d.json"}});
  EXPECT_FALSE(from_model.site);
  EXPECT_EQ(from_model.incomplete,
            "missing 'utc_offset_h' (latitude_deg from EPSG:7415 through PROJ at (155000, "
            "463000); longitude_deg from EPSG:7415 through PROJ at (155000, 463000); no file "
            "gives utc_offset_h)");
  // The scene's keys alone: said as the scene's site says a missing key.
  const MergedSite from_scene =
      merge_site({{keys(52.1, std::nullopt, 1.0, "the scene's site"), "s.json"}});
  EXPECT_EQ(from_scene.incomplete, "missing 'longitude_deg'");
  EXPECT_TRUE(merge_site({}).incomplete.empty());
  EXPECT_FALSE(merge_site({}).site);
}

TEST(SiteEntry, AModelValueOutOfRangeNamesTheFileAndWhereItCameFrom) {
  try {
    merge_site({{keys(95.0, 5.0, 1.0, "Site:Location 'Nowhere'"), "house.idf"}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "house.idf: Site:Location 'Nowhere': latitude_deg: must lie between -90 and 90 "
              "degrees");
  }
}

}  // namespace
}  // namespace shadowgen::scene::detail
