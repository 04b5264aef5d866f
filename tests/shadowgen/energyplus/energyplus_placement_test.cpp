// Surfaces placed as EnergyPlus places them (SurfaceGeometry.cc), against vertices computed
// by hand from the Input Output Reference's conventions: rotations clockwise seen from
// above, a zone's relative north about its origin, then the building's north axis about
// the world origin.

#include <gtest/gtest.h>

#include <cmath>

#include "energyplus_models.h"

namespace shadowgen::energyplus::testing {
namespace {

const double kRoot3 = std::sqrt(3.0);

// A zone turned 60 degrees from the building's north and set at (10, 5, 3), in a building
// turned 30 degrees from true north: 90 degrees in all, so the zone's +x runs to true south
// (-y). Its west wall is entered by its vertices and again as a Wall:Exterior.
constexpr std::string_view kRelativeZone = R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, Relative, Relative, Relative;
Building, Office, 30;  ! North Axis
Zone, Z1, 60, 10, 5, 3;
BuildingSurface:Detailed, West Detailed, Wall, Ext, Z1, , Outdoors, , SunExposed, WindExposed,
  autocalculate, 4,
  0, 0, 3,   ! upper left
  0, 0, 0,
  4, 0, 0,
  4, 0, 3;
Wall:Exterior, West Simple, Ext, Z1, , 180, 90, 0, 0, 0, 4, 3;
)";

TEST(EnergyPlusPlacement, RelativeZoneTurnsByItsNorthAboutItsOriginThenByTheBuildingsAxis) {
  const SourceModel model = read_idf(kRelativeZone);
  ASSERT_EQ(model.faces.size(), 2u);
  // (0, 0) is the zone origin (10, 5); turned 30 degrees clockwise: (5√3 + 2.5, 2.5√3 − 5).
  // (4, 0) turned 60 degrees is (2, −2√3), at (12, 5 − 2√3); turned 30 more:
  // (5√3 + 2.5, 2.5√3 − 9). z rises by the origin's 3.
  const std::vector<glm::dvec3> expected = {{5 * kRoot3 + 2.5, 2.5 * kRoot3 - 5, 6},
                                            {5 * kRoot3 + 2.5, 2.5 * kRoot3 - 5, 3},
                                            {5 * kRoot3 + 2.5, 2.5 * kRoot3 - 9, 3},
                                            {5 * kRoot3 + 2.5, 2.5 * kRoot3 - 9, 6}};
  expect_loop(face_named(model, "West Detailed").polygon.outer, expected);
  // The rectangle's azimuth 180 turns by both axes to 270 (west), its corner as above.
  expect_loop(face_named(model, "West Simple").polygon.outer, expected);
  // The front side is the outside: the outward normal points west.
  const glm::dvec3 normal = hsr::plane_of(face_named(model, "West Detailed").polygon).normal;
  EXPECT_NEAR(normal.x, -1.0, 1e-12);
}

// Entered clockwise from the upper right corner, in World coordinates: the same south wall
// as (0,0,3), (0,0,0), (4,0,0), (4,0,3) counter-clockwise from the upper left. The
// building's and the zone's north axes and the zone's origin are ignored in World
// coordinates, rectangles' starting corners too.
constexpr std::string_view kClockwiseWorld = R"(
Version, 24.1;
GlobalGeometryRules, UpperRightCorner, Clockwise, World, World, World;
Building, Office, 45;
Zone, Z1, 30, 100, 100, 100;
BuildingSurface:Detailed, South, Wall, Ext, Z1, , Outdoors, , SunExposed, WindExposed, , 4,
  4, 0, 3,  4, 0, 0,  0, 0, 0,  0, 0, 3;   ! clockwise seen from the south
Window, South Window, Glass, South, , 1, 1, 0.5, 2, 1.5;
Wall:Exterior, East, Ext, Z1, , 90, 90, 2, 3, 0, 5, 3;
)";

