// Tests of shadowgen/output/sun_instants.h: one CSV row per sun instant, ids quoted and
// guarded as in the report, directions of unit length, other lights left out.

#include "shadowgen/output/sun_instants.h"

#include <gtest/gtest.h>

#include <string>

#include "shadowgen/model/input_error.h"

namespace shadowgen {
namespace {

Light instant(const std::string& sun_id, const std::string& id, glm::dvec3 direction) {
  Light light;
  light.id = id;
  light.direction = direction;
  light.sun = SunInstant{sun_id, "2026-03-21T12:00", 10, 180.0, 38.5};
  return light;
}

TEST(SunInstantsCsv, OneRowPerInstantWithAUnitDirection) {
  Scene scene;
  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  scene.lights = {lamp, instant("day", "day@2026-03-21T12:00", {0.0, 0.75, -0.5})};
  EXPECT_EQ(sun_instants_csv(scene),
            "light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,"
            "direction_z\n"
            "day,day@2026-03-21T12:00,2026-03-21T12:00,10,180,38.5,0,0.83205029433784372,"
            "-0.55470019622522915\n");
}

TEST(SunInstantsCsv, IdsAreQuotedAndGuardedAsInTheReport) {
  Scene scene;
  scene.lights = {instant("=a,b", "=a,b@2026-03-21T12:00", {0.0, 0.0, -1.0})};
  const std::string exact = sun_instants_csv(scene);
  EXPECT_NE(exact.find("\n\"=a,b\",\"=a,b@2026-03-21T12:00\",2026-03-21T12:00,"), std::string::npos)
      << exact;
  const std::string safe = sun_instants_csv(scene, CsvIds::kSpreadsheetSafe);
  EXPECT_NE(safe.find("\n\"'=a,b\",\"'=a,b@2026-03-21T12:00\",2026-03-21T12:00,"),
            std::string::npos)
      << safe;
}

TEST(SunInstantsCsv, ASceneWithoutSunLightsIsAnErrorNamingIt) {
  Scene scene;
  scene.file = "lamp.json";
  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  scene.lights = {lamp};
  try {
    sun_instants_csv(scene);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "lamp.json: has no sun lights (a light of type \"sun\", at a time or from, to "
                 "and step_min) to list the instants of");
  }
  // A path with the sun down at every step is a sun light without instants: the header.
  scene.sun_paths = {SunPathSpan{"night", 60, "2026-12-21T00:00", "2026-12-21T23:00"}};
  EXPECT_EQ(sun_instants_csv(scene),
            "light,instant,time,step_min,azimuth_deg,elevation_deg,direction_x,direction_y,"
            "direction_z\n");
}

}  // namespace
}  // namespace shadowgen
