// An EnergyPlus model through a scene's meshes[] entry: the same lit areas as the same
// geometry written as plain polygons, both checked against the exact shadow oracle.

#include <gtest/gtest.h>

#include <string>

#include "hsr/area.h"
#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"
#include "tests/shadowgen/shadows/shadow_check.h"
#include "tests/support/temp_folder.h"

namespace shadowgen {
namespace {

// A house turned 90 degrees from true north, so its south wall faces west: a window with an
// overhang and fins, a door at floor level (a hole sharing the wall's lower edge), and a
// neighbouring building's wall on the site (never turned) 6 m west of it.
constexpr std::string_view kHouse = R"(
Version, 24.1;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, Relative, Relative, Relative;
Building, House, 90;
Site:Location, Somewhere, 52.0, 4.4, 1, 0;
Zone, Living;
Wall:Exterior, South, Ext, Living, , 180, 90, 0, 0, 0, 10, 3;
Window, South Window, Glass, South, , 1, 2, 1, 3, 1.5;
Door, South Door, Door, South, 1, 7, 0, 1, 2;
Shading:Overhang, Overhang, South Window, 0.2, 90, 0.5, 0.5, 1;
Shading:Fin, Fin, South Window, 0.1, 0.2, 0.3, 90, 0.5, 0.1, 0.2, 0.3, 90, 0.5;
Shading:Site, Neighbour, 90, 90, -6, -12, 0, 14, 6;
)";

constexpr std::string_view kLights = R"(
  "lights": [ { "id": "afternoon", "type": "directional", "direction": [1, 0.3, -0.8] },
              { "id": "evening", "type": "directional", "direction": [1, -0.5, -0.4] } ] })";

// The same surfaces as plain polygons, their vertices worked out by hand: the house's
// (x, y) is EnergyPlus's (y, -x) of the unturned house, its vertices in EnergyPlus's order.
constexpr std::string_view kPlainPolygons = R"({ "format": "shadowgen-scene/1",
  "polygons": [
    { "id": "South", "outer": [[0,0,3],[0,0,0],[0,-10,0],[0,-10,3]],
      "holes": [ [[0,-2,2.5],[0,-2,1],[0,-5,1],[0,-5,2.5]],
                 [[0,-7,2],[0,-7,0],[0,-8,0],[0,-8,2]] ] },
    { "id": "South Window", "outer": [[0,-2,2.5],[0,-2,1],[0,-5,1],[0,-5,2.5]] },
    { "id": "South Door", "outer": [[0,-7,2],[0,-7,0],[0,-8,0],[0,-8,2]] },
    { "id": "Overhang", "outer": [[-1,-1.5,2.7],[0,-1.5,2.7],[0,-5.5,2.7],[-1,-5.5,2.7]] },
    { "id": "Fin Left", "outer": [[0,-1.9,2.7],[0,-1.9,0.7],[-0.5,-1.9,0.7],[-0.5,-1.9,2.7]] },
    { "id": "Fin Right", "outer": [[0,-5.1,2.7],[0,-5.1,0.7],[-0.5,-5.1,0.7],[-0.5,-5.1,2.7]] },
    { "id": "Neighbour", "outer": [[-6,-12,6],[-6,-12,0],[-6,2,0],[-6,2,6]] } ],)";