TEST(EnergyPlusPlacement, ClockwiseInputFromTheUpperRightCornerIsTurnedToStartUpperLeft) {
  const SourceModel model = read_idf(kClockwiseWorld);
  const SourceFace& wall = face_named(model, "South");
  expect_loop(wall.polygon.outer, {{0, 0, 3}, {0, 0, 0}, {4, 0, 0}, {4, 0, 3}});
  // The window is placed from the wall's vertex 2, its lower left corner seen from outside.
  expect_loop(face_named(model, "South Window").polygon.outer,
              {{1, 0, 2}, {1, 0, 0.5}, {3, 0, 0.5}, {3, 0, 2}});
  ASSERT_EQ(wall.polygon.holes.size(), 1u);
  expect_loop(wall.polygon.holes[0], {{1, 0, 2}, {1, 0, 0.5}, {3, 0, 0.5}, {3, 0, 2}});
}

// Entered from the lower left corner, counter-clockwise: GetVertices brings the upper left
// corner first, so that vertex 2, from which windows are placed, is the lower left one.
TEST(EnergyPlusPlacement, LowerLeftCornerInputPlacesWindowsFromTheLowerLeftCorner) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, LowerLeftCorner, Counterclockwise, World;
Zone, Z1;
BuildingSurface:Detailed, South, Wall, Ext, Z1, , Outdoors, , SunExposed, WindExposed, , 4,
  0, 0, 0,  4, 0, 0,  4, 0, 3,  0, 0, 3;
Window, South Window, Glass, South, , 1, 1, 0.5, 2, 1.5;
Shading:Zone:Detailed, Fin, South, , 3,  4, 0, 0,  4, -1, 0,  4, -1, 3;
)");
  expect_loop(face_named(model, "South").polygon.outer,
              {{0, 0, 3}, {0, 0, 0}, {4, 0, 0}, {4, 0, 3}});
  expect_loop(face_named(model, "South Window").polygon.outer,
              {{1, 0, 2}, {1, 0, 0.5}, {3, 0, 0.5}, {3, 0, 2}});
  // A triangle from its lower left corner turns as a rectangle does: its last vertex first.
  expect_loop(face_named(model, "Fin").polygon.outer, {{4, -1, 3}, {4, 0, 0}, {4, -1, 0}});
  EXPECT_EQ(face_named(model, "Fin").origin,
            (FaceOrigin{"energyplus", "Fin", "Z1", "Shading:Zone"}));
}

TEST(EnergyPlusPlacement, WorldCoordinatesIgnoreNorthAxesAndZoneOrigins) {
  const SourceModel model = read_idf(kClockwiseWorld);
  // Azimuth 90 (east) as entered, from (2, 3, 0) as entered.
  expect_loop(face_named(model, "East").polygon.outer,
              {{2, 3, 3}, {2, 3, 0}, {2, 8, 0}, {2, 8, 3}});
  EXPECT_NEAR(hsr::plane_of(face_named(model, "East").polygon).normal.x, 1.0, 1e-12);
}

// Each simplified object in a zone at the origin of an unturned building: a south wall
// with a window, a door at floor level, an overhang and fins on the window, a roof and a
// floor.
constexpr std::string_view kSimplified = R"(
Version, 23.2;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, Relative;
Zone, Z1;
Wall:Exterior, South, Ext, Z1, , 180, 90, 0, 0, 0, 10, 3;
Window, South Window, Glass, South, , 1, 2, 1, 3, 1.5;
Door, South Door, Door, South, 1, 7, 0, 1, 2.1;
Roof, Roof, Roof, Z1, , 180, 0, 0, 0, 3, 10, 6;
Floor:GroundContact, Floor, Slab, Z1, , 180, 180, 0, 6, 0, 10, 6;
Shading:Overhang, Window Overhang, South Window, 0.2, 90, 0.5, 0.5, 1;
Shading:Fin, Window Fin, South Window, 0.1, 0.2, 0.3, 90, 0.5, 0.1, 0.2, 0.3, 90, 0.5;
)";

