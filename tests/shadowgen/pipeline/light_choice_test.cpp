// A run limited to some lights (shadowgen/pipeline/light_choice.h): the lights kept in the
// input's order, their lit polygons exactly those of a run with every light, and an id
// the input lacks refused with the lights it has.

#include "shadowgen/pipeline/light_choice.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shadowgen/model/input_error.h"
#include "shadowgen/output/database.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/hand_scenes.h"

namespace shadowgen {
namespace {

Scene two_lights() { return parse_scene(test::kTwoLights, "two.json", {}).scene; }

std::vector<std::string> light_ids(const Scene& scene) {
  std::vector<std::string> ids;
  for (const Light& light : scene.lights) ids.push_back(light.id);
  return ids;
}

TEST(KeepLights, KeepsTheNamedLightsInTheInputsOrder) {
  Scene scene = two_lights();
  const std::vector<std::string> named = {"slant", "down", "slant"};
  keep_lights(scene, named, "two.json");
  EXPECT_EQ(light_ids(scene), (std::vector<std::string>{"down", "slant"}));
  keep_lights(scene, std::vector<std::string>{"slant"}, "two.json");
  EXPECT_EQ(light_ids(scene), (std::vector<std::string>{"slant"}));
  keep_lights(scene, {}, "two.json");  // none named: all kept
  EXPECT_EQ(light_ids(scene), (std::vector<std::string>{"slant"}));
}

// A sun path's id names all its instants; an instant's own id names it alone.
TEST(KeepLights, ASunPathsIdNamesAllItsInstants) {
  Scene scene = parse_scene(
                    R"({"format": "shadowgen-scene/1", "polygons": [],
                        "site": {"latitude_deg": 51.4779, "longitude_deg": 0, "utc_offset_h": 0},
                        "lights": [
                          {"id": "down", "type": "directional", "direction": [0, 0, -1]},
                          {"id": "day", "type": "sun", "from": "2026-03-21T10:00",
                           "to": "2026-03-21T12:00", "step_min": 60}]})",
                    "sun.json", {})
                    .scene;
  Scene one = scene;
  keep_lights(scene, std::vector<std::string>{"day"}, "sun.json");
  EXPECT_EQ(light_ids(scene),
            (std::vector<std::string>{"day@2026-03-21T10:00", "day@2026-03-21T11:00",
                                      "day@2026-03-21T12:00"}));
  keep_lights(one, std::vector<std::string>{"day@2026-03-21T11:00", "down"}, "sun.json");
  EXPECT_EQ(light_ids(one), (std::vector<std::string>{"down", "day@2026-03-21T11:00"}));
}

// A unit square "g" at a site (`site`: the members of "site") under `lights` (the inside
// of the scene's "lights" array).
Scene unit_square_under(const std::string& site, const std::string& lights) {
  return parse_scene(R"({"format": "shadowgen-scene/1",
                         "polygons": [{"id": "g", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
                         "site": {)" +
                         site + R"(}, "lights": [)" + lights + "]}",
                     "sun.json", {})
      .scene;
}

// An instant named without the rest of its path is a light of its own, as a `sun` entry
// with its id and `time` places one: generated, it makes no sun path, so that nothing
// takes the one instant for the whole path (1 h of sun where the path gives 3, a shading
// schedule with no sun at the other steps). Every instant named is the path again.
TEST(KeepLights, AnInstantNamedWithoutItsPathIsALightOfItsOwn) {
  const Scene scene = unit_square_under(
      R"("latitude_deg": 51.4779, "longitude_deg": 0, "utc_offset_h": 0)",
      R"({"id": "day", "type": "sun", "from": "2026-03-21T10:00", "to": "2026-03-21T12:00",
          "step_min": 60})");
  Scene one = scene;
  keep_lights(one, std::vector<std::string>{"day@2026-03-21T11:00"}, "sun.json");
  ASSERT_EQ(light_ids(one), (std::vector<std::string>{"day@2026-03-21T11:00"}));
  const SunInstant& sun = one.lights[0].sun.value();
  EXPECT_EQ(sun.sun_id, "day@2026-03-21T11:00");
  EXPECT_EQ(sun.time, "2026-03-21T11:00");
  EXPECT_EQ(sun.step_min, 0);
  EXPECT_FALSE(in_sun_path(one.lights[0]));
  const ShadowedScene generated = generate_shadows(one, {}).shadowed;
  EXPECT_TRUE(generated.sun_paths.empty());
  EXPECT_EQ(lit_area(generated.lit()[0][0]), 1.0);  // a light with its lit polygons

  Scene every = scene;
  keep_lights(every,
              std::vector<std::string>{"day@2026-03-21T12:00", "day@2026-03-21T10:00",
                                       "day@2026-03-21T11:00"},
              "sun.json");
  const ShadowedScene path = generate_shadows(every, {}).shadowed;
  ASSERT_EQ(path.sun_paths.size(), 1u);
  EXPECT_EQ(path.sun_paths[0].instants, (std::vector<std::size_t>{0, 1, 2}));
}

// A sun path with the sun down at every step has no instant to name it by: its id keeps
// it, on a scene and on its database, and naming other lights drops it.
TEST(KeepLights, APathWithoutAnInstantIsKeptWhereItsIdIsNamed) {
  const Scene scene = unit_square_under(
      R"("latitude_deg": 69.65, "longitude_deg": 18.96, "utc_offset_h": 1)",
      R"({"id": "dec21", "type": "sun", "from": "2026-12-21T00:00", "to": "2026-12-21T23:00",
          "step_min": 60},
         {"id": "down", "type": "directional", "direction": [0, 0, -1]})");
  ASSERT_EQ(light_ids(scene), (std::vector<std::string>{"down"}));
  const ShadowedScene whole = generate_shadows(scene, {}).shadowed;
  for (const char* id : {"dec21", "down"}) {
    Scene chosen = scene;
    keep_lights(chosen, std::vector<std::string>{id}, "sun.json");
    ShadowedScene from_database = whole;
    keep_lights(from_database, std::vector<std::string>{id}, "night.db.json");
    const bool night = std::string(id) == "dec21";
    EXPECT_EQ(chosen.sun_paths.size(), night ? 1u : 0u) << id;
    EXPECT_EQ(light_ids(chosen), night ? std::vector<std::string>{} : light_ids(scene)) << id;
    EXPECT_EQ(generate_shadows(chosen, {}).shadowed.sun_paths.size(), night ? 1u : 0u) << id;
    EXPECT_EQ(from_database.sun_paths.size(), night ? 1u : 0u) << id;
  }
}

