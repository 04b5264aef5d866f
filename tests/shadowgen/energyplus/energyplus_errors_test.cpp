// Bad EnergyPlus input: one line naming the file, the line (IDF), the object's class and
// Name, the field and the problem.

#include <gtest/gtest.h>

#include <string>

#include "energyplus_models.h"

namespace shadowgen::energyplus::testing {
namespace {

constexpr std::string_view kHead = R"(Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Zone, Z1;
)";

std::string with_head(std::string_view body) { return std::string(kHead) + std::string(body); }

TEST(EnergyPlusErrors, MissingBaseSurface) {
  EXPECT_EQ(error_of(with_head("Window, W, Glass, Nowhere, , 1, 0, 0, 1, 1;\n")),
            "model.idf: line 4: Window 'W', Building Surface Name: no base surface (wall, roof, "
            "floor) is named 'Nowhere'");
}

TEST(EnergyPlusErrors, FewerThanThreeVertices) {
  EXPECT_EQ(error_of(with_head("Shading:Site:Detailed, Sliver, , , 0, 0, 0, 1, 0, 0;\n")),
            "model.idf: line 4: Shading:Site:Detailed 'Sliver': 2 vertices: a surface has at "
            "least 3");
}

TEST(EnergyPlusErrors, NumberThatDoesNotRead) {
  EXPECT_EQ(error_of(with_head("Shading:Site:Detailed, S, , 3,\n  0, 0, 0,\n  1, 1.2.3, 0,\n"
                               "  1, 0, 1;\n")),
            "model.idf: line 6: Shading:Site:Detailed 'S', Vertex 2 Y-coordinate: '1.2.3' is "
            "not a number");
}

TEST(EnergyPlusErrors, NumberThatIsNotFinite) {
  EXPECT_EQ(error_of(with_head("Shading:Site, S, 180, 90, inf, 0, 0, 1, 1;\n")),
            "model.idf: line 4: Shading:Site 'S', Starting X Coordinate: 'inf' is not finite");
  EXPECT_EQ(error_of(with_head("Shading:Site, S, 180, 90, 1e999, 0, 0, 1, 1;\n")),
            "model.idf: line 4: Shading:Site 'S', Starting X Coordinate: '1e999' is not a "
            "number");
}

TEST(EnergyPlusErrors, VertexCountThatDoesNotMatch) {
  EXPECT_EQ(error_of(with_head("Shading:Site:Detailed, S, , 4, 0, 0, 0, 1, 0, 0, 1, 0, 1;\n")),
            "model.idf: line 4: Shading:Site:Detailed 'S', Number of Vertices: says 4 "
            "vertices, and 3 are given");
  EXPECT_EQ(error_of(with_head("Shading:Site:Detailed, S, , 3, 0, 0, 0, 1, 0, 0, 1, 0;\n")),
            "model.idf: line 4: Shading:Site:Detailed 'S': 8 vertex coordinates: the vertices "
            "are x, y, z each, so a multiple of 3");
}

TEST(EnergyPlusErrors, VertexCountThatIsNotAWholeNumber) {
  EXPECT_EQ(error_of(with_head("Shading:Site:Detailed, S, , four, 0, 0, 0, 1, 0, 0, 1, 0, 1;\n")),
            "model.idf: line 4: Shading:Site:Detailed 'S', Number of Vertices: 'four' is not a "
            "whole number (nor autocalculate)");
  // 3.0 is the number 3, as EnergyPlus reads it.
  EXPECT_EQ(read_idf(with_head("Shading:Site:Detailed, S, , 3.0, 0, 0, 0, 1, 0, 0, 1, 0, 1;\n"))
                .faces.size(),
            1u);
}

TEST(EnergyPlusErrors, UnknownZone) {
  EXPECT_EQ(error_of(with_head("Wall:Exterior, W, Ext, Z9, , 180, 90, 0, 0, 0, 1, 1;\n")),
            "model.idf: line 4: Wall:Exterior 'W', Zone Name: no Zone is named 'Z9'");
}

TEST(EnergyPlusErrors, VersionOutOfRange) {
  EXPECT_EQ(error_of("Version, 8.8;\nGlobalGeometryRules, UpperLeftCorner, Counterclockwise, "
                     "World;\n"),
            "model.idf: line 1: Version 8.8: EnergyPlus files of versions 8.9 to 26.2 are read "
            "(EnergyPlus's IDFVersionUpdater brings an older file up to date)");
  EXPECT_EQ(error_of("GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;\n"),
            "model.idf: no Version object: an IDF file's Version says where each object's "
            "fields are");
}

TEST(EnergyPlusErrors, DuplicateSurfaceNames) {
  EXPECT_EQ(error_of(with_head("Shading:Site, Tree, 180, 90, 0, 0, 0, 1, 1;\n"
                               "Shading:Building, TREE, 180, 90, 0, 0, 0, 1, 1;\n")),
            "model.idf: line 5: Shading:Building 'TREE': the surface 'TREE' has the Name of "
            "Shading:Site 'Tree' on line 4; EnergyPlus's surface Names are unique, compared "
            "ignoring case");
}

TEST(EnergyPlusErrors, FileEndingInsideAnObject) {
  EXPECT_EQ(error_of(with_head("Shading:Site, Tree, 180, 90,\n  0, 0, 0, 1, 1\n")),
            "model.idf: line 4: the file ends inside this object: an IDF object ends with ';'");
}

TEST(EnergyPlusErrors, MissingGeometryRules) {
  EXPECT_EQ(error_of("Version, 9.6;\nZone, Z1;\n"),
            "model.idf: no GlobalGeometryRules object: EnergyPlus requires it to say how "
            "vertices are entered");
}

TEST(EnergyPlusErrors, OverhangOnAWallNotAWindow) {
  EXPECT_EQ(error_of(with_head("Wall:Exterior, W, Ext, Z1, , 180, 90, 0, 0, 0, 4, 3;\n"
                               "Shading:Overhang, O, W, 0.1, 90, 0, 0, 1;\n")),
            "model.idf: line 5: Shading:Overhang 'O', Window or Door Name: no window or door "
            "is named 'W'");
}

TEST(EnergyPlusErrors, EpJsonErrorsNameTheirPath) {
  EXPECT_EQ(error_of(R"({"Zone": {"Z1": {"x_origin": "east"}},
  "GlobalGeometryRules": {"G": {"starting_vertex_position": "UpperLeftCorner",
    "vertex_entry_direction": "Counterclockwise", "coordinate_system": "World"}}})",
                     "model.epJSON"),
            "model.epJSON: Zone 'Z1', x_origin: 'east' is not a number");
  EXPECT_EQ(error_of(R"({"Zone": {"Z1": {"x_origin": true}}})", "model.epJSON"),
            "model.epJSON: ['Zone']['Z1'].x_origin: expected a number or a string, found a "
            "boolean");
}

}  // namespace
}  // namespace shadowgen::energyplus::testing