TEST(EnergyPlusPlacement, RectangularWallWindowAndDoorAtFloorLevel) {
  const SourceModel model = read_idf(kSimplified);
  const SourceFace& wall = face_named(model, "South");
  expect_loop(wall.polygon.outer, {{0, 0, 3}, {0, 0, 0}, {10, 0, 0}, {10, 0, 3}});
  expect_loop(face_named(model, "South Window").polygon.outer,
              {{2, 0, 2.5}, {2, 0, 1}, {5, 0, 1}, {5, 0, 2.5}});
  expect_loop(face_named(model, "South Door").polygon.outer,
              {{7, 0, 2.1}, {7, 0, 0}, {8, 0, 0}, {8, 0, 2.1}});
  // Both openings are holes: the wall's area is its net area, 30 − 4.5 − 2.1.
  ASSERT_EQ(wall.polygon.holes.size(), 2u);
  EXPECT_NEAR(net_area(wall), 23.4, 1e-12);
}

TEST(EnergyPlusPlacement, RoofFacesUpAndFloorDown) {
  const SourceModel model = read_idf(kSimplified);
  expect_loop(face_named(model, "Roof").polygon.outer,
              {{0, 6, 3}, {0, 0, 3}, {10, 0, 3}, {10, 6, 3}});
  expect_loop(face_named(model, "Floor").polygon.outer,
              {{0, 0, 0}, {0, 6, 0}, {10, 6, 0}, {10, 0, 0}});
  EXPECT_NEAR(hsr::plane_of(face_named(model, "Roof").polygon).normal.z, 1.0, 1e-12);
  EXPECT_NEAR(hsr::plane_of(face_named(model, "Floor").polygon).normal.z, -1.0, 1e-12);
}

TEST(EnergyPlusPlacement, OverhangAboveItsWindowFacingDown) {
  const SourceModel model = read_idf(kSimplified);
  // 0.5 beyond each side of the 3 m window (4 m long), 0.2 above its top (2.5), 1 deep,
  // tilted 90 degrees from the window: horizontal, its outside down.
  expect_loop(face_named(model, "Window Overhang").polygon.outer,
              {{1.5, -1, 2.7}, {1.5, 0, 2.7}, {5.5, 0, 2.7}, {5.5, -1, 2.7}});
}

TEST(EnergyPlusPlacement, FinIsTwoSurfacesLeftAndRight) {
  const SourceModel model = read_idf(kSimplified);
  // 0.1 beside the window's sides (x 2 and 5), from 0.3 below its bottom (1) to 0.2 above
  // its top (2.5), 0.5 deep out of the wall.
  expect_loop(face_named(model, "Window Fin Left").polygon.outer,
              {{1.9, 0, 2.7}, {1.9, 0, 0.7}, {1.9, -0.5, 0.7}, {1.9, -0.5, 2.7}});
  expect_loop(face_named(model, "Window Fin Right").polygon.outer,
              {{5.1, 0, 2.7}, {5.1, 0, 0.7}, {5.1, -0.5, 0.7}, {5.1, -0.5, 2.7}});
}

TEST(EnergyPlusPlacement, FacesComeInTheFilesOrderWithTheirOrigins) {
  const SourceModel model = read_idf(kSimplified);
  std::vector<std::string> ids;
  for (const SourceFace& face : model.faces) ids.push_back(face.id);
  EXPECT_EQ(ids,
            (std::vector<std::string>{"South", "South Window", "South Door", "Roof", "Floor",
                                      "Window Overhang", "Window Fin Left", "Window Fin Right"}));
  EXPECT_EQ(face_named(model, "South").origin, (FaceOrigin{"energyplus", "South", "Z1", "Wall"}));
  EXPECT_EQ(face_named(model, "South Window").origin,
            (FaceOrigin{"energyplus", "South Window", "Z1", "Window"}));
  EXPECT_EQ(face_named(model, "South Door").origin,
            (FaceOrigin{"energyplus", "South Door", "Z1", "Door"}));
  EXPECT_EQ(face_named(model, "Window Fin Right").origin,
            (FaceOrigin{"energyplus", "Window Fin Right", "Z1", "Shading:Zone"}));
  EXPECT_EQ(face_named(model, "South").described, "Wall:Exterior 'South'");
  EXPECT_EQ(face_named(model, "South").line, 5u);
  EXPECT_TRUE(model.warnings.empty());
}

