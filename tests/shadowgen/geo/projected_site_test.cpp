// Tests of shadowgen/geo/projected_site.h: points of projected CRSs placed on the Earth
// against published coordinates, and the grid convergence against the transverse Mercator
// formula worked by hand.

#include "shadowgen/geo/projected_site.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace shadowgen::geo {
namespace {

double degrees(double d, double m, double s) { return d + m / 60.0 + s / 3600.0; }
double radians(double deg) { return deg * std::numbers::pi / 180.0; }

// On the sphere, the convergence of a transverse Mercator grid at latitude φ, λ − λ0 east of
// its central meridian: γ = atan(tan(λ − λ0) sin φ) (EPSG Guidance Note 7-2, and Snyder,
// "Map Projections: A Working Manual", 1987, eq. 8-15 with k0's scale aside). On the
// ellipsoid the next term adds η² (λ − λ0)³ sin φ cos² φ, η² = e'² cos² φ: for the points
// below at most 4.1e-6 degrees, so the formula must hold to 1e-5 degrees.
double spherical_convergence(double latitude, double delta_longitude) {
  return std::atan(std::tan(radians(delta_longitude)) * std::sin(radians(latitude))) * 180.0 /
         std::numbers::pi;
}

// The published coordinates are given to 0.001 arc second (RD) or 1 cm (the British
// National Grid): 2.8e-7 and 1e-7 degrees.
constexpr double kArcMilliSecond = 1.0 / 3600.0 / 1000.0;

TEST(ProjectedSite, TheAmersfootOriginOfRdNewIsItsPublishedPointWithNoConvergence) {
  // EPSG:28992 Amersfoort / RD New: (155000, 463000) is the projection's origin,
  // 52°09'22.178"N 5°23'15.500"E on the Amersfoort datum, where grid north is true north.
  // EPSG:7415 is RD New with NAP heights: the same grid.
  for (const char* crs : {"EPSG:28992", "EPSG:7415"}) {
    SCOPED_TRACE(crs);
    const ProjectedSite s = projected_site(crs, 155000.0, 463000.0);
    EXPECT_NEAR(*s.site.latitude_deg, degrees(52, 9, 22.178), kArcMilliSecond);
    EXPECT_NEAR(*s.site.longitude_deg, degrees(5, 23, 15.500), kArcMilliSecond);
    EXPECT_NEAR(*s.site.north_axis_deg, 0.0, 1e-8);
    EXPECT_FALSE(s.site.elevation_m);
    EXPECT_FALSE(s.site.utc_offset_h);
    EXPECT_EQ(s.site.from, std::string(crs) + " through PROJ at (155000, 463000)");
    EXPECT_EQ(s.caution, "");
  }
}

TEST(ProjectedSite, TheBritishNationalGridPointOfTheEpsgGuidanceNoteAndItsConvergence) {
  // EPSG Guidance Note 7-2, the transverse Mercator example: OSGB 1936 / British National
  // Grid (EPSG:27700) E 577274.99, N 69740.50 is 50°30'N 0°30'E. The grid's central
  // meridian is 2°W, so the point lies 2.5° east of it: grid north lies east of true north,
  // a positive convergence of atan(tan 2.5° sin 50.5°) = 1.92956°.
  const ProjectedSite s = projected_site("EPSG:27700", 577274.99, 69740.50);
  EXPECT_NEAR(*s.site.latitude_deg, 50.5, 1e-7);
  EXPECT_NEAR(*s.site.longitude_deg, 0.5, 1e-7);
  EXPECT_NEAR(*s.site.north_axis_deg, spherical_convergence(50.5, 2.5), 1e-5);
  EXPECT_GT(*s.site.north_axis_deg, 1.9295);
}

TEST(ProjectedSite, UtmConvergenceFollowsTheFormulaEastAndWestNorthAndSouth) {
  // WGS 84 / UTM zone 31N (central meridian 3°E) and 33S (15°E): at a point east of the
  // central meridian grid north lies east of true north in the north (γ > 0), west of it
  // in the south (γ < 0); west of the meridian the other way round.
  struct Case {
    const char* crs;
    double x, y, central_meridian;
  };
  for (const Case c :
       {Case{"EPSG:32631", 640000.0, 5760000.0, 3.0}, Case{"EPSG:32631", 360000.0, 5760000.0, 3.0},
        Case{"EPSG:32733", 640000.0, 6200000.0, 15.0},
        Case{"EPSG:32733", 360000.0, 6200000.0, 15.0}}) {
    SCOPED_TRACE(std::string(c.crs) + " x " + std::to_string(c.x));
    const ProjectedSite s = projected_site(c.crs, c.x, c.y);
    const double latitude = *s.site.latitude_deg;
    const double delta = *s.site.longitude_deg - c.central_meridian;
    EXPECT_GT(std::abs(delta), 1.5);  // 140 km from the meridian
    EXPECT_NEAR(*s.site.north_axis_deg, spherical_convergence(latitude, delta), 1e-5);
    EXPECT_EQ(*s.site.north_axis_deg > 0.0, (delta > 0.0) == (latitude > 0.0));
  }
}

// What projected_site throws for `crs`.
std::string crs_error(const char* crs) {
  try {
    projected_site(crs, 0.0, 0.0);
  } catch (const CrsError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ProjectedSite, AGeographicOrUnknownCrsGivesNoSite) {
  EXPECT_EQ(crs_error("EPSG:4326"), "EPSG:4326 is a geographic CRS, not a projected one");
  EXPECT_EQ(crs_error("EPSG:999999"), "PROJ does not know the CRS EPSG:999999");
  // NAP height alone.
  EXPECT_EQ(crs_error("EPSG:5709"), "EPSG:5709 is a vertical CRS, not a projected one");
  // A grid whose axes point west and south (South African Lo29: westing, southing).
  EXPECT_EQ(crs_error("EPSG:22279"),
            "EPSG:22279's axes point west and south, not east and north as a scene's x and y do");
}

TEST(ProjectedSite, APointOutsideTheAreaOfUseIsPlacedWithACaution) {
  // Coordinates moved near the origin but still labelled RD New: the grid's (0, 0) lies
  // in France, outside the Netherlands the CRS is for.
  const ProjectedSite s = projected_site("EPSG:7415", 0.0, 0.0);
  EXPECT_NEAR(*s.site.latitude_deg, 47.97, 0.01);
  EXPECT_NEAR(*s.site.longitude_deg, 3.31, 0.01);
  EXPECT_EQ(s.caution,
            "(0, 0) lies outside the area of use of EPSG:7415, Netherlands - onshore, including "
            "Waddenzee, Dutch Wadden Islands and 12-mile offshore coastal zone (longitude 3.2 to "
            "7.22, latitude 50.75 to 53.7 degrees)");
}

}  // namespace
}  // namespace shadowgen::geo
