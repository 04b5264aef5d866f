// Tests of the scene reader's site and sun lights (shadowgen/scene/scene_reader.h,
// docs/scene-format.md "Site and sun path"): a `sun` entry read as the directional lights
// of its instants, and every mistake named with its file, light and JSON path.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/scene/scene_reader.h"

namespace shadowgen {
namespace {

constexpr const char* kFile = "site.json";

// The Royal Observatory, Greenwich, on GMT.
const std::string kGreenwich =
    R"("site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "elevation_m": 45,
                "utc_offset_h": 0, "north_axis_deg": 0})";

std::string scene(const std::string& site, const std::string& lights) {
  std::string text = R"({"format": "shadowgen-scene/1", "polygons": [])";
  if (!site.empty()) text += ", " + site;
  return text + R"(, "lights": [)" + lights + "]}";
}

ReadResult read(const std::string& text, const ReadOptions& options = {}) {
  return parse_scene(text, kFile, options);
}

const char* const kMarch21 =
    R"({"id": "march21", "type": "sun", "from": "2026-03-21T00:00", "to": "2026-03-21T23:59",
        "step_min": 10})";

// The unit vector toward the sun, from a light's direction (which the reader scales).
glm::dvec3 toward_sun(const Light& light) {
  return -light.direction / std::sqrt(glm::dot(light.direction, light.direction));
}

// ---- Expansion --------------------------------------------------------------------------

// Sunrise at Greenwich on 21 March 2026 is at 06:03 and sunset at 18:13 (GMT): the sun's
// centre is above the horizon from 06:10 to 18:10 of the 10-minute instants, 73 of 144.
TEST(SunPath, IsItsInstantsAboveTheHorizonNamedByTheirTimeInOrder) {
  const ReadResult r = read(scene(kGreenwich, kMarch21));
  EXPECT_TRUE(r.warnings.empty());
  const std::vector<Light>& lights = r.scene.lights;
  ASSERT_EQ(lights.size(), 73u);
  EXPECT_EQ(lights.front().id, "march21@2026-03-21T06:10");
  EXPECT_EQ(lights[36].id, "march21@2026-03-21T12:10");
  EXPECT_EQ(lights.back().id, "march21@2026-03-21T18:10");
  for (const Light& light : lights) {
    EXPECT_EQ(light.type, LightType::kDirectional);
    ASSERT_TRUE(light.sun.has_value());
    EXPECT_EQ(light.sun->sun_id, "march21");
    EXPECT_EQ(light.sun->step_min, 10);
    EXPECT_EQ(light.id, "march21@" + light.sun->time);
    EXPECT_GT(light.sun->elevation_deg, 0.0);
    EXPECT_LT(light.direction.z, 0.0);  // sunlight travels down
  }
  // Morning sun in the east, evening sun in the west.
  EXPECT_NEAR(lights.front().sun->azimuth_deg, 90.4, 0.1);
  EXPECT_NEAR(lights.back().sun->azimuth_deg, 270.9, 0.1);
  EXPECT_GT(toward_sun(lights.front()).x, 0.99);
  EXPECT_LT(toward_sun(lights.back()).x, -0.99);
}

// The sun at noon GMT on 21 March 2026 at Greenwich: azimuth 177.7° (transit is at 12:07),
// elevation 38.87° (90° - 51.48° + δ 0.33°, plus refraction).
TEST(SunLight, WithATimeIsOneLightKeepingItsId) {
  const ReadResult r =
      read(scene(kGreenwich, R"({"id": "noon", "type": "sun", "time": "2026-03-21T12:00"})"));
  ASSERT_EQ(r.scene.lights.size(), 1u);
  const Light& noon = r.scene.lights[0];
  EXPECT_EQ(noon.id, "noon");
  ASSERT_TRUE(noon.sun.has_value());
  EXPECT_EQ(noon.sun->sun_id, "noon");
  EXPECT_EQ(noon.sun->time, "2026-03-21T12:00");
  EXPECT_EQ(noon.sun->step_min, 0);
  EXPECT_NEAR(noon.sun->azimuth_deg, 177.71, 0.01);
  EXPECT_NEAR(noon.sun->elevation_deg, 38.87, 0.01);
  // Toward the sun: south (-y, +y being north), a little east (+x), and up.
  const glm::dvec3 to_sun = toward_sun(noon);
  const double e = noon.sun->elevation_deg * std::numbers::pi / 180.0;
  const double a = noon.sun->azimuth_deg * std::numbers::pi / 180.0;
  EXPECT_NEAR(to_sun.x, std::cos(e) * std::sin(a), 1e-15);
  EXPECT_NEAR(to_sun.y, std::cos(e) * std::cos(a), 1e-15);
  EXPECT_NEAR(to_sun.z, std::sin(e), 1e-15);
  EXPECT_LT(to_sun.y, -0.77);
  // Directions are scaled like every directional light's: largest component in [0.5, 1).
  EXPECT_GE(std::fabs(noon.direction.y), 0.5);
  EXPECT_LT(std::fabs(noon.direction.y), 1.0);
}