// Site shading never turns; building shading turns with the building's north axis only
// (here 90 degrees: (x, y) goes to (y, −x)); the zone's north axis turns neither.
constexpr std::string_view kDetachedShading = R"(
Version, 22.2;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, Relative, Relative, Relative;
Building, B, 90;
Zone, Z1, 45, 1, 2, 3;
Shading:Site, Site Wall, 180, 90, 20, 30, 0, 5, 4;
Shading:Building, Building Wall, 180, 90, 20, 30, 0, 5, 4;
Shading:Site:Detailed, Site Triangle, , 3, 10, 0, 0, 10, 0, 5, 10, 5, 0;
Shading:Building:Detailed, Building Triangle, , autocalculate, 10, 0, 0, 10, 0, 5, 10, 5, 0;
)";

TEST(EnergyPlusPlacement, SiteShadingNeverTurnsBuildingShadingTurnsWithTheBuildingOnly) {
  const SourceModel model = read_idf(kDetachedShading);
  expect_loop(face_named(model, "Site Wall").polygon.outer,
              {{20, 30, 4}, {20, 30, 0}, {25, 30, 0}, {25, 30, 4}});
  expect_loop(face_named(model, "Building Wall").polygon.outer,
              {{30, -20, 4}, {30, -20, 0}, {30, -25, 0}, {30, -25, 4}});
  expect_loop(face_named(model, "Site Triangle").polygon.outer,
              {{10, 0, 0}, {10, 0, 5}, {10, 5, 0}});
  expect_loop(face_named(model, "Building Triangle").polygon.outer,
              {{0, -10, 0}, {0, -10, 5}, {5, -10, 0}});
  EXPECT_EQ(face_named(model, "Site Wall").origin,
            (FaceOrigin{"energyplus", "Site Wall", "", "Shading:Site"}));
  EXPECT_EQ(face_named(model, "Building Triangle").origin,
            (FaceOrigin{"energyplus", "Building Triangle", "", "Shading:Building"}));
}

// A window set back 0.2 m behind its wall's plane (a reveal) cuts the hole its projection
// onto the wall makes.
TEST(EnergyPlusPlacement, WindowInARevealCutsItsProjection) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Zone, Z1;
BuildingSurface:Detailed, South, Wall, Ext, Z1, , Outdoors, , SunExposed, WindExposed, , 4,
  0, 0, 3,  0, 0, 0,  4, 0, 0,  4, 0, 3;
FenestrationSurface:Detailed, Deep Window, Window, Glass, South, , , , 1, 4,
  1, 0.2, 2,  1, 0.2, 1,  3, 0.2, 1,  3, 0.2, 2;
)");
  const SourceFace& wall = face_named(model, "South");
  ASSERT_EQ(wall.polygon.holes.size(), 1u);
  expect_loop(wall.polygon.holes[0], {{1, 0, 2}, {1, 0, 1}, {3, 0, 1}, {3, 0, 2}});
  expect_loop(face_named(model, "Deep Window").polygon.outer,
              {{1, 0.2, 2}, {1, 0.2, 1}, {3, 0.2, 1}, {3, 0.2, 2}});
  EXPECT_NEAR(net_area(wall), 10.0, 1e-12);
}

// A roof entered facing down is turned over, as EnergyPlus turns it (GetVertices).
TEST(EnergyPlusPlacement, UpsideDownRoofIsTurnedOver) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Zone, Z1;
RoofCeiling:Detailed, Roof, Roof, Z1, , Outdoors, , SunExposed, WindExposed, , 4,
  0, 0, 3,  0, 6, 3,  10, 6, 3,  10, 0, 3;
)");
  expect_loop(face_named(model, "Roof").polygon.outer,
              {{10, 0, 3}, {10, 6, 3}, {0, 6, 3}, {0, 0, 3}});
}

TEST(EnergyPlusPlacement, VertexRoundingFollowsTheDecimalsWritten) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Zone, Z1;
BuildingSurface:Detailed, Wall, Wall, Ext, Z1, , Outdoors, , SunExposed, WindExposed, , 4,
  0, 0, 3.125,  0, 0, 0,  4.5, 0, 0,  4.5, 0, 3.125;
)");
  // Three decimals at most (3.125): each coordinate within 0.0005, a vertex within √3/2·1e-3.
  EXPECT_DOUBLE_EQ(face_named(model, "Wall").vertex_rounding, kRoot3 / 2 * 1e-3);
}