TEST(EnergyPlusScene, ModelGivesTheLitAreasOfTheSameGeometryAsPolygons) {
  const test::TempFolder folder("shadowgen-energyplus-scene");
  folder.write("house.idf", std::string(kHouse));
  const std::filesystem::path model_scene = folder.write("model.json",
                                                         R"({ "format": "shadowgen-scene/1",
  "meshes": [ { "id": "house", "file": "house.idf" } ],)" + std::string(kLights));
  const std::filesystem::path plain_scene =
      folder.write("plain.json", std::string(kPlainPolygons) + std::string(kLights));

  const Scene model = read_scene(model_scene).scene;
  const Scene plain = read_scene(plain_scene).scene;
  ASSERT_EQ(model.faces.size(), plain.faces.size());
  EXPECT_EQ(model.faces[0].id, "house/South");
  EXPECT_EQ(model.faces[0].origin, (FaceOrigin{"energyplus", "South", "Living", "Wall"}));

  const auto model_lit = test::lit_fractions(generate_shadows(model).shadowed);
  const auto plain_lit = test::lit_fractions(generate_shadows(plain).shadowed);
  ASSERT_EQ(model_lit.size(), plain_lit.size());
  bool some_shade = false;
  for (const auto& [key, fraction] : plain_lit) {
    const auto found = model_lit.find({"house/" + key.first, key.second});
    ASSERT_NE(found, model_lit.end()) << key.first;
    EXPECT_NEAR(found->second, fraction, 1e-9) << key.first << " under " << key.second;
    some_shade = some_shade || (fraction > 0.0 && fraction < 1.0);
  }
  EXPECT_TRUE(some_shade);  // the neighbour, overhang and fins cast on the wall and window

  const test::OracleCheck model_check = test::check_against_oracle(model, 1e-9);
  EXPECT_EQ(model_check.failures, 0u) << model_check.report;
  const test::OracleCheck plain_check = test::check_against_oracle(plain, 1e-9);
  EXPECT_EQ(plain_check.failures, 0u) << plain_check.report;
}

TEST(EnergyPlusScene, SiteLocationGivesTheScenesSite) {
  const test::TempFolder folder("shadowgen-energyplus-scene");
  folder.write("house.idf", std::string(kHouse));
  const Scene scene = read_scene(folder.write("model.json", R"({ "format": "shadowgen-scene/1",
  "meshes": [ { "id": "house", "file": "house.idf" } ],)" + std::string(kLights)))
                          .scene;
  ASSERT_TRUE(scene.site.has_value());
  EXPECT_EQ(scene.site->latitude_deg, 52.0);
  EXPECT_EQ(scene.site->longitude_deg, 4.4);
  EXPECT_EQ(scene.site->utc_offset_h, 1.0);
}

// The example model reads whole, its openings cut from their walls, and a winter
// afternoon's shadows on it (the neighbour's, the overhangs', the fins') are exact.
TEST(EnergyPlusScene, TheExampleOfficesAreExactUnderAWinterAfternoon) {
  Scene scene =
      read_scene(std::filesystem::path(SHADOWGEN_EXAMPLES_DIR) / "energyplus" / "office.json")
          .scene;
  ASSERT_EQ(scene.faces.size(), 23u);
  const auto face = [&](std::string_view id) -> const Face& {
    for (const Face& f : scene.faces) {
      if (f.id == id) return f;
    }
    ADD_FAILURE() << "no face " << id;
    return scene.faces[0];
  };
  EXPECT_EQ(face("office/West Office South Wall").parts[0].holes.size(), 2u);
  // The door at floor level shares the wall's lower edge: the wall is one outline that
  // runs round it, the wall's 4 corners and the door's 4.
  const Face& west_wall = face("office/West Office West Wall");
  ASSERT_EQ(west_wall.parts.size(), 1u);
  EXPECT_TRUE(west_wall.parts[0].holes.empty());
  EXPECT_EQ(west_wall.parts[0].outer.size(), 8u);
  EXPECT_NEAR(hsr::area(west_wall.parts), 6.0 * 3.0 - 1.0 * 2.1, 1e-12);  // net of the door
  EXPECT_EQ(face("office/East Office East Window Fin Left").origin.semantic, "Shading:Zone");
  ASSERT_TRUE(scene.site.has_value());
  EXPECT_EQ(scene.site->latitude_deg, 39.74);

  std::erase_if(scene.lights,
                [](const Light& light) { return light.id != "year@2026-01-15T13:00"; });
  ASSERT_EQ(scene.lights.size(), 1u);
  // The instant as a light of its own, so that its lit polygons are kept to compare.
  scene.lights[0].sun.reset();
  scene.sun_paths.clear();
  const test::OracleCheck check = test::check_against_oracle(scene, 1e-9);
  EXPECT_EQ(check.failures, 0u) << check.report;
  EXPECT_GT(check.pairs, 0u);
}

}  // namespace
}  // namespace shadowgen