// At the 2026 March equinox (14:46 UT) it is morning at 90° W on the equator and the sun
// stands due east: with north at +y the light travels along -x; with the scene's +y turned
// 90° clockwise from north (+y east, +x south) it travels along -y.
TEST(SunLight, NorthAxisTurnsTheSceneUnderTheSky) {
  auto site = [](const char* north) {
    return std::string(R"("site": {"latitude_deg": 0, "longitude_deg": -90, "utc_offset_h": -6,
                                   "north_axis_deg": )") +
           north + "}";
  };
  const std::string equinox = R"({"id": "e", "type": "sun", "time": "2026-03-20T08:46"})";
  const Light plain = read(scene(site("0"), equinox)).scene.lights.at(0);
  const Light turned = read(scene(site("90"), equinox)).scene.lights.at(0);
  EXPECT_NEAR(plain.sun->azimuth_deg, 90.0, 0.01);
  EXPECT_EQ(plain.sun->azimuth_deg, turned.sun->azimuth_deg);
  const double horizontal = std::cos(plain.sun->elevation_deg * std::numbers::pi / 180.0);
  EXPECT_NEAR(toward_sun(plain).x, horizontal, 1e-6);
  EXPECT_NEAR(toward_sun(plain).y, 0.0, 2e-4);
  EXPECT_NEAR(toward_sun(turned).y, horizontal, 1e-6);
  EXPECT_NEAR(toward_sun(turned).x, 0.0, 2e-4);
  EXPECT_EQ(toward_sun(plain).z, toward_sun(turned).z);
}

// One instant written in two time zones is one sun.
TEST(SunLight, TimesAreLocalStandardTimeAtTheOffset) {
  auto site = [](const char* offset) {
    return std::string(R"("site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, )") +
           R"("utc_offset_h": )" + offset + "}";
  };
  const Light gmt =
      read(scene(site("0"), R"({"id": "s", "type": "sun", "time": "2026-06-21T12:00"})"))
          .scene.lights.at(0);
  const Light india =
      read(scene(site("5.5"), R"({"id": "s", "type": "sun", "time": "2026-06-21T17:30:00"})"))
          .scene.lights.at(0);
  EXPECT_EQ(gmt.direction, india.direction);
  EXPECT_EQ(india.sun->time, "2026-06-21T17:30");
}

TEST(SunLight, OtherLightsKeepTheirPlaceAndNoSunInstant) {
  const ReadResult r = read(scene(
      kGreenwich, std::string(R"({"id": "lamp", "type": "point", "position": [0, 0, 3]}, )") +
                      kMarch21 + R"(, {"id": "d", "type": "directional", "direction": [0,0,-1]})"));
  ASSERT_EQ(r.scene.lights.size(), 75u);
  EXPECT_EQ(r.scene.lights.front().id, "lamp");
  EXPECT_FALSE(r.scene.lights.front().sun.has_value());
  EXPECT_EQ(r.scene.lights[1].id, "march21@2026-03-21T06:10");
  EXPECT_EQ(r.scene.lights.back().id, "d");
  EXPECT_FALSE(r.scene.lights.back().sun.has_value());
}

TEST(Site, IsKeptWithItsDefaults) {
  const ReadResult r = read(
      scene(R"("site": {"latitude_deg": -33.9, "longitude_deg": 151.2, "utc_offset_h": 10})", ""));
  ASSERT_TRUE(r.scene.site.has_value());
  EXPECT_EQ(r.scene.site->latitude_deg, -33.9);
  EXPECT_EQ(r.scene.site->longitude_deg, 151.2);
  EXPECT_EQ(r.scene.site->utc_offset_h, 10.0);
  EXPECT_EQ(r.scene.site->elevation_m, 0.0);
  EXPECT_EQ(r.scene.site->north_axis_deg, 0.0);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_FALSE(read(scene("", "")).scene.site.has_value());
}

// ---- Warnings ---------------------------------------------------------------------------

TEST(SunLight, AMisspeltKeyWarnsWithTheKeyMeant) {
  const ReadResult r = read(scene(
      R"("site": {"latitude_deg": 51.4779, "longitude_deg": 0, "utc_offset_h": 0, "north_axis_dg": 5})",
      R"({"id": "noon", "type": "sun", "time": "2026-03-21T12:00", "step_mins": 10})"));
  EXPECT_EQ(r.warnings,
            (std::vector<std::string>{
                std::string(kFile) + ": site: unknown key 'north_axis_dg' (did you mean "
                                     "'north_axis_deg'?)",
                std::string(kFile) + ": light 'noon': lights[0] ('noon'): unknown key 'step_mins' "
                                     "(did you mean 'step_min'?)"}));
}