// A comparison of view methods draws a few instants of each sun path, spread evenly
// (ranks ⌊(i + ½)·n / k⌋), every light that is no path's instant, and all of a path no
// longer than k.
TEST(KeepSpreadInstants, KeepsEvenlySpreadInstantsOfEachPathAndEveryOtherLight) {
  const Scene scene = parse_scene(R"({"format": "shadowgen-scene/1", "polygons": [],
                      "site": {"latitude_deg": 51.4779, "longitude_deg": 0, "utc_offset_h": 0},
                      "lights": [
                        {"id": "day", "type": "sun", "from": "2026-03-21T08:00",
                         "to": "2026-03-21T16:00", "step_min": 60},
                        {"id": "noon", "type": "sun", "time": "2026-03-21T12:00"},
                        {"id": "down", "type": "directional", "direction": [0, 0, -1]},
                        {"id": "short", "type": "sun", "from": "2026-06-21T11:00",
                         "to": "2026-06-21T12:00", "step_min": 30}]})",
                                  "suns.json", {})
                          .scene;
  Scene spread = scene;
  // day: 9 instants, 08:00 to 16:00; of 3, ranks ⌊9/6⌋ = 1, ⌊27/6⌋ = 4, ⌊45/6⌋ = 7.
  const std::vector<std::string> kept = keep_spread_instants(spread, 3);
  const std::vector<std::string> expected = {"day@2026-03-21T09:00",   "day@2026-03-21T12:00",
                                             "day@2026-03-21T15:00",   "short@2026-06-21T11:00",
                                             "short@2026-06-21T11:30", "short@2026-06-21T12:00"};
  EXPECT_EQ(kept, expected);
  EXPECT_EQ(light_ids(spread), (std::vector<std::string>{
                                   "day@2026-03-21T09:00", "day@2026-03-21T12:00",
                                   "day@2026-03-21T15:00", "noon", "down", "short@2026-06-21T11:00",
                                   "short@2026-06-21T11:30", "short@2026-06-21T12:00"}));
  Scene none = scene;
  EXPECT_TRUE(keep_spread_instants(none, 0).empty());
  EXPECT_EQ(light_ids(none), (std::vector<std::string>{"noon", "down"}));
}

// Lights are generated independently: one light alone gives, bit for bit, what it gives
// beside the others, and dropping the others from a database gives the same database.
TEST(KeepLights, OneLightAloneIsThatLightOfTheWholeRun) {
  GenerateOptions one_thread;
  one_thread.threads = 1;
  ShadowedScene all = generate_shadows(two_lights(), one_thread).shadowed;
  Scene slant_only = two_lights();
  keep_lights(slant_only, std::vector<std::string>{"slant"}, "two.json");
  const ShadowedScene alone = generate_shadows(slant_only, one_thread).shadowed;
  ASSERT_EQ(alone.lit().size(), 2u);
  ASSERT_EQ(alone.lit()[0].size(), 1u);
  EXPECT_GT(lit_area(alone.lit()[0][0]), 0.0);

  keep_lights(all, std::vector<std::string>{"slant"}, "two.db.json");
  EXPECT_EQ(light_ids(all.scene()), (std::vector<std::string>{"slant"}));
  EXPECT_EQ(database_json(all), database_json(alone));
}

TEST(KeepLights, AnIdTheInputLacksIsRefusedWithTheLightsItHas) {
  Scene scene = two_lights();
  try {
    keep_lights(scene, std::vector<std::string>{"down", "sun"}, "two.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "two.json");
    EXPECT_EQ(e.problem(),
              "--lights names 'sun', which is not a light of it (its lights: 'down', 'slant')");
  }
  EXPECT_EQ(light_ids(scene), (std::vector<std::string>{"down", "slant"})) << "left as it was";

  Scene dark = scene;
  dark.lights.clear();
  try {
    keep_lights(dark, std::vector<std::string>{"sun"}, "dark.json");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "--lights names 'sun', which is not a light of it (it has none)");
  }
}

}  // namespace
}  // namespace shadowgen
