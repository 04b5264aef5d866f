#pragma once

// Where a point of a projected coordinate reference system stands on the Earth, through
// PROJ (https://proj.org), offline: the definitions come from proj-data's proj.db, and no
// transformation grid is needed, since no datum is changed (see below).
//
//   ProjectedSite s = geo::projected_site("EPSG:7415", 155000.0, 463000.0);
//   // s.site.latitude_deg 52.156160556 (52°09'22.178"N), longitude_deg 5.387638889
//   // (5°23'15.500"E), north_axis_deg 0: the origin of the Dutch RD grid
//
// - The CRS is any string PROJ resolves ("EPSG:28992"); a compound CRS (EPSG:7415 =
//   Amersfoort / RD New + NAP height) is taken by its horizontal part. It must be
//   projected, with axes east and north (in either order; the point is given as (easting,
//   northing)), in any linear unit.
// - Latitude and longitude are geodetic, on the CRS's own datum (its base geographic CRS:
//   Amersfoort for RD New, OSGB 1936 for the British National Grid): the inverse
//   projection alone, the same numbers as the CRS's published definition gives. A datum
//   differs from WGS 84 by at most a few hundred metres (Amersfoort: about 100 m), a few
//   thousandths of a degree, which moves the sun by as little (its apparent position
//   changes by 1° for 111 km on the ground).
// - north_axis_deg is the grid convergence at the point: the angle from true north to the
//   grid's +y axis, clockwise seen from above (the scene's `north_axis_deg`,
//   docs/scene-format.md, "Orientation and time"). It is measured, not taken from a
//   formula of one projection: the meridian through the point is projected a short step
//   either side of it (1e-4 degrees of latitude, about 11 m), and the angle is that of the
//   grid's +y from this chord. A central chord's direction is the tangent's to the square
//   of the step (about 1e-12 rad on a grid of the Earth's curvature), and its ends come
//   out of PROJ to about 1e-9 m of its 22 m, so the angle holds to about 1e-8 degrees. East of a
//   transverse Mercator grid's central meridian in the northern hemisphere it is positive: grid
//   north lies east of true north there, by atan(tan(λ − λ0) sin φ) on the sphere (EPSG Guidance
//   Note 7-2).
// - `from` says where this came from: "EPSG:7415 through PROJ at (155000, 463000)".

#include <stdexcept>
#include <string>

#include "shadowgen/model/source_model.h"

namespace shadowgen::geo {

// Why a CRS gives no site: PROJ does not know it, it is not projected (a geographic CRS
// has no grid to place a scene on), its axes are not east and north, or the point lies
// where its projection is not defined. what() is one line: "EPSG:4326 is a geographic CRS,
// not a projected one".
class CrsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ProjectedSite {
  SourceSite site;  // latitude, longitude, north axis and `from`; nothing else
  // Empty, or why the numbers may not be what the file meant: the point lies outside the
  // CRS's area of use ("(0, 0) lies outside the area of use of EPSG:7415, Netherlands -
  // onshore, ... (longitude 3.2 to 7.22, latitude 50.75 to 53.7 degrees)"), as coordinates
  // moved near the origin that kept their CRS would.
  std::string caution;
};

// Throws CrsError.
ProjectedSite projected_site(const std::string& crs, double x, double y);

}  // namespace shadowgen::geo