// The sun down at every step: no light, a warning, and a path all the same (a polar
// night has 0 sun hours, not none).
TEST(SunPath, WithTheSunAlwaysDownIsEmptyAndSaysSo) {
  const ReadResult r = read(
      scene(kGreenwich,
            R"({"id": "night", "type": "sun", "from": "2026-03-21T20:00", "to": "2026-03-21T23:00",
          "step_min": 60})"));
  EXPECT_TRUE(r.scene.lights.empty());
  ASSERT_EQ(r.scene.sun_paths.size(), 1u);
  EXPECT_EQ(r.scene.sun_paths[0].id, "night");
  EXPECT_EQ(r.scene.sun_paths[0].step_min, 60);
  EXPECT_EQ(r.scene.sun_paths[0].from, "2026-03-21T20:00");
  EXPECT_EQ(r.scene.sun_paths[0].to, "2026-03-21T23:00");
  EXPECT_EQ(r.warnings, std::vector<std::string>{
                            std::string(kFile) +
                            ": light 'night': lights[0] ('night'): the sun is below the horizon "
                            "at every instant of the path"});
}

// ---- Errors -----------------------------------------------------------------------------

struct SunError {
  const char* name;
  std::string text;
  std::string problem;  // InputError::problem(), whole
};

void PrintTo(const SunError& c, std::ostream* os) { *os << c.name; }