// A Relative coordinate system with World rectangles: the rectangle's azimuth still turns
// with the building's north axis (GetRectSurfaces), its starting corner is taken as it is
// (MakeRectangularVertices), as EnergyPlus does (and warns of).
TEST(EnergyPlusPlacement, WorldRectanglesInARelativeFileTurnTheirAzimuthOnly) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, Relative, Relative, World;
Building, B, 90;
Zone, Z1, 0, 5, 0, 0;
Wall:Exterior, W, Ext, Z1, , 180, 90, 0, 0, 0, 4, 3;
)");
  expect_loop(face_named(model, "W").polygon.outer, {{0, 0, 3}, {0, 0, 0}, {0, -4, 0}, {0, -4, 3}});
}

// Depths as fractions of the window: an overhang's of its height, a fin's of its width.
TEST(EnergyPlusPlacement, ProjectionShadingTakesItsDepthFromTheWindow) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Zone, Z1;
Wall:Exterior, South, Ext, Z1, , 180, 90, 0, 0, 0, 10, 3;
Window, Win, Glass, South, , 1, 2, 1, 4, 1.5;
Shading:Overhang:Projection, Brow, Win, 0, 90, 0, 0, 0.4;
Shading:Fin:Projection, Side, Win, 0, 0, 0, 90, 0.25, 0, 0, 0, 90, 0.5;
)");
  // 0.4 × 1.5 = 0.6 deep, right over the window's top (2.5).
  expect_loop(face_named(model, "Brow").polygon.outer,
              {{2, -0.6, 2.5}, {2, 0, 2.5}, {6, 0, 2.5}, {6, -0.6, 2.5}});
  // 0.25 × 4 = 1 and 0.5 × 4 = 2 deep, along the window's sides.
  expect_loop(face_named(model, "Side Left").polygon.outer,
              {{2, 0, 2.5}, {2, 0, 1}, {2, -1, 1}, {2, -1, 2.5}});
  expect_loop(face_named(model, "Side Right").polygon.outer,
              {{6, 0, 2.5}, {6, 0, 1}, {6, -2, 1}, {6, -2, 2.5}});
}

// What EnergyPlus drops, with a word: a vertex within 0.01 m of the one before it, and an
// overhang without area.
TEST(EnergyPlusPlacement, DroppedVerticesAndSurfacesAreSaid) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Zone, Z1;
Shading:Site:Detailed, S, , 5,  0, 0, 0,  4, 0, 0,  4.005, 0, 0,  4, 0, 3,  0, 0, 3;
Wall:Exterior, South, Ext, Z1, , 180, 90, 0, 0, 0, 10, 3;
Window, Win, Glass, South, , 1, 2, 1, 4, 1.5;
Shading:Overhang, Flat, Win, 0.1, 90, 0, 0, 0;
)");
  expect_loop(face_named(model, "S").polygon.outer, {{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}});
  EXPECT_EQ(model.faces.size(), 3u);  // no overhang
  EXPECT_EQ(model.warnings,
            (std::vector<std::string>{
                "model.idf: line 8: Shading:Overhang 'Flat': its length times its depth is not "
                "positive; EnergyPlus enters no surface for it, and neither does this reader",
                "model.idf: 1 surface has a vertex within 0.01 m of the one before it, dropped "
                "as EnergyPlus drops it: 'S'"}));
}

TEST(EnergyPlusPlacement, SiteLocationGivesTheSite) {
  const SourceModel model = read_idf(R"(
Version, 9.6;
GlobalGeometryRules, UpperLeftCorner, Counterclockwise, World;
Site:Location, Denver Centennial, 39.74, -105.18, -7, 1829;
)");
  EXPECT_TRUE(model.faces.empty());
  EXPECT_EQ(model.site.latitude_deg, 39.74);
  EXPECT_EQ(model.site.longitude_deg, -105.18);
  EXPECT_EQ(model.site.utc_offset_h, -7.0);
  EXPECT_EQ(model.site.elevation_m, 1829.0);
  EXPECT_EQ(model.site.north_axis_deg, 0.0);
  EXPECT_EQ(model.site.from, "Site:Location 'Denver Centennial'");
}

}  // namespace
}  // namespace shadowgen::energyplus::testing
