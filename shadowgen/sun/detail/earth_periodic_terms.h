#pragma once

// The Earth's heliocentric longitude L, latitude B and radius vector R from the periodic
// terms of VSOP87 as NREL's Solar Position Algorithm truncates them (Reda & Andreas,
// NREL/TP-560-34302, 2008, Table A4.2). L and B in radians, R in astronomical units.

namespace shadowgen::sun::detail {

struct HeliocentricPosition {
  double longitude_rad = 0.0;
  double latitude_rad = 0.0;
  double radius_au = 0.0;
};

// `jme`: Julian ephemeris millennia from J2000.0 (TT).
HeliocentricPosition earth_heliocentric(double jme);

}  // namespace shadowgen::sun::detail