std::vector<SunError> sun_errors() {
  const std::string noon = R"({"id": "noon", "type": "sun", "time": "2026-03-21T12:00"})";
  auto site = [](const std::string& members) { return R"("site": {)" + members + "}"; };
  const std::string place = R"("latitude_deg": 51.4779, "longitude_deg": 0)";
  auto sun = [&](const std::string& members) {
    return scene(kGreenwich, R"({"id": "p", "type": "sun", )" + members + "}");
  };
  return {
      {"MissingSite", scene("", noon),
       "light 'noon': lights[0] ('noon'): a sun light needs the scene's \"site\" (latitude_deg, "
       "longitude_deg, utc_offset_h) or a \"weather\" file, and it has neither"},
      {"LatitudeOutOfRange",
       scene(site(R"("latitude_deg": 91, "longitude_deg": 0, "utc_offset_h": 0)"), ""),
       "site.latitude_deg: must lie between -90 and 90 degrees"},
      {"LongitudeOutOfRange",
       scene(site(R"("latitude_deg": 10, "longitude_deg": -180.5, "utc_offset_h": 0)"), ""),
       "site.longitude_deg: must lie between -180 and 180 degrees"},
      {"UtcOffsetOutOfRange", scene(site(place + R"(, "utc_offset_h": 15)"), ""),
       "site.utc_offset_h: must lie between -14 and 14 hours"},
      {"MissingUtcOffset", scene(site(place), ""), "site: missing 'utc_offset_h'"},
      // Far above the air whose refraction the sun's position assumes, the parallax took
      // the sun from 62.44 to 89.99997 degrees up.
      {"ElevationAboveTheAtmosphere",
       scene(site(place + R"(, "utc_offset_h": 0, "elevation_m": 1e300)"), noon),
       "site.elevation_m: must lie between -6500000 and 11000 m"},
      {"ElevationBelowTheAlgorithmsRange",
       scene(site(place + R"(, "utc_offset_h": 0, "elevation_m": -7e6)"), noon),
       "site.elevation_m: must lie between -6500000 and 11000 m"},
      {"NorthAxisBeyondATurn",
       scene(site(place + R"(, "utc_offset_h": 0, "north_axis_deg": 1e300)"), noon),
       "site.north_axis_deg: must lie between -360 and 360 degrees"},
      {"SiteNotAnObject", scene(R"("site": [51.5, 0])", ""),
       "site: expected an object, found an array"},
      {"TimeWithoutMinutes", sun(R"("time": "2026-03-21T12")"),
       "light 'p': lights[0] ('p').time: '2026-03-21T12' is not a time 'YYYY-MM-DDTHH:MM' "
       "(seconds ':SS' optional)"},
      {"TimeOnANonexistentDay", sun(R"("time": "2026-02-29T12:00")"),
       "light 'p': lights[0] ('p').time: '2026-02-29T12:00' is not a time 'YYYY-MM-DDTHH:MM' "
       "(seconds ':SS' optional)"},
      {"TimeNotAString", sun(R"("time": 12)"),
       "light 'p': lights[0] ('p').time: expected a string, found a number"},
      {"YearBeyondTheAlgorithm", sun(R"("time": "6001-03-21T12:00")"),
       "light 'p': lights[0] ('p').time: '6001-03-21T12:00' is beyond the year 6000, where the "
       "solar position algorithm ends"},
      {"SunDownAtTheTime", sun(R"("time": "2026-03-21T23:00")"),
       "light 'p': lights[0] ('p').time: the sun is below the horizon at 2026-03-21T23:00 "
       "(apparent elevation -36.10 degrees)"},
      {"ToBeforeFrom",
       sun(R"("from": "2026-03-21T12:00", "to": "2026-03-21T11:59", "step_min": 10)"),
       "light 'p': lights[0] ('p').to: must not be before 'from' (2026-03-21T12:00)"},
      {"StepZero", sun(R"("from": "2026-03-21T00:00", "to": "2026-03-21T23:59", "step_min": 0)"),
       "light 'p': lights[0] ('p').step_min: must be a positive whole number of minutes, not 0"},
      {"StepFractional",
       sun(R"("from": "2026-03-21T00:00", "to": "2026-03-21T23:59", "step_min": 7.5)"),
       "light 'p': lights[0] ('p').step_min: must be a positive whole number of minutes, not 7.5"},
      {"StepNegative",
       sun(R"("from": "2026-03-21T00:00", "to": "2026-03-21T23:59", "step_min": -10)"),
       "light 'p': lights[0] ('p').step_min: must be a positive whole number of minutes, not -10"},
      {"MissingTo", sun(R"("from": "2026-03-21T00:00", "step_min": 10)"),
       "light 'p': lights[0] ('p'): missing 'to'"},
      {"BothForms", sun(R"("time": "2026-03-21T12:00", "step_min": 10)"),
       "light 'p': lights[0] ('p'): give either 'time' or 'from', 'to' and 'step_min', not both"},
      {"NeitherForm", sun(R"("direction": [0, 0, -1])"),
       "light 'p': lights[0] ('p'): a sun light needs 'time', or 'from', 'to' and 'step_min'"},
      {"TooManyInstants",
       sun(R"("from": "2000-01-01T00:00", "to": "2003-01-01T00:00", "step_min": 1)"),
       "light 'p': lights[0] ('p').step_min: the path has 1578241 instants, more than the "
       "1000000 a sun path may have"},
      {"InstantIdTakenByAnotherLight",
       scene(kGreenwich,
             R"({"id": "p@2026-03-21T12:00", "type": "directional", "direction": [0, 0, -1]},
                {"id": "p", "type": "sun", "from": "2026-03-21T11:00", "to": "2026-03-21T13:00",
                 "step_min": 60})"),
       "light 'p': lights[1] ('p').id: duplicate id 'p@2026-03-21T12:00' (already used by "
       "another light)"},
      {"SunIdTakenByAnotherLight",
       scene(kGreenwich,
             R"({"id": "noon", "type": "directional", "direction": [0, 0, -1]}, )" + noon),
       "lights[1].id: duplicate id 'noon' (already used by another light)"},
  };
}

// The InputError reading `text` throws, if any.
std::optional<InputError> error_reading(const std::string& text) {
  try {
    read(text);
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

class SunErrors : public ::testing::TestWithParam<SunError> {};

TEST_P(SunErrors, ThrowInputErrorNamingFileLightPathAndProblem) {
  const std::optional<InputError> e = error_reading(GetParam().text);
  ASSERT_TRUE(e.has_value()) << "no InputError for: " << GetParam().text;
  EXPECT_EQ(e->file(), kFile);
  EXPECT_EQ(e->face_id(), "");
  EXPECT_EQ(e->problem(), GetParam().problem);
}

INSTANTIATE_TEST_SUITE_P(Table, SunErrors, ::testing::ValuesIn(sun_errors()),
                         [](const auto& test) { return std::string(test.param.name); });

TEST(SunErrors, ADuplicateKeyInTheSiteIsAnError) {
  const std::optional<InputError> e = error_reading(scene(
      R"("site": {"latitude_deg": 51, "latitude_deg": 52, "longitude_deg": 0, "utc_offset_h": 0})",
      ""));
  ASSERT_TRUE(e.has_value());
  EXPECT_NE(e->problem().find("the key 'latitude_deg' is given twice"), std::string::npos)
      << e->problem();
}

TEST(SunErrors, AnUnknownKeyIsAnErrorWhenStrict) {
  EXPECT_THROW(
      read(scene(kGreenwich, R"({"id": "n", "type": "sun", "time": "2026-03-21T12:00", "tme": 1})"),
           {.strict = true}),
      InputError);
}

}  // namespace
}  // namespace shadowgen
