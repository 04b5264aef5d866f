// The forms an EnergyPlus model comes in: IDF of 8.9 (Shading Control Name in the
// fenestration objects, no Space Name), of 9.6 on (Space Name, no Shading Control Name),
// epJSON; comments, objects over many lines, class names in any case, unknown objects.

#include <gtest/gtest.h>

#include <algorithm>

#include "energyplus_models.h"

namespace shadowgen::energyplus::testing {
namespace {

constexpr std::string_view kVersion89 = R"(
!- An 8.9 file: no Space Name; windows still name their shading control.
VERSION,8.9;
GlobalGeometryRules,UpperLeftCorner,Counterclockwise,Relative;
Zone,Z1,0,1,2,0;
BuildingSurface:Detailed,South,Wall,Ext,Z1,Outdoors,,SunExposed,WindExposed,0.5,4,
  0,0,3,0,0,0,10,0,0,10,0,3;
FenestrationSurface:Detailed,Window 1,Window,Glass,South,,autocalculate,Blinds,,1,4,
  1,0,2,1,0,1,3,0,1,3,0,2;
Window,Window 2,Glass,South,Blinds,,1,5,1,2,1;
GlazedDoor,Glass Door,Glass,South,Blinds,,1,8,0,1,2.1;
Wall:Exterior,East,Ext,Z1,90,90,10,0,0,6,3;
)";

constexpr std::string_view kVersion96 = R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, Relative;
Zone, Z1, 0, 1, 2, 0;
BuildingSurface:Detailed, South, Wall, Ext, Z1, Space 1, Outdoors, , SunExposed, WindExposed,
  0.5, 4,  0, 0, 3,  0, 0, 0,  10, 0, 0,  10, 0, 3;
FenestrationSurface:Detailed, Window 1, Window, Glass, South, , autocalculate, , 1, 4,
  1, 0, 2,  1, 0, 1,  3, 0, 1,  3, 0, 2;
Window, Window 2, Glass, South, , 1, 5, 1, 2, 1;
GlazedDoor, Glass Door, Glass, South, , 1, 8, 0, 1, 2.1;
Wall:Exterior, East, Ext, Z1, Space 1, 90, 90, 10, 0, 0, 6, 3;
)";

void expect_same_faces(const SourceModel& a, const SourceModel& b) {
  ASSERT_EQ(a.faces.size(), b.faces.size());
  for (const SourceFace& face : a.faces) {
    const SourceFace& other = face_named(b, face.id);
    EXPECT_EQ(face.polygon.outer, other.polygon.outer) << face.id;
    EXPECT_EQ(face.polygon.holes, other.polygon.holes) << face.id;
    EXPECT_EQ(face.origin, other.origin) << face.id;
    EXPECT_EQ(face.vertex_rounding, other.vertex_rounding) << face.id;
  }
}

TEST(EnergyPlusFormats, Version89AndVersion96FieldsGiveTheSameFaces) {
  const SourceModel old_model = read_idf(kVersion89);
  const SourceModel new_model = read_idf(kVersion96);
  expect_same_faces(old_model, new_model);
  // The zone's origin (1, 2, 0) moved everything; the openings are holes of the wall.
  expect_loop(face_named(old_model, "Window 2").polygon.outer,
              {{6, 2, 2}, {6, 2, 1}, {8, 2, 1}, {8, 2, 2}});
  expect_loop(face_named(old_model, "East").polygon.outer,
              {{11, 2, 3}, {11, 2, 0}, {11, 8, 0}, {11, 8, 3}});
  EXPECT_EQ(face_named(old_model, "South").polygon.holes.size(), 3u);
  EXPECT_NEAR(net_area(face_named(old_model, "South")), 30 - 2 - 2 - 2.1, 1e-12);
  EXPECT_EQ(face_named(old_model, "Glass Door").origin.semantic, "GlassDoor");
}

// The 9.6 model above as EnergyPlus's converter writes it in epJSON.
constexpr std::string_view kEpJson = R"({
  "Version": {"Version 1": {"version_identifier": "9.6", "idf_order": 1}},
  "GlobalGeometryRules": {"GlobalGeometryRules 1": {"starting_vertex_position": "UpperLeftCorner",
      "vertex_entry_direction": "Counterclockwise", "coordinate_system": "Relative",
      "idf_order": 2}},
  "Zone": {"Z1": {"direction_of_relative_north": 0, "x_origin": 1, "y_origin": 2,
      "z_origin": 0, "idf_order": 3}},
  "BuildingSurface:Detailed": {"South": {"surface_type": "Wall", "construction_name": "Ext",
      "zone_name": "Z1", "space_name": "Space 1", "outside_boundary_condition": "Outdoors",
      "sun_exposure": "SunExposed", "wind_exposure": "WindExposed",
      "view_factor_to_ground": 0.5, "number_of_vertices": 4, "idf_order": 4,
      "vertices": [
        {"vertex_x_coordinate": 0, "vertex_y_coordinate": 0, "vertex_z_coordinate": 3},
        {"vertex_x_coordinate": 0, "vertex_y_coordinate": 0, "vertex_z_coordinate": 0},
        {"vertex_x_coordinate": 10, "vertex_y_coordinate": 0, "vertex_z_coordinate": 0},
        {"vertex_x_coordinate": 10, "vertex_y_coordinate": 0, "vertex_z_coordinate": 3}]}},
  "FenestrationSurface:Detailed": {"Window 1": {"surface_type": "Window",
      "construction_name": "Glass", "building_surface_name": "South",
      "view_factor_to_ground": "Autocalculate", "multiplier": 1, "number_of_vertices": 4,
      "vertex_1_x_coordinate": 1, "vertex_1_y_coordinate": 0, "vertex_1_z_coordinate": 2,
      "vertex_2_x_coordinate": 1, "vertex_2_y_coordinate": 0, "vertex_2_z_coordinate": 1,
      "vertex_3_x_coordinate": 3, "vertex_3_y_coordinate": 0, "vertex_3_z_coordinate": 1,
      "vertex_4_x_coordinate": 3, "vertex_4_y_coordinate": 0, "vertex_4_z_coordinate": 2,
      "idf_order": 5}},
  "Window": {"Window 2": {"construction_name": "Glass", "building_surface_name": "South",
      "multiplier": 1, "starting_x_coordinate": 5, "starting_z_coordinate": 1, "length": 2,
      "height": 1, "idf_order": 6}},
  "GlazedDoor": {"Glass Door": {"construction_name": "Glass", "building_surface_name": "South",
      "multiplier": 1, "starting_x_coordinate": 8, "starting_z_coordinate": 0, "length": 1,
      "height": 2.1, "idf_order": 7}},
  "Wall:Exterior": {"East": {"construction_name": "Ext", "zone_name": "Z1",
      "space_name": "Space 1", "azimuth_angle": 90, "tilt_angle": 90,
      "starting_x_coordinate": 10, "starting_y_coordinate": 0, "starting_z_coordinate": 0,
      "length": 6, "height": 3, "idf_order": 8}},
  "Schedule:Constant": {"Always On": {"hourly_value": 1}}
})";

TEST(EnergyPlusFormats, EpJsonGivesTheFacesOfTheSameIdf) {
  const SourceModel json = parse_energyplus(kEpJson, "model.epJSON", {});
  const SourceModel idf = read_idf(kVersion96);
  expect_same_faces(json, idf);
  // idf_order keeps the IDF's order.
  for (std::size_t i = 0; i < idf.faces.size(); ++i) EXPECT_EQ(json.faces[i].id, idf.faces[i].id);
  EXPECT_TRUE(json.warnings.empty());
}

TEST(EnergyPlusFormats, EpJsonWarnsOfAKeyItsClassDoesNotHave) {
  std::string text(kEpJson);
  text.replace(text.find("\"length\": 6"), 11, "\"lenght\": 6");
  const SourceModel model = parse_energyplus(text, "model.epJSON", {});
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0],
            "model.epJSON: ['Wall:Exterior']['East']: unknown key 'lenght' (did you mean "
            "'length'?)");
}

TEST(EnergyPlusFormats, CommentsCaseAndUnknownObjectsAreReadAsEnergyPlusReadsThem) {
  const SourceModel model = read_idf(R"(
! A comment line; the next objects are over several lines, their class names in any case.
  vErSiOn,
    24.2;    ! a comment after the field
Output:Variable, *, Site Outdoor Air Drybulb Temperature, Hourly;
globalgeometryrules,
  UpperLeftCorner,    !- Starting Vertex Position
  Counterclockwise,   !- Vertex Entry Direction
  World;              !- Coordinate System
SHADING:SITE:DETAILED,
  Tree,               !- Name
  ,                   !- Transmittance Schedule Name
  3,                  !- Number of Vertices
  0, 0, 0,
  1, 0, 0, ! a comment between vertices
  1, 0, 1;
Schedule:Compact, Sched, Fraction, Through: 12/31, For: AllDays, Until: 24:00, 1;
)");
  ASSERT_EQ(model.faces.size(), 1u);
  EXPECT_EQ(model.faces[0].id, "Tree");
  EXPECT_EQ(model.faces[0].line, 10u);
  expect_loop(model.faces[0].polygon.outer, {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}});
}

}  // namespace
}  // namespace shadowgen::energyplus::testing
